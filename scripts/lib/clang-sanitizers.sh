# Shared by scripts/check-sanitizers.sh and scripts/fuzz.sh (sourced, not run): clang and its
# sanitizer runtimes, the instrumented build folders, and the fuzz run of the input readers.
# Debian 12 ships clang 14; SUNDIALS' CMake package asks for OpenMP, hence libomp-dev.

filmdyn_root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"

# ASan + UBSan in one build: the tests, the app and the fuzz harnesses all come from it (with
# FILMDYN_BUILD_FUZZ the readers' packages also get libFuzzer's coverage hooks: core/CMakeLists.txt).
# Line tables only (enough for the reports' stack traces) keeps the build short.
filmdyn_asan_flags="-fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer -gline-tables-only -O1"
# ThreadSanitizer: the worker pool on plain threads (core/base/worker_pool.cpp says why).
filmdyn_tsan_flags="-fsanitize=thread -DFILMDYN_PLAIN_THREADS -fno-omit-frame-pointer -gline-tables-only -O1"

filmdyn_install_clang() {
  "$filmdyn_root/scripts/install-deps.sh"
  local missing=() p
  for p in clang libclang-rt-dev libomp-dev; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  [ ${#missing[@]} -eq 0 ] && return 0
  local sudo=()
  [ "$(id -u)" -eq 0 ] || sudo=(sudo)
  echo "sanitizers: installing ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  "${sudo[@]}" apt-get update -qq
  "${sudo[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
}

# filmdyn_configure_clang BUILD_DIR FLAGS [CMAKE_ARGS...]
filmdyn_configure_clang() {
  local build="$1" flags="$2"
  shift 2
  cmake -S "$filmdyn_root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
    -DCMAKE_C_FLAGS="$flags" -DCMAKE_CXX_FLAGS="$flags" \
    -DCMAKE_C_FLAGS_RELWITHDEBINFO="" -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="" \
    -DFILMDYN_BUILD_BENCH=OFF "$@" >/dev/null
}

filmdyn_asan_build_dir() { echo "${FILMDYN_ASAN_BUILD_DIR:-$filmdyn_root/build-asan}"; }
# filmdyn_configure_asan [CMAKE_ARGS...]: later arguments override the defaults
# (-DFILMDYN_BUILD_UI=OFF).
filmdyn_configure_asan() {
  filmdyn_configure_clang "$(filmdyn_asan_build_dir)" "$filmdyn_asan_flags" \
    -DFILMDYN_BUILD_UI=ON -DFILMDYN_BUILD_TESTS=ON -DFILMDYN_BUILD_FUZZ=ON "$@"
}

filmdyn_sanitizer_env() {
  local supp="$filmdyn_root/tests/sanitizers"
  export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
  export ASAN_OPTIONS="detect_leaks=1:abort_on_error=0:detect_stack_use_after_return=0"
  export LSAN_OPTIONS="suppressions=$supp/lsan.supp:print_suppressions=0"
  export TSAN_OPTIONS="halt_on_error=1:second_deadlock_stack=1:suppressions=$supp/tsan.supp"
}

# filmdyn_fuzz_readers RUNS: each harness RUNS executions from its seed corpus; a crash, a
# sanitizer report or an exception other than InputError fails with the input that caused it.
filmdyn_fuzz_readers() {
  local runs="$1" build reader work status
  build="$(filmdyn_asan_build_dir)"
  filmdyn_sanitizer_env
  for reader in case_reader pressure_csv; do
    work="$build/corpus-$reader"
    mkdir -p "$work"
    echo "fuzz: $reader, $runs executions"
    status=0
    (cd "$build" && "./tests/fuzz/fuzz_$reader" -runs="$runs" -max_len=65536 -timeout=10 \
       -rss_limit_mb=2048 -print_final_stats=1 "$work" "$filmdyn_root/tests/fuzz/corpus/$reader") \
       >"$build/fuzz-$reader.log" 2>&1 || status=$?
    grep -E "DONE|stat::number_of_executed_units|stat::peak_rss_mb|ERROR|SUMMARY|not an InputError" \
      "$build/fuzz-$reader.log" || true
    if [ "$status" -ne 0 ]; then
      echo "fuzz: $reader FAILED (exit $status; log $build/fuzz-$reader.log, input $build/crash-*)"
      return 1
    fi
  done
  echo "fuzz: no finding"
}
