#!/usr/bin/env bash
# deepshadow view, the interactive viewer, under Xvfb (a virtual X display): keys sent through
# its interactor (--keys), screenshots taken and compared. A light move rebuilds only the
# light's structure (one light: one build), a technique switch changes the picture, g hides
# the meshes, the status line shows the frame beneath it; without a display the command says
# so and exits 2, and with a display nobody serves as well.
# Usage: TestView.sh path/to/deepshadow path/to/deepshadow-testkit work-directory
set -u
tool=$1
kit=$2
work=$3
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
rm -rf "$work"
mkdir -p "$work"
cd "$work" || exit 1
source "$here/expect.sh"

env -u DISPLAY -u WAYLAND_DISPLAY "$tool" view --scene rods > out.txt 2> err.txt
code=$?
if [ "$code" -eq 2 ] && grep -q "^deepshadow: view needs a display" err.txt && [ "$(wc -l < err.txt)" -eq 1 ]; then
  echo "ok: no display: $(cat err.txt)"
else
  fail "no display: exit $code, $(cat err.txt)"
fi
expect 2 "unknown key" "--keys takes" -- "$tool" view --keys t,x
expect 2 "a display no X server serves (SIGSEGV before)" "no X server answers" -- env DISPLAY=:4711 "$tool" view --scene rods

command -v Xvfb > /dev/null || skip_rest Xvfb
# A display number nobody uses.
for number in $(seq 90 120); do
  [ -e "/tmp/.X$number-lock" ] || break
done
Xvfb ":$number" -screen 0 1024x768x24 -nolisten tcp > xvfb.txt 2>&1 &
xvfb=$!
trap 'kill $xvfb 2> /dev/null' EXIT
for attempt in $(seq 50); do
  [ -e "/tmp/.X11-unix/X$number" ] && break
  sleep 0.1
done

mkdir -p shots
expect 0 "view with keys under Xvfb" -- env DISPLAY=":$number" "$tool" view --scene rods --ground \
  --size 160x120 --technique dsm --keys s,Left,s,t,s,g,s --screenshots shots
field() { python3 -c "import json,sys; print(json.load(open(sys.argv[1]))[sys.argv[2]])" "$1" "$2"; }
[ "$(field shots/view-1.json window)" = "vtkXOpenGLRenderWindow" ] || fail "not VTK's X window: $(field shots/view-1.json window)"
not_flat shots/view-1.png "the first view"
not_flat shots/view-1-window.png "the window with its status line"
rmse_at_least shots/view-1.png shots/view-1-window.png 0.001 "the status line shows"
rmse_at_least shots/view-1.png shots/view-2.png 0.005 "a light move moves the shadows"
[ "$(field shots/view-2.json shadow_builds)" -eq $(( $(field shots/view-1.json shadow_builds) + 1 )) ] ||
  fail "a light move made $(field shots/view-1.json shadow_builds) -> $(field shots/view-2.json shadow_builds) builds, not one more"
# The status line speaks of the frame beneath it: the rebuild the light move caused, the
# time the frame took (it showed the frame before's).
builds=$(field shots/view-2.json shadow_builds)
status=$(field shots/view-2.json status)
case "$status" in
  *"builds $builds"*"") echo "ok: the status line shows this frame's $builds builds" ;;
  *) fail "the status line '$status' is not of the frame with $builds builds" ;;
esac
case "$status" in
  *"| $(printf '%.0f' "$(field shots/view-2.json frame_ms)") ms |"*) echo "ok: the status line shows this frame's time" ;;
  *) fail "the status line '$status' shows another frame's time than $(field shots/view-2.json frame_ms) ms" ;;
esac
[ "$(field shots/view-3.json technique)" != "$(field shots/view-2.json technique)" ] || fail "t did not switch the technique"
rmse_at_least shots/view-2.png shots/view-3.png 0.005 "a technique switch changes the picture"
rmse_at_least shots/view-3.png shots/view-4.png 0.01 "g hides the ground"
[ "$failures" -eq 0 ] || { echo "$failures failure(s)"; exit 1; }
echo "all viewer checks passed"
