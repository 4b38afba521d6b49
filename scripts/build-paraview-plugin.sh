#!/usr/bin/env bash
# Builds the ParaView plugin (Plugins/ParaView: the module's layers compiled again against
# ParaView's VTK 9.2, and the "Shadowed Volume" representation) into build-paraview/, after
# scripts/setup-paraview.sh. The plugin: build-paraview/lib/paraview-5.11/plugins/DeepShadow/DeepShadow.so
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
"$root/scripts/setup-paraview.sh"
# shellcheck disable=SC1091
. "${DEEPSHADOW_PVSDK:-/opt/deepshadow-pvsdk}/env.sh"
# Debian's interpreter, the one pvbatch embeds (a pyenv python may come first on PATH).
cmake -S "$root/Plugins/ParaView" -B "$root/build-paraview" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DPython3_EXECUTABLE=/usr/bin/python3 -DParaView_DIR="$ParaView_DIR" >/dev/null
cmake --build "$root/build-paraview" -j "$(nproc)"
echo "build-paraview-plugin: $root/build-paraview/lib/paraview-5.11/plugins/DeepShadow/DeepShadow.so"
