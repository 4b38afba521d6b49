#!/usr/bin/env bash
# The first thing to run on a machine with a GPU: the test suite and the benchmarks through
# EGL on its driver instead of llvmpipe. Writes OUTDIR (default out/gpu): probe.json (which
# driver drew), ctest.txt, bench.json (ours against VTK's mapper), shadows.json (every
# technique: frame times, build times, errors), measured/frame-budget-gpu.md (the deep shadow
# maps' frame budget page, to commit as Documentation/Measured/frame-budget-gpu.md; its
# progress in frame-budget.txt), gallery/ and scenes/ (pictures to look at).
# Needs a build (scripts/setup.sh). Where the driver's EGL vendor file is outside glvnd's
# default folders (containers often mount it elsewhere), point __EGL_VENDOR_LIBRARY_FILENAMES
# at it. GPU_CHECK_CTEST_ARGS adds ctest arguments (e.g. -E to leave out tests whose tools the
# machine lacks); GPU_CHECK_STEP_LIMIT (seconds, default none) stops each step after that long,
# so that a leased machine returns what the finished steps wrote.
# Usage: scripts/gpu-check.sh [OUTDIR]
set -uo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
out=${1:-$root/out/gpu}
bin=$root/build/bin
mkdir -p "$out"
export VTK_DEEPSHADOW_BACKEND=egl DISPLAY= WAYLAND_DISPLAY=
limit=${GPU_CHECK_STEP_LIMIT:-0}
step() { if [ "$limit" -gt 0 ]; then timeout "$limit" "$@"; else "$@"; fi; }

"$bin/deepshadow" render --scene box --size 64x64 --frames 1 --out "$out/probe.png" \
  --json "$out/probe.json" || exit 1
renderer=$(sed -n 's/.*"gl_renderer": "\(.*\)".*/\1/p' "$out/probe.json")
echo "EGL draws with: $renderer"
case $renderer in
  *llvmpipe*) echo "note: that is Mesa's CPU rasterizer, not a GPU (is the driver's EGL vendor file found?)" ;;
esac

# shellcheck disable=SC2086 # the extra arguments are words
(cd "$root/build" && step ctest -j"$(nproc)" --output-on-failure ${GPU_CHECK_CTEST_ARGS:-}) \
  > "$out/ctest.txt" 2>&1
echo "ctest: $(grep -E 'tests passed|tests failed' "$out/ctest.txt" | tail -1) (details in $out/ctest.txt)"
step "$bin/deepshadow" bench --json "$out/bench.json"
step "$bin/deepshadow" shadow-bench --json "$out/shadows.json"
step python3 "$root/scripts/measured-tables.py" frame-budget --page frame-budget-gpu --tool "$bin/deepshadow" \
  --out "$out/measured" 2>"$out/frame-budget.txt" || echo "frame budget page: failed (see $out/frame-budget.txt)"
step "$bin/deepshadow" gallery --out "$out/gallery" | tail -1
step "$bin/deepshadow" all --out "$out/scenes" | tail -1
step "$bin/deepshadow" bench --blend-modes all --json "$out/bench-modes.json"
