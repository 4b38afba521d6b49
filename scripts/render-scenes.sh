#!/usr/bin/env bash
# The main job: renders every standard scene headless with vtkDeepShadowVolumeMapper, and the
# CPU reference of each, into out/scenes (PNG images, differences, JSON statistics); then the
# short error-against-run-time report of every shadow technique into out/report.
# Extra arguments go to `deepshadow all` (e.g. --size 256x256).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
"$root/scripts/setup.sh"
mkdir -p "$root/out/scenes"
"$root/build/bin/deepshadow" all --out "$root/out/scenes" "$@"
"$root/build/bin/deepshadow" report --quick --out "$root/out/report"
