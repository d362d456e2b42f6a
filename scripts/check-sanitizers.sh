#!/usr/bin/env bash
# Builds FilmDyn with clang's sanitizers and runs the test suites under them. Two scopes:
#  full (default):
#  1. AddressSanitizer + UndefinedBehaviorSanitizer (+ LeakSanitizer) on the core, app and ui
#     tests (build-asan/; GL tests under xvfb-run as usual). The build also holds the libFuzzer
#     harnesses: --fuzz-runs N (default 0) fuzzes each input reader N times afterwards.
#  2. ThreadSanitizer on the core suites that run FilmDyn's own threads: the worker pool (film
#     joints and skirt panels side by side) and the run job with its error-estimate companion
#     thread (build-tsan/, core only). Debian's oneTBB is not instrumented, so TSan would report
#     every task TBB hands between its threads; this build runs the worker pool's tasks on plain
#     std::threads instead (FILMDYN_PLAIN_THREADS), and the sweep (a TBB task group) is not in it.
#  ci: what CI runs after the tests, bounded in time: the ASan + UBSan build of the core alone
#     (no GUI, no app) and its suites except those labelled `long` or `heavy` (whole coupled runs
#     that take minutes under ASan; lighter suites drive the same model), then the fuzz smoke.
#     No TSan stage. Run the full scope before a release and after changing threads or the GUI.
# Any sanitizer report fails the test it occurs in. Suppressions (third-party libraries only)
# live in tests/sanitizers/. Usage: scripts/check-sanitizers.sh [--scope full|ci] [--fuzz-runs N]
# (docs/reliability.md)
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/lib/clang-sanitizers.sh"
fuzz_runs=0
scope=full
while [ $# -gt 0 ]; do
  case "$1" in
    --fuzz-runs) fuzz_runs="$2"; shift 2 ;;
    --scope)
      scope="${2:-}"
      case "$scope" in
        full|ci) ;;
        *) echo "check-sanitizers: --scope '$scope' (allowed: full, ci)" >&2; exit 2 ;;
      esac
      shift 2 ;;
    *) echo "check-sanitizers: unknown option '$1' (allowed: --scope full|ci, --fuzz-runs N)" >&2
       exit 2 ;;
  esac
done
start=$(date +%s)
jobs="${FILMDYN_BUILD_JOBS:-$(nproc)}"
filmdyn_install_clang

asan="$(filmdyn_asan_build_dir)"
# The ci scope's suites: all but these labels (see the header and below).
ci_excluded_labels='long|heavy|gl'
if [ "$scope" = ci ]; then
  filmdyn_configure_asan -DFILMDYN_BUILD_UI=OFF
else
  filmdyn_configure_asan
fi
if [ "$scope" = ci ]; then
  # Only what this scope runs: the suites it selects below (a suite is built by the target of its
  # name; the layer check is a script) and the fuzz harnesses. The left-out suites were 12 of the
  # build's 159 objects, about 16 % of its compile time.
  mapfile -t suites < <(cd "$asan" && ctest -N -LE "$ci_excluded_labels" | awk '/Test +#/{print $3}')
  declare -A is_target=()
  while read -r target; do is_target[$target]=1; done \
    < <(cd "$asan" && ninja -t targets all | sed -n 's/: phony$//p')
  wanted=(fuzz_case_reader fuzz_pressure_csv)
  for suite in "${suites[@]}"; do
    [ -n "${is_target[$suite]:-}" ] && wanted+=("$suite")
  done
  [ ${#wanted[@]} -gt 2 ] || { echo "check-sanitizers: no suite to build in $asan" >&2; exit 1; }
  cmake --build "$asan" -j "$jobs" --target "${wanted[@]}"
else
  cmake --build "$asan" -j "$jobs"
fi
echo "sanitizers: ASan + UBSan build ($scope scope) done at $(( $(date +%s) - start )) s"
filmdyn_sanitizer_env
# The tests labelled 'long' are left out in both scopes: the estimate's own test (two full
# coupled runs at several speeds, ~160 s in Release), `filmdyn reproduce` (six runs of the paper's
# study, ~110 s under ASan) and the engine runs with elastic joints (~120 s under ASan); their
# code paths are those of the run-job, coupled-run, CLI and elastic-film tests.
# The GL tests (label 'gl') run without leak detection: Mesa's driver is unloaded at exit and
# leaves allocations no stack can be attributed to; ASan and UBSan still check them.
# The ci scope also leaves out the tests labelled 'heavy' (see the header).
if [ "$scope" = ci ]; then
  (cd "$asan" && ctest --output-on-failure -j "${FILMDYN_TEST_JOBS:-2}" -LE "$ci_excluded_labels")
else
  (cd "$asan" && ctest --output-on-failure -j "${FILMDYN_TEST_JOBS:-2}" -LE 'long|gl')
  (cd "$asan" && ASAN_OPTIONS="$ASAN_OPTIONS:detect_leaks=0" \
     ctest --output-on-failure -j "${FILMDYN_TEST_JOBS:-2}" -L gl -LE long)
fi
echo "sanitizers: ASan + UBSan tests passed at $(( $(date +%s) - start )) s"

if [ "$fuzz_runs" -gt 0 ]; then
  filmdyn_fuzz_readers "$fuzz_runs"
fi

if [ "$scope" = ci ]; then
  echo "check-sanitizers (ci scope): no finding in $(( $(date +%s) - start )) s"
  exit 0
fi

tsan_build="${FILMDYN_TSAN_BUILD_DIR:-$filmdyn_root/build-tsan}"
threaded=(test_core_worker_pool test_engine_run_job)
filmdyn_configure_clang "$tsan_build" "$filmdyn_tsan_flags" \
  -DFILMDYN_BUILD_UI=OFF -DFILMDYN_BUILD_TESTS=ON -DFILMDYN_BUILD_FUZZ=OFF
cmake --build "$tsan_build" -j "$jobs" --target "${threaded[@]}"
echo "sanitizers: TSan build done at $(( $(date +%s) - start )) s"
(cd "$tsan_build" && ctest --output-on-failure -j 1 -R "^($(IFS='|'; echo "${threaded[*]}"))\$")
echo "sanitizers: TSan tests passed at $(( $(date +%s) - start )) s"

echo "check-sanitizers: no finding in $(( $(date +%s) - start )) s"
