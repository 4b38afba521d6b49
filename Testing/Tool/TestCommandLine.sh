#!/usr/bin/env bash
# The deepshadow tool's contract: --help, defaults, the JSON fields, what the pictures show
# (not flat; shadowed where shadows are expected), and exit code 2 with one line on stderr
# (and no output file left behind) for bad arguments, unreadable files and unsupported data.
# Hostile input has its own test (TestHostileInput.sh).
# Usage: TestCommandLine.sh path/to/deepshadow path/to/deepshadow-testkit work-directory
set -u
tool=$1
kit=$2
work=$3
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
mkdir -p "$work"
cd "$work" || exit 1
source "$here/expect.sh"

# A raw MetaImage volume: write_mhd NAME ELEMENTTYPE "DIMS" BYTES-GENERATOR
write_mhd() {
  printf 'ObjectType = Image\nNDims = 3\nDimSize = %s\nElementType = %s\nElementDataFile = %s.raw\n' \
    "$3" "$2" "$1" > "$1.mhd"
  eval "$4" > "$1.raw"
}

expect 0 "--help" -- "$tool" --help
grep -q "deepshadow render" out.txt || fail "--help lacks the render usage"
for command in render reference view all gallery bench shadow-bench report scenes presets; do
  expect 0 "$command --help" -- "$tool" "$command" --help
  grep -q "^  deepshadow $command" out.txt || fail "$command --help lacks its synopsis"
  grep -q "^  $command " out.txt || fail "$command --help lacks its description"
  [ "$(grep -c '^  deepshadow ' out.txt)" -eq 1 ] || fail "$command --help shows other commands' synopses"
done
expect 0 "--version" -- "$tool" --version
grep -q "^deepshadow [0-9][0-9.]* (vtkDeepShadow, built with VTK 9" out.txt || fail "--version: $(cat out.txt)"
expect 2 "no arguments" -- "$tool"
expect 2 "unknown command" -- "$tool" paint --out x.png
expect 2 "unknown option" -- "$tool" render --colour red --out x.png
expect 2 "missing --out" -- "$tool" render
expect 2 "bad size" -- "$tool" render --size 12 --out x.png
expect 2 "bad number" -- "$tool" render --sample-distance fast --out x.png
expect 2 "negative sample distance" -- "$tool" render --sample-distance -1 --out x.png
expect 2 "zero light direction" -- "$tool" render --light-dir 0,0,0 --out x.png
expect 2 "--objects on another scene" "sparse only" -- "$tool" render --scene rods --objects 4 --out x.png
expect 2 "--objects beyond 24" "[1, 24]" -- "$tool" render --scene sparse --objects 25 --out x.png
expect 2 "--objects not whole" "whole number" -- "$tool" render --scene sparse --objects 2.5 --out x.png
expect 2 "--chunk-nodes beyond 64" "chunk-nodes" -- "$tool" render --technique dsm --chunk-nodes 65 --out x.png
expect 0 "sparse with 4 objects, chunked deep shadow map" -- "$tool" render --scene sparse --scale 0.25 --objects 4 \
  --technique dsm --chunk-nodes 4 --size 32x32 --frames 1 --out x.png --json x.json
grep -q '"chunks_used": [1-9]' x.json || fail "chunked render: chunks_used in its JSON"
# A pool too small for the shadow degrades it (the bound doubled): the module says so, and
# without --verbose the tool prints it once and lists it in the JSON; a pool that fits says nothing.
expect 0 "chunked deep shadow map, a pool too small" -- "$tool" render --scene box --scale 0.25 --technique dsm \
  --chunk-nodes 4 --node-pool-mb 0.01 --size 32x32 --frames 1 --out x.png --json x.json
