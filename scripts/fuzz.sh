#!/usr/bin/env bash
# Fuzzes the input readers with libFuzzer (clang), in the ASan + UBSan build that
# scripts/check-sanitizers.sh also uses (build-asan/; only the harnesses and the core are built
# here). Each harness starts from its seed corpus in tests/fuzz/corpus/<reader>/ and runs RUNS
# executions (default 1e6); a crash, a sanitizer report or an exception other than InputError
# stops it with the input that caused it (crash-*, in build-asan/).
# Usage: scripts/fuzz.sh [RUNS]   (docs/reliability.md)
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/lib/clang-sanitizers.sh"
runs="${1:-1000000}"
filmdyn_install_clang
filmdyn_configure_asan
cmake --build "$(filmdyn_asan_build_dir)" -j "${FILMDYN_BUILD_JOBS:-$(nproc)}" \
  --target fuzz_case_reader fuzz_pressure_csv
filmdyn_fuzz_readers "$runs"
