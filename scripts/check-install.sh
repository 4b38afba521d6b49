#!/usr/bin/env bash
# The installed tree works for its two kinds of users (ctest runs this as Install.Consumers):
#   check-install.sh BUILD [PYTHON SITE]   (SITE: the package's directory under the prefix)
# installs BUILD into BUILD/Testing/Temporary/install, builds Examples/ (HeadlessVolume.cxx) as
# an outside project with find_package(vtkDeepShadow), runs it, and runs
# Examples/Python/ShadowedScene.py against the installed package with only PYTHONPATH set.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=$(cd "$1" && pwd)
python=${2:-}
site=${3:-}
work="$build/Testing/Temporary/install-check"
prefix="$work/prefix"
rm -rf "$work"
mkdir -p "$work"

cmake --install "$build" --prefix "$prefix" > "$work/install.log"
test -f "$prefix/lib/cmake/vtkDeepShadow/vtkDeepShadowConfig.cmake" || { echo "no CMake package"; exit 1; }

# C++: an outside project against the installed tree only.
cmake -S "$root/Examples" -B "$work/example" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_PREFIX_PATH="$prefix" > "$work/configure.log"
cmake --build "$work/example" > "$work/build.log"
env -i PATH=/usr/bin:/bin HOME="$work" "$work/example/HeadlessVolume" "" "$work/HeadlessVolume.png"

test -s "$work/HeadlessVolume.png" || { echo "no HeadlessVolume.png"; exit 1; }
[ -n "$python" ] || { echo "install check: the C++ consumer of $prefix rendered"; exit 0; }

# Python: the installed package, nothing from the build tree, no display.
test -f "$prefix/$site/vtkdeepshadow/__init__.py" || { echo "no Python package in $prefix/$site"; exit 1; }
(cd "$work" && env -i PATH=/usr/bin:/bin HOME="$work" PYTHONPATH="$prefix/$site" \
  "$python" "$root/Examples/Python/ShadowedScene.py" "$work/ShadowedScene.png")
test -s "$work/ShadowedScene.png" || { echo "no ShadowedScene.png"; exit 1; }
echo "install check: the C++ and Python consumers of $prefix rendered"
