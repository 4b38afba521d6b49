#!/usr/bin/env bash
# The report's guard (issue "Shadows that follow the physics"): on every standard and hybrid
# scene, no translucent technique at its defaults is less accurate than no shadows at all.
# Runs `deepshadow report --frames 0` (errors only) at 64x64 and reads results.csv's
# worse_than_none column.
# Usage: TestReportGuard.sh path/to/deepshadow work-directory
set -u
tool=$1
work=$2
rm -rf "$work"
mkdir -p "$work"
scenes=box,bucky,rods,clouds,spheres,head,sparse,hybrid-ground,hybrid-glass,hybrid-rod,hybrid-smoke,hybrid-sparse
techniques=rays,rays-cached,rays-color,dsm,dsm:chunk-nodes=4,dsm-cached,dsm-color,dsm-clustered,dsm3,dsm3-cached,cssm,cssm-cached
if ! "$tool" report --out "$work" --size 64x64 --error-size 64x64 --frames 0 --scenes "$scenes" \
  --techniques "$techniques" 2> "$work/progress.txt"; then
  echo "FAILED: the report did not run"; tail -3 "$work/progress.txt"; exit 1
fi
csv="$work/results.csv"
column=$(head -1 "$csv" | tr ',' '\n' | grep -n '^worse_than_none$' | cut -d: -f1)
rows=$(($(wc -l < "$csv") - 1))
if [ -z "$column" ] || [ "$rows" -ne 156 ]; then
  echo "FAILED: expected 156 rows with a worse_than_none column, got $rows"; exit 1
fi
defects=$(awk -F, -v c="$column" 'NR > 1 && $c == 1 { print $1 ": " $4 " RMSE " $18 }' "$csv")
if [ -n "$defects" ]; then
  echo "FAILED: translucent techniques less accurate than no shadows:"; echo "$defects"; exit 1
fi
grep -q "None here." "$work/README.md" || { echo "FAILED: the README does not say the guard holds"; exit 1; }
echo "ok: $rows rows, no translucent technique worse than none on $(echo "$scenes" | tr ',' ' ' | wc -w) scenes"
