#!/usr/bin/env bash
# Resolution-matched shadow maps against shadow maps on hybrid-sparse (a small volume over a
# large ground, the camera close to it): the shadow-edge error of each against exact opaque
# visibility (the CPU's opaque shadow rays with the GPU's approximations), as
# Documentation/Shadows.md ("Resolution-matched shadow maps") reports it.
#   bash scripts/rmsm-edges.sh [BUILD_DIR] [OUT_DIR]     (SIZE=WxH, default 512x512)
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
build="${1:-build}"
out="${2:-/tmp/rmsm-edges}"
size="${SIZE:-512x512}"
tool="$build/bin/deepshadow"
mkdir -p "$out"
export DISPLAY=
scene=(--scene hybrid-sparse --size "$size")
"$tool" reference "${scene[@]}" --technique rays-opaque --gpu-twin --out "$out/exact.png" >/dev/null
render() { # NAME TECHNIQUE [FLAGS...]
  local name="$1"
  shift
  "$tool" render "${scene[@]}" --frames 1 --technique "$@" --out "$out/$name.png" --json "$out/$name.json" >/dev/null
}
render none none
render shadowmap-512 shadowmap
render shadowmap-1024 shadowmap --shadow-map-size 1024
render shadowmap-2048 shadowmap --shadow-map-size 2048
render shadowmap-4096 shadowmap --shadow-map-size 4096
render rmsm rmsm
render rmsm-downsample-1 rmsm --analysis-downsample 1
render rmsm-downsample-8 rmsm --analysis-downsample 8
render rmsm-atlas-512 rmsm --atlas-size 512
render rmsm-max-4096 rmsm --max-resolution 4096
cd "$out"
/usr/bin/python3 "$here/edge-error.py" exact.png none.png none.png shadowmap-512.png shadowmap-1024.png \
  shadowmap-2048.png shadowmap-4096.png rmsm.png rmsm-downsample-1.png rmsm-downsample-8.png \
  rmsm-atlas-512.png rmsm-max-4096.png
