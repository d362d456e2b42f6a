#!/usr/bin/env bash
# Set-up command (a): install packages, build (Release), run the main job on the embedded default
# case: the desktop application when a display is available, otherwise a headless run that writes
# its results folder. Extra arguments go to `filmdyn run` in the headless case.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/scripts/install-deps.sh"
# The application alone: the test suites and benches are built by the test command.
"$root/scripts/build.sh" filmdyn
filmdyn="${FILMDYN_BUILD_DIR:-$root/build}/app/filmdyn"
if [ -n "${DISPLAY:-}${WAYLAND_DISPLAY:-}" ]; then
  exec "$filmdyn"
fi
if "$filmdyn" --help | grep -q '^  run '; then
  echo "setup-and-run: no display; running the default case headless (results in ./results/)"
  exec "$filmdyn" run "$@"
fi
echo "setup-and-run: no display, and the headless 'run' command is not built yet;" >&2
echo "start with a display (or 'xvfb-run $filmdyn') to open the application." >&2
exit 1
