#!/usr/bin/env bash
# Installs every Debian 12 package FilmDyn needs to build, test and run. Idempotent: does
# nothing when all are present. Needs root or sudo; downloads only from Debian's archive.
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config git lld
  qt6-base-dev qt6-charts-dev qt6-svg-dev libqt6opengl6-dev
  libeigen3-dev libsuitesparse-dev libvtk9-dev nlohmann-json3-dev
  libsundials-dev libfmt-dev libtbb-dev libcli11-dev libboost-math-dev libhdf5-dev
  xvfb xauth libgl1-mesa-dri fonts-dejavu-core
  locales  # the definitions the tests compile a German locale from (decimal comma)
)
# Deliberately NOT libvtk9-qt-dev: Debian builds VTK's Qt module against Qt 5, which cannot share
# a process with Qt 6 (docs/design.md). FilmDyn has its own VTK-in-Qt-6 widget.

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages already installed"
  exit 0
fi

if [ "$(id -u)" -eq 0 ]; then
  sudo=()
elif command -v sudo >/dev/null 2>&1; then
  sudo=(sudo)
else
  echo "install-deps: missing packages (${missing[*]}) and neither root nor sudo available" >&2
  exit 1
fi

echo "install-deps: installing ${#missing[@]} packages: ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
"${sudo[@]}" apt-get update -qq
"${sudo[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
echo "install-deps: done"
