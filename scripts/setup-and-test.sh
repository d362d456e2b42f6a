#!/usr/bin/env bash
# Set-up command (b): install packages, build (Release), run every test. GL tests run under
# xvfb-run automatically; everything else on Qt's offscreen platform.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
start=$(date +%s)
"$root/scripts/install-deps.sh"
"$root/scripts/build.sh"
build="${FILMDYN_BUILD_DIR:-$root/build}"
cd "$build"
ctest --output-on-failure -j "${FILMDYN_TEST_JOBS:-2}"
echo "setup-and-test: all tests passed in $(( $(date +%s) - start )) s"
