#!/usr/bin/env bash
# Refreshes docs/screenshots/*.png: builds the GUI tests that open the main window — one performs
# two real runs (core's run job) and saves each page, one drives the steady skirt calculator, the
# others save the field maps, the help window, the run table's identity and warnings columns —
# and runs them under Xvfb (xvfb-run) unless a DISPLAY is already set. Usage: scripts/screenshots.sh [build-dir]  (default: build/)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${1:-${FILMDYN_BUILD_DIR:-$root/build}}"
out="$root/docs/screenshots"
jobs="${FILMDYN_JOBS:-2}"
if [ ! -f "$build/CMakeCache.txt" ]; then
  generator=()
  command -v ninja >/dev/null 2>&1 && generator=(-G Ninja)
  cmake -S "$root" -B "$build" "${generator[@]}" -DCMAKE_BUILD_TYPE=Release
fi
cmake --build "$build" -j "$jobs" --target test_ui_main_window_after_run test_ui_skirt_calculator \
  test_ui_field_view test_ui_help test_ui_project_runs test_ui_run_warnings_column test_ui_study_view \
  test_ui_case_editor_lists
mkdir -p "$out"
export FILMDYN_SCREENSHOT_DIR="$out" QT_QPA_PLATFORM=xcb
for exe in "$build/tests/ui/screenshots/test_ui_main_window_after_run" \
           "$build/tests/ui/case_editor/test_ui_skirt_calculator" \
           "$build/tests/ui/fields/test_ui_field_view" \
           "$build/tests/ui/help/test_ui_help" \
           "$build/tests/ui/main_window/test_ui_project_runs" \
           "$build/tests/ui/run/test_ui_run_warnings_column" \
           "$build/tests/ui/main_window/test_ui_study_view" \
           "$build/tests/ui/case_editor/test_ui_case_editor_lists"; do
  if [ -n "${DISPLAY:-}" ]; then
    "$exe"
  else
    xvfb-run -a -s "-screen 0 1920x1200x24" "$exe"
  fi
done
echo "screenshots in $out:"
ls -1 "$out"
