#!/usr/bin/env bash
# Installs what vtkDeepShadow needs on Debian 12 (only what is missing; safe to re-run) and
# builds it into build/. Used by render-scenes.sh and test.sh; --deps-only installs and stops
# (scripts/sanitize.sh builds its own directory).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)

packages=(cmake ninja-build g++ ccache pkg-config
  libvtk9-dev libosmesa6-dev libegl-dev libegl-mesa0 libgl1-mesa-dri
  libglm-dev libcgal-dev libgtest-dev
  libgdcm-dev     # DICOM through GDCM (compressed transfer syntaxes, series, multi-frame)
  python3-nibabel # real MR scans (NIfTI) for the reader tests
  python3-pydicom # a real CT series (its test files), and the DICOM series the tests write
  dcm2niix        # the independent DICOM-to-NIfTI converter the DICOM tests compare against
  libgdcm-tools   # gdcmconv: the tests re-encode a real series in compressed transfer syntaxes
  mricron-data    # the Colin27 brain MRI (NIfTI): the tests' and documentation's real anatomy
  chromium        # headless screenshots of the main job's page (out/index.html)
  doxygen         # the class documentation from the headers (Documentation.Doxygen)
  xvfb)           # a virtual display for the interactive viewer's test
missing=()
for package in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" ||
    missing+=("$package")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${missing[*]}"
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo="sudo"
  export DEBIAN_FRONTEND=noninteractive
  $sudo apt-get update -q
  $sudo apt-get install -y -q --no-install-recommends "${missing[@]}"
fi

[ "${1:-}" = "--deps-only" ] && exit 0
cmake -S "$root" -B "$root/build" -G Ninja -DCMAKE_BUILD_TYPE=Release
cmake --build "$root/build" -j "$(nproc)"
