#!/usr/bin/env bash
# Fuzzes the input readers with libFuzzer (clang), the core built with AddressSanitizer and
# UndefinedBehaviorSanitizer, in its own build folder (build-fuzz/). Each harness starts from its
# seed corpus in tests/fuzz/corpus/<reader>/ and runs RUNS executions (default 1e6); a crash, a
# sanitizer report or an exception other than InputError stops it with the input that caused it
# (crash-*, in build-fuzz/). Usage: scripts/fuzz.sh [RUNS]   (docs/reliability.md)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
runs="${1:-1000000}"
build="${FILMDYN_FUZZ_BUILD_DIR:-$root/build-fuzz}"
# clang, its libFuzzer/sanitizer runtimes and its OpenMP (SUNDIALS' CMake package asks for
# OpenMP; Debian 12: clang 14); the rest comes from install-deps.sh.
"$root/scripts/install-deps.sh"
missing=()
for p in clang libclang-rt-dev libomp-dev; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  sudo=()
  [ "$(id -u)" -eq 0 ] || sudo=(sudo)
  echo "fuzz: installing ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  "${sudo[@]}" apt-get update -qq
  "${sudo[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi
flags="-fsanitize=address,undefined,fuzzer-no-link -fno-sanitize-recover=undefined -fno-omit-frame-pointer -g -O1"
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
  -DCMAKE_C_FLAGS="$flags" -DCMAKE_CXX_FLAGS="$flags" \
  -DFILMDYN_BUILD_UI=OFF -DFILMDYN_BUILD_TESTS=OFF -DFILMDYN_BUILD_BENCH=OFF \
  -DFILMDYN_BUILD_FUZZ=ON >/dev/null
cmake --build "$build" -j "${FILMDYN_BUILD_JOBS:-$(nproc)}" --target fuzz_case_reader fuzz_pressure_csv
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
export ASAN_OPTIONS=detect_leaks=1
for reader in case_reader pressure_csv; do
  work="$build/corpus-$reader"
  mkdir -p "$work"
  echo "fuzz: $reader, $runs executions"
  status=0
  (cd "$build" && "./tests/fuzz/fuzz_$reader" -runs="$runs" -max_len=65536 -timeout=10 \
     -rss_limit_mb=2048 -print_final_stats=1 "$work" "$root/tests/fuzz/corpus/$reader") \
     >"$build/fuzz-$reader.log" 2>&1 || status=$?
  grep -E "DONE|stat::number_of_executed_units|stat::peak_rss_mb|ERROR|SUMMARY|not an InputError" \
    "$build/fuzz-$reader.log" || true
  if [ "$status" -ne 0 ]; then
    echo "fuzz: $reader FAILED (exit $status; log $build/fuzz-$reader.log, input $build/crash-*)"
    exit 1
  fi
done
echo "fuzz: no finding"
