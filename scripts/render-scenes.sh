#!/usr/bin/env bash
# The main job: every standard, bounded and hybrid scene rendered headless without shadows,
# with its default shadows (deep shadow maps; coloured ones for the hybrid scenes) and as the
# CPU ground truth, side by side in out/index.html with frame times and errors (deepshadow
# gallery: about two minutes on two cores after the build), and Chromium's screenshot of the
# page in out/index.png. The reports of every technique and parameter: scripts/report.sh.
# Extra arguments go to `deepshadow gallery` (e.g. --size 384x384, --scenes head,rods).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
"$root/scripts/setup.sh"
mkdir -p "$root/out"
start=$(date +%s)
"$root/build/bin/deepshadow" gallery --out "$root/out" "$@"
if command -v chromium > /dev/null; then
  timeout 120 chromium --headless --no-sandbox --disable-gpu --hide-scrollbars \
    --screenshot="$root/out/index.png" --window-size=1300,3600 "file://$root/out/index.html" \
    > /dev/null 2>&1 || echo "render-scenes: Chromium could not screenshot the page"
fi
echo "render-scenes: out/index.html in $(( $(date +%s) - start )) s after the build"
