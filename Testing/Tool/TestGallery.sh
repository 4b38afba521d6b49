#!/usr/bin/env bash
# The main job's page (deepshadow gallery) on a few scenes at a small size: every picture it
# names is there and not flat, the shadows are closer to the ground truth than no shadows, and
# headless Chromium draws the page (when installed: scripts/setup.sh installs it).
# Usage: TestGallery.sh path/to/deepshadow path/to/deepshadow-testkit work-directory
set -u
tool=$1
kit=$2
work=$3
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
rm -rf "$work"
mkdir -p "$work"
cd "$work" || exit 1
source "$here/expect.sh"

scenes=rods,spheres-half,hybrid-ground
expect 0 "gallery of three scenes" -- "$tool" gallery --out page --scenes "$scenes" --size 96x96 \
  --error-size 48x48 --frames 1
for scene in ${scenes//,/ }; do
  for kind in none shadows truth; do
    grep -q "src=\"$scene-$kind.png\"" page/index.html || fail "index.html does not show $scene-$kind.png"
    not_flat "page/$scene-$kind.png" "$scene-$kind.png"
  done
done
# Shadows bring the picture nearer the ground truth: RMSE with shadows < RMSE without.
python3 - page/summary.json <<'PY' || fail "a scene's shadows are not nearer the ground truth"
import json, sys
for scene in json.load(open(sys.argv[1]))["scenes"]:
    print("%s: RMSE %.5f without shadows, %.5f with %s" % (scene["scene"], scene["rmse_unshadowed"],
          scene["rmse_shadowed"], scene["technique"]))
    assert scene["rmse_shadowed"] < 0.5 * scene["rmse_unshadowed"], scene["scene"]
PY
expect 2 "gallery of an unknown scene" "unknown scene" -- "$tool" gallery --out page2 --scenes teapot

command -v chromium > /dev/null || skip_rest chromium
timeout 120 chromium --headless --no-sandbox --disable-gpu --hide-scrollbars \
  --screenshot="$work/page.png" --window-size=900,700 "file://$work/page/index.html" \
  > chromium.txt 2>&1
if [ -s page.png ]; then
  not_flat page.png "Chromium's screenshot of index.html"
else
  fail "Chromium wrote no screenshot"; tail -5 chromium.txt
fi
[ "$failures" -eq 0 ] || { echo "$failures failure(s)"; exit 1; }
echo "all gallery checks passed"
