#!/usr/bin/env bash
# Refreshes docs/screenshots/*.png: builds the GUI test that opens the main window, performs two
# real runs (core's run job) and saves each page, and runs it under Xvfb (xvfb-run) unless a
# DISPLAY is already set. Usage: scripts/screenshots.sh [build-dir]  (default: build/)
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
cmake --build "$build" -j "$jobs" --target test_ui_main_window_after_run
exe="$build/tests/ui/screenshots/test_ui_main_window_after_run"
mkdir -p "$out"
export FILMDYN_SCREENSHOT_DIR="$out" QT_QPA_PLATFORM=xcb
if [ -n "${DISPLAY:-}" ]; then
  "$exe"
else
  xvfb-run -a -s "-screen 0 1920x1200x24" "$exe"
fi
echo "screenshots in $out:"
ls -1 "$out"
