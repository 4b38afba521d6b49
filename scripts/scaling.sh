#!/usr/bin/env bash
# Build and frame time of the deep shadow maps against the sparse scene's object count and
# the map size (issue "large and sparse scenes"): for each count (--objects) and size S, one
# S^2 map (dsm), the same with chunked node memory (dsm:chunk-nodes=4), and clustered maps of
# the same texels (dsm-clustered, at most 4 maps of (S/2)^2). Prints a Markdown table; the numbers
# come from `deepshadow shadow-bench` (build: a light move's rebuild; frame: a camera move's
# frame over the unshadowed one of the same run).
#   scripts/scaling.sh BUILD_DIR [COUNTS] [SIZES]   # defaults "1 4 12 24" and "256 512 1024"
# About 10 minutes on 2 cores (llvmpipe).
set -euo pipefail

build=${1:?usage: scaling.sh BUILD_DIR [COUNTS] [SIZES]}
counts=${2:-1 4 12 24}
sizes=${3:-256 512 1024}
tool="$build/bin/deepshadow"
[[ -x $tool ]] || { echo "scaling: no $tool (build first)" >&2; exit 2; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

echo "| objects | map | technique | build ms | frame / unshadowed | memory MB | RMSE |"
echo "|---|---|---|---|---|---|---|"
for count in $counts; do
  techniques=()
  for size in $sizes; do
    techniques+=("dsm:shadow-map-size=$size" "dsm:chunk-nodes=4:shadow-map-size=$size"
      "dsm-clustered:shadow-map-size=$((size / 2))")
  done
  list=$(IFS=,; echo "${techniques[*]}")
  DISPLAY= "$tool" shadow-bench --scenes sparse --objects "$count" --techniques "$list" \
    --size 512x512 --error-size 128x128 --frames 3 --json "$work/$count.json" > "$work/$count.txt"
  python3 - "$work/$count.json" "$count" <<'PY'
import json, re, sys
rows = json.load(open(sys.argv[1]))
rows = rows["rows"] if isinstance(rows, dict) else rows
for r in rows:
    spec = r["technique"]
    size = int(re.search(r"shadow-map-size=(\d+)", spec).group(1))
    name = spec.split(":")[0] + (":chunk-nodes=4" if "chunk-nodes" in spec else "")
    maps = f"{r['clusters']} x {size}^2" if name == "dsm-clustered" else f"{size}^2"
    print(f"| {sys.argv[2]} | {maps} | {name} | {r['build_ms']:.0f} | {r['camera_ratio']:.2f} | "
          f"{r['shadow_bytes'] / 1048576:.1f} | {r['rmse']:.5f} |")
PY
done
