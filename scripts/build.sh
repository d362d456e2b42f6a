#!/usr/bin/env bash
# Configures and builds FilmDyn (Release) in build/ (or $FILMDYN_BUILD_DIR). Used by both set-up
# commands; incremental when the build directory exists. Arguments name the targets to build
# (e.g. `scripts/build.sh filmdyn`: the application alone, without the test suites and benches);
# none builds everything.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${FILMDYN_BUILD_DIR:-$root/build}"
jobs="${FILMDYN_JOBS:-$(nproc)}"
generator=()
command -v ninja >/dev/null 2>&1 && generator=(-G Ninja)
if [ ! -f "$build/CMakeCache.txt" ]; then
  cmake -S "$root" -B "$build" "${generator[@]}" -DCMAKE_BUILD_TYPE=Release
fi
targets=()
for target in "$@"; do targets+=(--target "$target"); done
cmake --build "$build" -j "$jobs" "${targets[@]}"
