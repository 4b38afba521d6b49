#!/usr/bin/env bash
# Installs what is missing, builds (the module, and the ParaView plugin against ParaView's
# SDK), and runs every test with ctest. Extra arguments go to ctest (e.g. -R Core, -L paraview).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
"$root/scripts/setup.sh"
# The ParaView plugin, for the tests labelled paraview (ParaView's runtime and SDK beside VTK 9.1).
"$root/scripts/build-paraview-plugin.sh"
cd "$root/build"
ctest --output-on-failure --timeout 900 -j 2 "$@"