[ "$(grep -c "^deepshadow: warning: the deep shadow map's node pool" err.txt)" = 1 ] ||
  fail "a pool too small: one warning line on stderr"
grep -q '"warnings": \["the deep shadow map.s node pool' x.json || fail "a pool too small: the warning in the JSON"
expect 0 "chunked deep shadow map, a pool that fits" -- "$tool" render --scene box --scale 0.25 --technique dsm \
  --chunk-nodes 4 --size 32x32 --frames 1 --out x.png --json x.json
[ -s err.txt ] && fail "a pool that fits: stderr not empty"
grep -q '"warnings": \[\]' x.json || fail "a pool that fits: no warning in the JSON"
expect 2 "rmsm page size not a power of 2" "page-size" -- "$tool" render --technique rmsm --page-size 33 --out x.png
expect 2 "rmsm virtual size not allowed" "max-resolution" -- "$tool" render --technique rmsm --max-resolution 5000 --out x.png
expect 2 "rmsm atlas too small for the base level" "raise the atlas size" -- "$tool" render --technique rmsm --atlas-size 100 --out x.png
expect 0 "rmsm on the box" -- "$tool" render --scene box --scale 0.25 --technique rmsm --size 48x48 --frames 1 \
  --out x.png --json x.json
grep -q '"pages_unique": [1-9]' x.json && grep -q '"superpages": [1-9]' x.json || fail "rmsm render: its pages in its JSON"
expect 2 "unknown scene" -- "$tool" render --scene teapot --out x.png
expect 2 "unknown technique" -- "$tool" render --technique magic --out x.png
expect 2 "threshold out of range" -- "$tool" render --technique shadowmap --shadow-threshold 2 --out x.png
expect 2 "bad filter" -- "$tool" render --technique shadowmap --pcf 5x5 --out x.png
expect 2 "epsilon out of range" -- "$tool" render --technique dsm --epsilon 1.5 --out x.png
expect 2 "layers out of range" -- "$tool" render --technique dsm --layers 0 --out x.png
expect 2 "bad CSSM offsets" -- "$tool" render --technique cssm --cssm-offsets 9 --out x.png
expect 2 "bad opacity levels" -- "$tool" render --technique dsm3 --opacity-levels 0.5,0.2,0.9 --out x.png
expect 2 "bad technique spec" -- "$tool" shadow-bench --techniques dsm:colour=red
expect 2 "bad light" -- "$tool" render --light lamp:1,2,3 --out x.png
expect 2 "spot without angle" -- "$tool" render --light spot:0,0,100 --out x.png
expect 2 "scene and volume" -- "$tool" render --scene box --volume a.vti --out x.png
expect 2 "missing file" -- "$tool" render --volume does-not-exist.vti --out x.png
echo "not a volume" > garbage.vti
expect 2 "unreadable file" -- "$tool" render --volume garbage.vti --out x.png
echo "1 2 3" > volume.xyz
expect 2 "unsupported extension" -- "$tool" render --volume volume.xyz --out x.png

# 32-bit integers (kept in single precision): 32 samples 0, then 32 samples 1000000.
write_mhd int32 MET_INT "4 4 4" "head -c 128 /dev/zero; for i in \$(seq 32); do printf '\x40\x42\x0f\x00'; done"
expect 0 "int32 volume" -- "$tool" render --volume int32.mhd --size 64x64 --frames 1 --out int32.png
not_flat int32.png "int32 volume"
# Doubles beyond float's range: one 1e300 (0x7e37e43c8800759c, little endian) among zeros.
write_mhd huge MET_DOUBLE "4 4 4" "printf '\x9c\x75\x00\x88\x3c\xe4\x37\x7e'; head -c 504 /dev/zero"
expect 2 "doubles beyond float's range" "beyond single precision" -- "$tool" render --volume huge.mhd --out x.png
write_mhd flat MET_UCHAR "4 4 1" "head -c 16 /dev/zero"
expect 2 "zero extent" -- "$tool" render --volume flat.mhd --out x.png
# A float volume whose first sample is NaN (0x7fc00000, little endian), then 31 samples 0.0
# and 32 samples 1.0 (a constant volume would be transparent under the default look).
write_mhd nan MET_FLOAT "4 4 4" "printf '\x00\x00\xc0\x7f'; for i in \$(seq 31); do printf '\x00\x00\x00\x00'; done; for i in \$(seq 32); do printf '\x00\x00\x80\x3f'; done"
expect 2 "NaN samples" -- "$tool" render --volume nan.mhd --out x.png
expect 0 "NaN samples, replaced" -- "$tool" render --volume nan.mhd --replace-nonfinite --size 64x64 --frames 1 --out nan.png
not_flat nan.png "NaN samples, replaced"

# Transfer functions: the presets, a ParaView preset file, window/level, and bad ones.
expect 0 "presets" -- "$tool" presets
for name in CT-Bone CT-Skin CT-Muscle CT-Soft-Tissue CT-Lung MR-Default MR-Angio; do
  grep -q "^$name " out.txt || fail "presets lacks $name"
done
expect 0 "head with CT-Bone" -- "$tool" render --scene head --scale 0.25 --tf ct-bone --size 64x64 \
  --frames 1 --out tf-bone.png
not_flat tf-bone.png "head with CT-Bone"
expect 0 "head with CT-Skin" -- "$tool" render --scene head --scale 0.25 --tf CT-Skin --size 64x64 \
  --frames 1 --out tf-skin.png
rmse_at_least tf-bone.png tf-skin.png 0.01 "CT-Bone and CT-Skin"
expect 0 "CT-Bone, window/level" -- "$tool" render --scene head --scale 0.25 --tf CT-Bone \
  --window 300 --level 100 --size 64x64 --frames 1 --out tf-window.png
rmse_at_least tf-bone.png tf-window.png 0.01 "CT-Bone with and without window/level"
cat > paraview-preset.json <<'JSON'
[ { "Name": "Bone", "ColorSpace": "RGB",
    "RGBPoints": [ -1000, 0, 0, 0, 300, 0.9, 0.8, 0.7, 2000, 1, 1, 1 ],
    "Points": [ -1000, 0, 0.5, 0, 200, 0, 0.5, 0, 600, 0.8, 0.5, 0, 2000, 0.9, 0.5, 0 ] } ]
JSON
expect 0 "head with a ParaView preset file" -- "$tool" render --scene head --scale 0.25 \
  --tf paraview-preset.json --shade off --ambient 0.3 --size 64x64 --frames 1 --out tf-file.png
not_flat tf-file.png "head with a ParaView preset file"
expect 2 "unknown preset" "neither a transfer-function preset" -- "$tool" render --tf CT-Teapot --out x.png
echo '[{"RGBPoints": [0, 0, 0]}]' > bad-preset.json
expect 2 "bad preset file" "whole nodes of 4" -- "$tool" render --tf bad-preset.json --out x.png
expect 2 "window without level" -- "$tool" render --tf CT-Bone --window 100 --out x.png
# Isosurfaces and gradient opacity reach the mapper (its composed features say so).
expect 0 "head as an isosurface with a deep shadow map" -- "$tool" render --scene head --scale 0.25 \
  --isosurface 700 --technique dsm --size 64x64 --frames 1 --out iso.png --json iso.json
not_flat iso.png "head as an isosurface"
grep -q '"Isosurface"' iso.json || fail "--isosurface did not compose the Isosurface feature"
expect 0 "head with gradient opacity" -- "$tool" render --scene head --scale 0.25 \
  --gradient-opacity 200 --size 64x64 --frames 1 --out gradient.png --json gradient.json
not_flat gradient.png "head with gradient opacity"
grep -q '"GradientOpacity"' gradient.json || fail "--gradient-opacity did not compose GradientOpacity"
# A binary mask of the volume's dimensions (the half x < 8 kept), read as --volume is.
write_mhd masked MET_UCHAR "16 16 16" "python3 -c 'import sys; sys.stdout.buffer.write(bytes(((i * 37) % 200) + 40 for i in range(4096)))'"
write_mhd halfmask MET_UCHAR "16 16 16" "python3 -c 'import sys; sys.stdout.buffer.write(bytes(1 if i % 16 < 8 else 0 for i in range(4096)))'"
write_mhd smallmask MET_UCHAR "8 8 8" "head -c 512 /dev/zero"
expect 0 "a volume with a mask" -- "$tool" render --volume masked.mhd --mask halfmask.mhd \
  --size 64x64 --frames 1 --out masked.png --json masked.json
not_flat masked.png "a volume with a mask"
grep -q '"Mask"' masked.json || fail "--mask did not compose the Mask feature"
expect 0 "the same volume without it" -- "$tool" render --volume masked.mhd --size 64x64 --frames 1 --out unmasked.png
rmse_at_least masked.png unmasked.png 0.01 "a volume with and without its mask"
expect 2 "a mask of other dimensions" "the mask's dimensions 8x8x8 differ from the volume's 16x16x16" -- \
  "$tool" render --volume masked.mhd --mask smallmask.mhd --out x.png
expect 2 "a mask that is not there" "--mask:" -- "$tool" render --volume masked.mhd --mask nowhere.mhd --out x.png
expect 2 "bad contour value" "--isosurface expects a number" -- "$tool" render --isosurface 1,x --out x.png
expect 2 "17 contour values" "at most 16" -- "$tool" render --isosurface 1,2,3,4,5,6,7,8,9,10,11,12,13,14,15,16,17 --out x.png
expect 2 "non-positive gradient opacity" "must be positive" -- "$tool" render --gradient-opacity 0 --out x.png
expect 2 "window without a preset" -- "$tool" render --window 100 --level 0 --out x.png
expect 2 "bad shade" -- "$tool" render --shade maybe --out x.png
expect 2 "ambient out of range" -- "$tool" render --ambient 2 --out x.png

# Real medical files (python3-nibabel's test data): a NIfTI MR scan renders with shadows from
# an anterior view, and a look chosen from its histogram when no --tf is given.
nibabel=/usr/lib/python3/dist-packages/nibabel/tests/data
if [ -f "$nibabel/example4d.nii.gz" ]; then
  expect 0 "a NIfTI MR scan, anterior, deep shadow maps" -- "$tool" render --volume "$nibabel/example4d.nii.gz" \
    --tf MR-Default --technique dsm --view anterior --size 64x64 --frames 1 --out nifti.png
  not_flat nifti.png "a NIfTI MR scan"
  expect 0 "a NIfTI MR scan, no --tf and no --technique" -- "$tool" render --volume "$nibabel/example4d.nii.gz" \
    --view anterior --size 64x64 --frames 1 --out nifti-default.png --json nifti-default.json
  grep -q '"technique": "dsm"' nifti-default.json && grep -q '"look": "MR-Default, window' nifti-default.json &&
    echo "ok: a medical file's defaults: dsm, MR-Default windowed from its histogram" ||
    fail "a medical file's defaults: $(grep -E '"technique"|"look"' nifti-default.json)"
  not_flat nifti-default.png "a NIfTI MR scan with its defaults"
  expect 0 "the second volume of the 4D file" -- "$tool" render --volume "$nibabel/example4d.nii.gz" --volume-index 1 \
    --view anterior --size 64x64 --frames 1 --out nifti-1.png
  rmse_at_least nifti-1.png nifti-default.png 0.001 "volume 1 is not volume 0"
  expect 2 "a volume index past the file's volumes" "holds 2 volumes" -- "$tool" render --volume "$nibabel/example4d.nii.gz" \
    --volume-index 2 --out x.png
  "$tool" render --volume "$nibabel/example4d.nii.gz" --tf CT-Bone --size 32x32 --frames 1 --out x.png 2> ct-on-mr.txt
  grep -q "^deepshadow: warning: the CT preset CT-Bone is in Hounsfield units" ct-on-mr.txt &&
    echo "ok: a CT preset on MR data warns" || fail "a CT preset on MR data: $(cat ct-on-mr.txt)"
else
  echo "skipped: python3-nibabel's test data is not installed"
fi
# A real DICOM series (python3-pydicom's test files): 5 axial CT slices, with GDCM.
pydicom=/usr/lib/python3/dist-packages/pydicom/data/test_files/dicomdirtests
if [ -d "$pydicom/98892001/CT5N" ]; then
  rm -rf dicom && cp -r "$pydicom/98892001/CT5N" dicom
  expect 0 "a DICOM CT series, anterior, its defaults" -- "$tool" render --volume dicom \
    --view anterior --elevation 30 --size 64x64 --frames 1 --out dicom.png --json dicom.json
  not_flat dicom.png "a DICOM series"
  grep -q '"modality": "CT"' dicom.json && grep -q '"look": "CT-Bone"' dicom.json &&
    echo "ok: a CT series is shown with CT-Bone" || fail "a CT series' look: $(grep -E '"modality"|"look"' dicom.json)"
  expect 2 "one file of the series" "give the folder of the series" -- "$tool" render --volume dicom/2062 --out x.png
  expect 0 "the series of a folder of several" -- "$tool" series --volume "$pydicom/98892003/MR2"
  [ "$(grep -c "UID" out.txt)" -eq 3 ] && echo "ok: three series listed" || fail "series: $(cat out.txt)"
  expect 2 "a folder of several series" "holds 3 series" -- "$tool" render --volume "$pydicom/98892003/MR2" --out x.png
  expect 2 "a series number three series share" "choose one by its UID" -- "$tool" render --volume "$pydicom/98892003/MR2" \
    --series 2 --out x.png
else
  echo "skipped: python3-pydicom's test files are not installed"
fi
mkdir -p no-dicom && echo "notes" > no-dicom/readme.txt
expect 2 "a directory with no DICOM" "no DICOM files" -- "$tool" render --volume no-dicom --out x.png

# The camera: patient views, turns, and a camera file that reproduces a view exactly.
expect 0 "anterior view" -- "$tool" render --scene head --scale 0.25 --tf CT-Bone --view anterior \
  --size 64x64 --frames 1 --out anterior.png
expect 0 "left view, turned" -- "$tool" render --scene head --scale 0.25 --tf CT-Bone --view left \
  --azimuth 20 --elevation 10 --roll 5 --zoom 1.2 --size 64x64 --frames 1 --out left.png --json left.json
rmse_at_least anterior.png left.png 0.01 "anterior and left views"
grep -q '"camera": {' left.json || fail "render --json lacks the camera"
expect 0 "the camera file render --json wrote" -- "$tool" render --scene head --scale 0.25 --tf CT-Bone \
  --camera left.json --size 64x64 --frames 1 --out left-again.png
rmse_at_most left.png left-again.png 0 "a camera file reproduces the view"
expect 2 "unknown view" "--view takes anterior|" -- "$tool" render --view sideways --out x.png
expect 2 "camera with a view" "--camera sets the whole camera" -- "$tool" render --camera left.json \
  --view left --out x.png
echo '{"position": [0, 0, 1], "focal_point": [0, 0, 1], "view_up": [0, 1, 0]}' > degenerate-camera.json
expect 2 "degenerate camera" "the position is the focal point" -- "$tool" render \
  --camera degenerate-camera.json --out x.png
expect 2 "missing camera file" "no such file" -- "$tool" render --camera nowhere.json --out x.png

# A machine without what the backend needs (EGL with no vendor library, as where no driver
# is installed): one line and exit 2, no picture. VTK's End() aborted on the missing context.
no_driver=(env __EGL_VENDOR_LIBRARY_FILENAMES=/nonexistent.json "$tool")
expect 2 "EGL without a driver: render" "no headless egl context" -- "${no_driver[@]}" render \
  --backend egl --size 32x32 --frames 1 --out x.png
expect 2 "EGL without a driver: bench" "EGL" -- "${no_driver[@]}" bench --backend egl \
  --bench-sizes 32 --size 32x32 --frames 1

# The defaults: a standard scene, a PNG and the JSON statistics.
expect 0 "render with defaults" -- "$tool" render --size 96x96 --frames 2 --out default.png --json default.json
not_flat default.png "render with defaults"
for field in technique width height frames build_ms render_ms shadow_bytes first_frame_ms shadow_builds; do
  grep -q "\"$field\":" default.json || fail "default.json lacks $field"
done
grep -q '"frames": 2' default.json || fail "frames not recorded"
expect 0 "render with a technique" -- "$tool" render --scene bucky --scale 0.5 --size 64x64 --frames 1 \
  --technique shadowmap --shadow-map-size 64 --light dir:1,0,1 --light spot:0,0,90:30:0.5 \
  --out shadowed.png --json shadowed.json
grep -q '"shadow_builds": 2' shadowed.json || fail "expected 2 shadow builds (two lights)"
grep -q '"technique": "shadowmap"' shadowed.json || fail "technique not recorded"
# Shadows show: each technique's picture differs from the unshadowed one of the same view
# (measured RMSE 0.036-0.081 here; an unshadowed picture differs by 0).
expect 0 "the same view unshadowed" -- "$tool" render --scene bucky --scale 0.5 --size 64x64 --frames 1 \
  --light dir:1,0,1 --light spot:0,0,90:30:0.5 --out unshadowed-2.png
rmse_at_least shadowed.png unshadowed-2.png 0.01 "shadow map: shadowed"
expect 0 "bucky unshadowed" -- "$tool" render --scene bucky --scale 0.5 --size 64x64 --frames 1 --out unshadowed.png
not_flat unshadowed.png "bucky unshadowed"
expect 0 "render with a deep shadow map" -- "$tool" render --scene bucky --scale 0.5 --size 64x64 --frames 1 \
  --technique dsm --epsilon 0.01 --layers 4 --shadow-map-size 64 --out dsm.png --json dsm.json
for field in dsm_nodes_avg dsm_nodes_max shadow_bytes; do
  grep -q "\"$field\":" dsm.json || fail "dsm.json lacks $field"
done
# 64 x 64 texels x 4 nodes x 8 bytes, plus the 4096-texel feeler table (16 bytes each).
grep -q '"shadow_bytes": 196608' dsm.json || { echo "FAILED: dsm shadow_bytes"; grep shadow_bytes dsm.json; failures=$((failures + 1)); }
grep -q '"dsm_nodes_max": 0' dsm.json && fail "no nodes counted"
rmse_at_least dsm.png unshadowed.png 0.01 "deep shadow map: shadowed"
# Which passes ran: the first frame builds the map; the timed frames (nothing changed) only cast.
tr -d ' \n' < dsm.json | grep -q '"first_frame_passes":\[[^]]*"light-space-build"' ||
  fail "first frame's passes lack the map build"
tr -d ' \n' < dsm.json | grep -q '"passes":\["ray-cast"\]' ||
  fail "a repeated frame ran more than the ray cast"
for t in dsm-color dsm3 cssm cssm-cached; do
  expect 0 "render with $t" -- "$tool" render --scene bucky --scale 0.5 --size 64x64 --frames 1 \
    --technique $t --cssm-offsets 7 --cssm-seed 3 --out $t.png --json $t.json
  grep -q "\"technique\": \"$t\"" $t.json || fail "$t not recorded"
  rmse_at_least $t.png unshadowed.png 0.01 "$t: shadowed"
done
expect 0 "shadow-bench with technique specs" -- "$tool" shadow-bench --scenes bucky --scale 0.5 \
  --size 64x64 --error-size 16x16 --frames 1 --techniques none,dsm:layers=2:epsilon=0.1,cssm:cssm-photons=2
grep -q "dsm:layers=2:epsilon=0.1" out.txt || fail "shadow-bench row for the spec"
# "none" among the techniques is the baseline row, once (it crashed the tool).
[ "$(grep -c '^bucky  *none ' out.txt)" = 1 ] || fail "shadow-bench's none row"
# --volume without --scenes: the file alone, under a key light of its own.
expect 0 "shadow-bench of a volume file" -- "$tool" shadow-bench --volume int32.mhd --size 32x32 \
  --error-size 16x16 --frames 1 --techniques none,dsm-fixed:dsm-bits=64
grep -q '^int32.mhd  *dsm-fixed:dsm-bits=64 ' out.txt || fail "shadow-bench row of the file"
[ "$(grep -c '^bucky\|^box' out.txt)" = 0 ] || fail "shadow-bench of a file ran standard scenes"
# --receiver-error: the shadow term's error at the first receivers, per row, in the JSON; a
# fine map is closer there than 8 coarse slices. --charts: a chart per scene; a folder that
# does not exist is refused before the work.
mkdir -p charts
expect 0 "shadow-bench receiver errors and charts" -- "$tool" shadow-bench --scenes bucky --scale 0.5 \
  --size 32x32 --error-size 32x32 --frames 1 --techniques dsm-fixed:dsm-bits=512,slices:slices=8 \
  --receiver-error --charts charts --json receivers.json
python3 - receivers.json <<'PY' || fail "receiver errors"
import json, sys
rows = {r["technique"]: r for r in json.load(open(sys.argv[1]))["rows"]}
fine, coarse = rows["dsm-fixed:dsm-bits=512"], rows["slices:slices=8"]
assert fine["receiver_pixels"] > 100, fine
assert fine["receiver_rmse"] < 0.5 * coarse["receiver_rmse"], (fine["receiver_rmse"], coarse["receiver_rmse"])
PY
[ "$(head -c 4 charts/bucky.png | tail -c 3)" = PNG ] || fail "no chart of bucky"
expect 2 "charts into a missing folder" -- "$tool" shadow-bench --scenes bucky --charts no/such/folder
expect 0 "reference" -- "$tool" reference --scene bucky --scale 0.5 --size 64x64 --out reference.png --json reference.json
grep -q '"render_ms":' reference.json || fail "reference.json lacks render_ms"
# The CPU reference of the unshadowed view is the GPU's picture within its error (0.0013 here).
rmse_at_most reference.png unshadowed.png 0.005 "the CPU reference matches the GPU"
expect 0 "report" -- "$tool" report --scenes bucky,rods --scale 0.5 --size 64x64 --error-size 32x32 \
  --frames 1 --techniques dsm,shadowmap,cssm-cached --out report
for f in results.csv README.md bucky/error-vs-time.png rods/error-vs-time.png rods/dsm.png \
  rods/dsm-diff.png rods/truth.png rods/truth-color.png rods/truth-shadow.png; do
  [ -s "report/$f" ] || fail "report/$f missing"
done
[ "$(wc -l < report/results.csv)" -eq 9 ] || fail "results.csv: expected a header and 8 rows"
[ "$(grep -c '^report: \[' err.txt)" -eq 8 ] || fail "report progress on stderr"
grep -q '^| >= ' report/README.md || fail "README.md lacks the budget table"
# The Pareto flags (camera-moving frames): a flagged row is beaten by no other in both frame
# time and RMSE; an unflagged one is matched or beaten by some row in both.
awk -F, 'NR > 1 { s[NR] = $1; t[NR] = $13; e[NR] = $18; p[NR] = $22 }
  END { bad = 0
    for (i in s) { beaten = 0; matched = 0
      for (j in s) if (i != j && s[i] == s[j] && t[j] <= t[i] && e[j] <= e[i]) {
        matched = 1; if (t[j] < t[i] || e[j] < e[i]) beaten = 1 }
      if ((p[i] == 1 && beaten) || (p[i] == 0 && !matched)) { print "row " i " pareto " p[i]; bad = 1 } }
    exit bad }' report/results.csv || fail "Pareto flags"
expect 2 "report without --out" -- "$tool" report --quick
expect 2 "report of an unknown scene" -- "$tool" report --scenes teapot --out report2
expect 0 "scenes" -- "$tool" scenes
[ "$(grep -c '^[a-z]' out.txt)" -eq 15 ] || fail "expected 7 scenes, 3 bounded and 5 hybrid ones"

# Polyhedral bounds: bounded scenes, meshes from files combined by --csg, and bad bounds.
cube_obj() { # cube_obj FILE LO HI [FACES]: an OBJ cube, outward; FACES < 6 leaves it open
  local lo=$2 hi=$3 faces=${4:-6}
  { for z in $lo $hi; do for y in $lo $hi; do for x in $lo $hi; do echo "v $x $y $z"; done; done; done
    printf 'f 1 5 7 3\nf 2 4 8 6\nf 1 2 6 5\nf 3 7 8 4\nf 1 3 4 2\nf 5 6 8 7\n' | head -n "$faces"; } > "$1"
}
cube_obj big.obj -20 20
cube_obj small.obj -8 8
cube_obj open.obj -20 20 5
cube_obj far.obj 100 110
{ cat big.obj; sed 's/-20/-10/g; s/ 20/ 30/g' big.obj | grep '^v'; \
  printf 'f 9 13 15 11\nf 10 12 16 14\nf 9 10 14 13\nf 11 15 16 12\nf 9 11 12 10\nf 13 14 16 15\n'; } > crossed.obj
expect 0 "a bounded scene" -- "$tool" render --scene box-torus --scale 0.5 --size 64x64 --technique dsm --out torus.png --json torus.json
grep -q '"bound_mode": "per-ray"' torus.json || fail "torus.json lacks the bound mode"
grep -q '"Bound"' torus.json || fail "torus.json lacks the Bound feature"
expect 0 "--bound with --csg" -- "$tool" render --scene box --scale 0.5 --size 64x64 --bound big.obj --bound small.obj --csg "diff(A,B)" --out diff.png --json diff.json
grep -q '"bound_expression": "diff(A,B)"' diff.json || fail "diff.json lacks the expression"
expect 0 "--csg-mesh" -- "$tool" render --scene box --scale 0.5 --size 64x64 --bound big.obj --bound small.obj --csg "diff(A,B)" --csg-mesh --out diff-mesh.png --json diff-mesh.json
grep -q '"bound_mode": "cgal-mesh"' diff-mesh.json || fail "diff-mesh.json lacks the mode"
# The two ways bound the same solid (identical here; TestBoundTwoWays holds the tolerance).
not_flat diff.png "--bound with --csg"
rmse_at_most diff.png diff-mesh.png 0.002 "per-ray and CGAL-mesh bounds agree"
expect 0 "an empty CSG result" -- "$tool" render --scene box --scale 0.5 --size 64x64 --bound big.obj --bound far.obj --csg "inter(A,B)" --out empty.png
grep -q "encloses nothing" err.txt || fail "an empty result is not said"
"$kit" flat empty.png > kit.txt && echo "ok: an empty bound draws nothing" || fail "an empty bound drew something: $(cat kit.txt)"
expect 2 "an open bound" -- "$tool" render --scene box --size 64x64 --bound open.obj --out x.png
grep -q "not closed" err.txt || fail "the open bound's error does not say so"
expect 2 "a self-intersecting bound" -- "$tool" render --scene box --size 64x64 --bound crossed.obj --out x.png
grep -q "intersects itself" err.txt || fail "the self-intersection is not said"
expect 2 "a bad --csg" -- "$tool" render --scene box --size 64x64 --bound big.obj --csg "diff(A,B)" --out x.png
expect 2 "--csg without bounds" -- "$tool" render --scene box --size 64x64 --csg "A" --out x.png
echo "solid" > mesh.xyz
expect 2 "an unsupported mesh format" -- "$tool" render --scene box --size 64x64 --bound mesh.xyz --out x.png
expect 2 "a missing mesh" -- "$tool" render --scene box --size 64x64 --bound none.stl --out x.png

# Hybrid scenes: meshes that cast and receive (--mesh and its options, --ground, the scenes).
expect 0 "a hybrid scene" -- "$tool" render --scene hybrid-glass --scale 0.5 --size 64x64 --technique dsm-color --frames 1 --out glass.png --json glass.json
grep -q '"casting_meshes": 2' glass.json || fail "glass.json lacks its 2 casting meshes"
expect 0 "the glass scene unshadowed" -- "$tool" render --scene hybrid-glass --scale 0.5 --size 64x64 --frames 1 --out glass-none.png
rmse_at_least glass.png glass-none.png 0.01 "the glass and the box shadow the ground"
expect 0 "the smoke + cup + head scene (two volumes)" -- "$tool" render --scene hybrid-smoke --scale 0.5 --size 64x64 --technique dsm --frames 2 --out smoke.png --json smoke.json
grep -q '"volumes": 2' smoke.json && grep -q '"other_volume_shadow_builds": 4' smoke.json ||
  fail "smoke.json lacks its 2 volumes and their 4 grids (head, smoke, ground, cup), built once"
grep -q '"merged_volumes": 1' smoke.json && grep -q '"volume_segment_bytes": 524288' smoke.json ||
  fail "smoke.json: the smoke is not merged into the head's march in 8 segments (16 B x 64 x 64 x 8)"
expect 0 "the smoke scene unshadowed" -- "$tool" render --scene hybrid-smoke --scale 0.5 --size 64x64 --frames 1 --out smoke-none.png
rmse_at_least smoke.png smoke-none.png 0.01 "the smoke scene is shadowed"
expect 0 "the smoke blended over the head (--volume-segments 0)" -- "$tool" render --scene hybrid-smoke --scale 0.5 --size 64x64 --technique dsm --frames 1 --volume-segments 0 --out blended.png --json blended.json
grep -q '"merged_volumes": 0' blended.json ||
  fail "--volume-segments 0 still merges"
expect 2 "--volume-segments out of range" -- "$tool" render --scene hybrid-smoke --volume-segments 9
expect 0 "--mesh with opacity, colour, transform and --ground" -- "$tool" render --scene box --scale 0.5 --size 64x64 --technique rays --frames 1 --mesh small.obj --mesh-opacity 0.4 --mesh-color 1,0.2,0.2 --mesh-transform 0,0,30,0.5 --ground --out meshes.png --json meshes.json
grep -q '"meshes": 2' meshes.json || fail "meshes.json lacks the mesh and the ground"
expect 0 "an open mesh (meshes need not be closed)" -- "$tool" render --scene box --scale 0.5 --size 64x64 --technique shadowmap --frames 1 --mesh open.obj --out open.png
expect 2 "--mesh-opacity before any --mesh" -- "$tool" render --scene box --mesh-opacity 0.5 --mesh small.obj --out x.png
expect 2 "--mesh-opacity out of range" -- "$tool" render --scene box --mesh small.obj --mesh-opacity 1.5 --out x.png
expect 2 "a bad --mesh-color" -- "$tool" render --scene box --mesh small.obj --mesh-color 1,2 --out x.png
expect 2 "a bad --mesh-transform" -- "$tool" render --scene box --mesh small.obj --mesh-transform 1,2,3,0 --out x.png
expect 2 "an unsupported --mesh format" -- "$tool" render --scene box --mesh mesh.xyz --out x.png
# A binary STL of one triangle whose second point has x = NaN (float 0x7fc00000).
{ head -c 80 /dev/zero; printf '\001\000\000\000'; head -c 12 /dev/zero; head -c 12 /dev/zero
  printf '\000\000\300\177'; head -c 8 /dev/zero; printf '\000\000\200\077'; head -c 8 /dev/zero
  head -c 2 /dev/zero; } > nan.stl
expect 2 "a --mesh with NaN points" -- "$tool" render --scene box --scale 0.5 --size 64x64 --technique rays --mesh nan.stl --out x.png
# A translucent mesh inside the volume is peeled into layers the volume composites.
grep -q '"peeled_layers": 4' meshes.json || fail "meshes.json lacks its 4 peeled layers"
expect 0 "--translucent-layers 0 (VTK's order)" -- "$tool" render --scene box --scale 0.5 --size 64x64 --frames 1 --mesh small.obj --mesh-opacity 0.4 --translucent-layers 0 --out unsorted.png --json unsorted.json
grep -q '"peeled_layers": 0' unsorted.json || fail "unsorted.json peeled layers"
expect 2 "--translucent-layers out of range" -- "$tool" render --scene box --mesh small.obj --translucent-layers 9 --out x.png

echo "$failures failure(s)"
[ "$failures" -eq 0 ]
