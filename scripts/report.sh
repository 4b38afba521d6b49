#!/usr/bin/env bash
# The error-against-run-time reports of every shadow technique over a sweep of its
# parameters (deepshadow report): on the standard scenes into out/report and on the hybrid
# scenes into out/report-hybrid. Quick by default (256x256, errors at 128x128, 3 frames:
# about 4 and 9 minutes on two cores); --full: 512x512, errors at 256x256, 5 frames (hours).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
"$root/scripts/setup.sh"
quick=(--quick)
if [ "${1:-}" = "--full" ]; then
  quick=()
  shift
fi
"$root/build/bin/deepshadow" report "${quick[@]}" --out "$root/out/report" "$@"
"$root/build/bin/deepshadow" report "${quick[@]}" \
  --scenes hybrid-ground,hybrid-glass,hybrid-rod,hybrid-smoke,hybrid-sparse --out "$root/out/report-hybrid" "$@"
