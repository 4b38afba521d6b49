#!/usr/bin/env bash
# Installs what is missing, builds, and runs every test (GoogleTest unit tests and VTK
# regression-image tests) with ctest. Extra arguments go to ctest (e.g. -R Core).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
"$root/scripts/setup.sh"
cd "$root/build"
ctest --output-on-failure --timeout 900 -j 2 "$@"
