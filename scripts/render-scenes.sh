#!/usr/bin/env bash
# The main job: renders every standard scene headless with vtkDeepShadowVolumeMapper, and the
# CPU reference of each, into out/scenes (PNG images, differences, JSON statistics); then the
# short error-against-run-time report of every shadow technique into out/report; and the
# bounded scenes (volumes inside CSG bounds) with deep shadows into out/bounded; and the
# hybrid scenes (meshes and volumes shadowing each other) with coloured deep shadows into
# out/hybrid, and their short error-against-run-time report into out/report-hybrid.
# Extra arguments go to `deepshadow all` (e.g. --size 256x256).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
"$root/scripts/setup.sh"
mkdir -p "$root/out/scenes"
"$root/build/bin/deepshadow" all --out "$root/out/scenes" "$@"
"$root/build/bin/deepshadow" report --quick --out "$root/out/report"
mkdir -p "$root/out/bounded"
for scene in head-cut box-torus spheres-half; do
  "$root/build/bin/deepshadow" render --scene "$scene" --technique dsm --frames 1 \
    --out "$root/out/bounded/$scene.png" --json "$root/out/bounded/$scene.json"
done
mkdir -p "$root/out/hybrid"
for scene in hybrid-ground hybrid-glass hybrid-rod hybrid-smoke; do
  "$root/build/bin/deepshadow" render --scene "$scene" --technique dsm-color --frames 1 \
    --out "$root/out/hybrid/$scene.png" --json "$root/out/hybrid/$scene.json"
done
"$root/build/bin/deepshadow" report --quick --scenes hybrid-ground,hybrid-glass,hybrid-rod,hybrid-smoke \
  --out "$root/out/report-hybrid"
