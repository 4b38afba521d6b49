#!/usr/bin/env bash
# Benchmark: ParaView frames while rotating (interactive renders) and after (still renders),
# with ParaView's default light kit, on the Colin27 brain MRI (181x217x181, mricron-data) at
# 500x500: ParaView's Volume, the Shadowed Volume without a technique, and with dsm at
# ShadowInteractiveLag 0 and at its default, and dsm-cached, each at the default
# ShadowInteractiveSubsampling (8) and, for dsm and dsm-cached at the default lag, at 1 (a
# lookup per sample while interacting). Unshaded (ParaView's default), or shaded with SHADE=1
# (shaded volumes look their shadows up per sample). Needs the plugin
# (scripts/build-paraview-plugin.sh).
#   [SHADE=1] scripts/paraview-rotation.sh [FRAMES [DEGREES]]
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
plugin="$root/build-paraview/lib/paraview-5.11/plugins/DeepShadow/DeepShadow.so"
sdk=${DEEPSHADOW_PVSDK:-/opt/deepshadow-pvsdk}
[ -f "$plugin" ] && [ -f "$sdk/env.sh" ] || { echo "the ParaView plugin is not built (scripts/build-paraview-plugin.sh)" >&2; exit 2; }
brain=/usr/share/mricron/templates/ch2.nii.gz
[ -f "$brain" ] || { echo "$brain is missing (apt-get install mricron-data)" >&2; exit 2; }
frames=${1:-36}
degrees=${2:-2.5}
work=$(mktemp -d)
trap 'kill ${xvfb:-} 2>/dev/null || true; rm -rf "$work"' EXIT
# ParaView 5.11 reads .vti; VTK's NIfTI reader (system Python) converts it.
env -u PYTHONPATH /usr/bin/python3 - "$brain" "$work/brain.vti" <<'PY'
import sys
from vtkmodules.vtkIOImage import vtkNIFTIImageReader
from vtkmodules.vtkIOXML import vtkXMLImageDataWriter
reader = vtkNIFTIImageReader()
reader.SetFileName(sys.argv[1])
writer = vtkXMLImageDataWriter()
writer.SetInputConnection(reader.GetOutputPort())
writer.SetFileName(sys.argv[2])
writer.Write()
PY
# shellcheck source=../Testing/ParaView/xvfb.sh
. "$root/Testing/ParaView/xvfb.sh"
# shellcheck disable=SC1090
. "$sdk/env.sh"
export DISPLAY=$display
run() { pvbatch "$root/Testing/ParaView/rotation.py" "$plugin" "$work/brain.vti" "$@" "$frames" "$degrees" 2>&1 |
  grep -E "interactive .* ms|frames:" || { echo "pvbatch failed: $*" >&2; exit 1; }; }
run "Volume" none 0
run "Shadowed Volume" none 0
run "Shadowed Volume" dsm 0
run "Shadowed Volume" dsm 10
run "Shadowed Volume" dsm-cached 10
SUBSAMPLING=1 run "Shadowed Volume" dsm 10
SUBSAMPLING=1 run "Shadowed Volume" dsm-cached 10
