#!/usr/bin/env bash
# Hostile input II (issue 45): the inputs of a second, independent corpus, written by
# HostileInputs.py, each once a signal, a hang, unbounded memory, a wrong picture with exit 0,
# a lost user file or a wrong reason. Each must now give exit 2 with one line saying what is
# wrong (and no output file), or exit 0 with the right picture.
# Usage: TestHostileInputII.sh deepshadow deepshadow-testkit python3 work-directory
set -u
tool=$1
kit=$2
python=$3
work=$4
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
mkdir -p "$work"
cd "$work" || exit 1
source "$here/expect.sh"
rm -rf gen seeds && mkdir seeds
"$kit" seeds seeds > /dev/null || { echo "FAILED: seeds"; exit 1; }
"$python" "$here/HostileInputs.py" gen || { echo "FAILED: HostileInputs.py"; exit 1; }
small=(--size 32x32 --frames 1)
box=(render --scene box --scale 0.1 "${small[@]}")
volume=(render --volume seeds/volume-raw.vti "${small[@]}")
# Every case runs under a time limit: a hang is a failure, not a stuck test.
limit=(timeout 120)

echo "== Signals before: XML nested 150,000 deep, NIfTI float128, a display nobody serves"
expect 2 "a .vti nested 150000 deep (SIGSEGV)" "nest more than 256" -- "${limit[@]}" "$tool" render --volume gen/deep.vti "${small[@]}" --out x.png
expect 2 "a .vtp nested 150000 deep (SIGSEGV)" "nest more than 256" -- "${limit[@]}" "$tool" "${box[@]}" --mesh gen/deep.vtp --out x.png
expect 2 "a .vti of 2 million elements" "more than 100000 XML elements" -- "${limit[@]}" "$tool" render --volume gen/wide.vti "${small[@]}" --out x.png
expect 2 "NIfTI datatype 1536, float128 (SIGSEGV)" "datatype 1536 (float128)" -- "${limit[@]}" "$tool" render --volume gen/float128.nii "${small[@]}" --out x.png
expect 2 "NIfTI bitpix 16 for uint8" "bitpix 16" -- "${limit[@]}" "$tool" render --volume gen/bitpix.nii "${small[@]}" --out x.png
expect 2 "NIfTI vox_offset 1e9 past the end" "truncated" -- "${limit[@]}" "$tool" render --volume gen/voxoffset.nii "${small[@]}" --out x.png
expect 2 "NIfTI with a negative dimension" "dimension 2 is -4" -- "${limit[@]}" "$tool" render --volume gen/dims.nii "${small[@]}" --out x.png
expect 0 "gzip data named .nii (was: truncated)" -- "${limit[@]}" "$tool" render --volume gen/gzipped-as.nii "${small[@]}" --out gz.png
expect 0 "the same NIfTI uncompressed" -- "${limit[@]}" "$tool" render --volume gen/ramp.nii "${small[@]}" --out plain.png
rmse_at_most gz.png plain.png 0 "gzip under .nii reads as the plain file"
not_flat plain.png "the plain NIfTI ramp"
expect 2 "view with DISPLAY naming no X server (SIGSEGV)" "no X server answers" -- env DISPLAY=:4711 "${limit[@]}" "$tool" view --scene box --scale 0.1

echo "== Hangs and unbounded work before"
expect 2 "a DICOM folder holding a named pipe (blocked for ever)" "not a regular file" -- "${limit[@]}" "$tool" render --volume gen/dicom-fifo "${small[@]}" --out x.png
expect 2 "a transfer function of 200000 nodes (quadratic)" "at most 4096" -- "${limit[@]}" "$tool" "${box[@]}" --tf gen/tf-200k.json --out x.png
terms="union(A$(printf ',A%.0s' $(seq 19)))"
expect 2 "20 unions of a 20,000-triangle sphere (105 s)" "triangles of work" -- "${limit[@]}" "$tool" "${box[@]}" --bound gen/sphere-20k.vtp --csg "$terms" --out x.png
expect 2 "--csg-max-work below an intersection's work" "more than the limit of 1000" -- "${limit[@]}" "$tool" render --volume seeds/volume-raw.vti "${small[@]}" --bound gen/cube.obj --bound gen/sphere-20k.vtp --csg "inter(A,B)" --csg-max-work 1000 --out x.png

echo "== Memory before: what a device gives without end"
expect 2 "--tf /dev/zero (bad_alloc)" "more than a preset file needs" -- "${limit[@]}" "$tool" "${box[@]}" --tf /dev/zero --out x.png
expect 2 "--camera /dev/urandom (bad_alloc)" "larger than a camera needs" -- "${limit[@]}" "$tool" "${box[@]}" --camera /dev/urandom --out x.png

echo "== Wrong or blank pictures with exit 0 before"
expect 2 "a .vti piece covering half its WholeExtent" "2048 points of its WholeExtent without data" -- "${limit[@]}" "$tool" render --volume gen/half-piece.vti "${small[@]}" --out x.png
expect 2 "base64 appended data cut in half" "truncated" -- "${limit[@]}" "$tool" render --volume gen/base64-cut.vti "${small[@]}" --out x.png
expect 0 "the same base64 appended data whole" -- "${limit[@]}" "$tool" render --volume gen/ramp-base64.vti "${small[@]}" --out b64.png
expect 0 "the same volume raw-appended" -- "${limit[@]}" "$tool" render --volume gen/ramp.vti "${small[@]}" --out raw.png
rmse_at_most b64.png raw.png 0 "base64 and raw appended data draw the same"
expect 2 "a DICOM series of two sizes, headers past 4 MiB (checks skipped)" "mixes image sizes" -- "${limit[@]}" "$tool" render --volume gen/dicom-bigheader "${small[@]}" --out x.png
expect 0 "a DICOM series with 5 MiB headers, one size" -- "${limit[@]}" "$tool" render --volume gen/dicom-bigheader-good "${small[@]}" --out dicom.png
not_flat dicom.png "the DICOM series of large headers"
expect 2 "OBJ 'v nan nan nan' (was read as 0,0,0)" "not a finite number" -- "${limit[@]}" "$tool" "${box[@]}" --mesh gen/nan.obj --out x.png
expect 2 "NRRD data file: LIST naming missing files" "names 2 files for 16 slices" -- "${limit[@]}" "$tool" render --volume gen/list.nhdr "${small[@]}" --out x.png
# A LIST of one file a slice, as VTK reads it, draws the volume of the single data file.
{ grep -v '^data file' seeds/volume.nhdr | grep -v '^$'
  printf 'data file: LIST\n'
  for k in $(seq 0 15); do
    dd if=seeds/volume-nhdr.raw of=seeds/slice$k.raw bs=256 skip=$k count=1 status=none
    echo "slice$k.raw"
  done; } > seeds/list.nhdr
expect 0 "a NRRD LIST of 16 slice files" -- "${limit[@]}" "$tool" render --volume seeds/list.nhdr "${small[@]}" --out list.png
expect 0 "the same volume in one data file" -- "${limit[@]}" "$tool" render --volume seeds/volume.nhdr "${small[@]}" --out single.png
rmse_at_most list.png single.png 0 "a LIST draws the single file's volume"
head -c 100 seeds/slice9.raw > seeds/slice9.part && mv seeds/slice9.part seeds/slice9.raw
expect 2 "a NRRD LIST with a short slice file" "slice9.raw' holds 100 bytes" -- "${limit[@]}" "$tool" render --volume seeds/list.nhdr "${small[@]}" --out x.png
sed 's/^data file: .*/data file: slice%d%n%s.raw 0 15 1/' seeds/volume.nhdr > seeds/pattern.nhdr
expect 2 "a NRRD data file pattern VTK would give sprintf" "one %d" -- "${limit[@]}" "$tool" render --volume seeds/pattern.nhdr "${small[@]}" --out x.png
expect 2 "an all-constant volume, default transfer function (blank)" "constant" -- "${limit[@]}" "$tool" render --volume gen/constant.vti "${small[@]}" --out x.png
expect 0 "the constant volume with a transfer function" -- "${limit[@]}" "$tool" render --volume gen/constant.vti "${small[@]}" --tf gen/tf-grey.json --out constant.png
not_flat constant.png "the constant volume's uniform fog"
expect 0 "transfer-function nodes at -+1.7e308 (was black)" -- "${limit[@]}" "$tool" "${volume[@]}" --tf gen/tf-overflow.json --out overflow.png
expect 0 "the same grey over a range a double spans" -- "${limit[@]}" "$tool" "${volume[@]}" --tf gen/tf-grey.json --out grey.png
rmse_at_most overflow.png grey.png 0.002 "nodes at -+1.7e308 draw the grey they interpolate"
expect 2 "--window 5e-324 (whole volume opaque)" "narrower than the smallest" -- "${limit[@]}" "$tool" "${volume[@]}" --tf CT-Bone --window 5e-324 --level 100 --out x.png
expect 0 "--window at its minimum" -- "${limit[@]}" "$tool" "${volume[@]}" --tf CT-Bone --window 1e-4 --level 100 --out x.png
expect 2 "camera view angle 1e-300" "\"view_angle\" must be in [0.0001, 179]" -- "${limit[@]}" "$tool" "${volume[@]}" --camera gen/camera-tiny-angle.json --out x.png
expect 2 "a camera 1e15 away framing the volume" "\"view_angle\" must be in" -- "${limit[@]}" "$tool" "${volume[@]}" --camera gen/camera-far.json --out x.png
expect 2 "a camera looking away from the volume" "sees nothing of the scene" -- "${limit[@]}" "$tool" "${volume[@]}" --camera gen/camera-away.json --out x.png

echo "== User data lost before"
cp seeds/volume-raw.vti victim.vti
expect_kept 2 "--out naming the input volume (replaced by a PNG)" "is the input --volume" -- "${limit[@]}" "$tool" render --volume victim.vti "${small[@]}" --out victim.vti
cmp -s victim.vti seeds/volume-raw.vti && echo "ok: the volume is intact" || fail "the input volume was changed"
cp seeds/volume-raw.vti victim.vti
expect_kept 2 "--out naming the input through another path" "is the input --volume" -- "${limit[@]}" "$tool" render --volume victim.vti "${small[@]}" --out ./../"$(basename "$PWD")"/victim.vti
cmp -s victim.vti seeds/volume-raw.vti || fail "the input volume was changed"
expect_kept 2 "--out naming a .mhd's detached data file" "is the input --volume" -- "${limit[@]}" "$tool" render --volume seeds/volume.mhd "${small[@]}" --out seeds/volume.raw
cp gen/tf-grey.json victim.json
expect_kept 2 "--json naming the --tf file" "is the input --tf" -- "${limit[@]}" "$tool" "${volume[@]}" --tf victim.json --out x.png --json victim.json
cmp -s victim.json gen/tf-grey.json && echo "ok: the transfer function is intact" || fail "the --tf file was changed"
expect 2 "--out /dev/null (as root: replaced by a file)" "not a regular file" -- "${limit[@]}" "$tool" "${box[@]}" --out /dev/null
[ -c /dev/null ] && echo "ok: /dev/null is still a character device" || fail "/dev/null was replaced"
rm -f pipe.png && mkfifo pipe.png
expect 2 "--out naming a named pipe" "not a regular file" -- "${limit[@]}" "$tool" "${box[@]}" --out pipe.png
[ -p pipe.png ] && echo "ok: the pipe is still a pipe" || fail "the pipe was replaced"
echo "mine" > same.txt
expect_kept 2 "--out X --json X (X held JSON afterwards)" "are the same file" -- "${limit[@]}" "$tool" "${box[@]}" --out same.txt --json same.txt
[ "$(cat same.txt)" = "mine" ] && echo "ok: X is untouched" || fail "X was written: $(head -c 40 same.txt)"
ln -sf same.txt link.txt
expect_kept 2 "--out through a link to --json's file" "are the same file" -- "${limit[@]}" "$tool" "${box[@]}" --out link.txt --json same.txt
"${limit[@]}" "$tool" "${box[@]}" --out - > stdout.png 2> stdout.txt
[ $? -eq 0 ] && [ "$(head -c 4 stdout.png | tail -c 3)" = "PNG" ] && echo "ok: --out - writes the PNG to standard output" ||
  fail "--out -: $(cat stdout.txt)"
# Not through expect, which removes what --out names first.
"${limit[@]}" "$tool" "${box[@]}" --out - --json /dev/stdout > stdout.png 2> stdout.txt
[ $? -eq 2 ] && grep -q "are the same file" stdout.txt && [ ! -s stdout.png ] &&
  echo "ok: --out - --json /dev/stdout: $(cat stdout.txt)" || fail "--out - --json /dev/stdout: $(cat stdout.txt)"

echo "== Refused for the wrong reason, or refused when right, before"
expect 0 "a closed cylinder with 20,000-corner caps as --bound (was: not closed)" -- "${limit[@]}" "$tool" "${volume[@]}" --bound gen/cylinder.vtk --out cylinder.png
expect 0 "the same cylinder with 256-corner caps" -- "${limit[@]}" "$tool" "${volume[@]}" --bound gen/cylinder-256.vtk --out cylinder-256.png
rmse_at_most cylinder.png cylinder-256.png 0.01 "20,000 and 256 corners bound the volume alike"
rmse_at_least cylinder.png raw.png 0.01 "the cylinder bounds the volume (it differs from the unbounded picture)"
expect 0 "the 20,000-corner cylinder as a --mesh" -- "${limit[@]}" "$tool" "${box[@]}" --mesh gen/cylinder.vtk --out x.png
expect 2 "a cube at +-1e300 (was: all faces degenerate)" "at most 1e+18" -- "${limit[@]}" "$tool" "${box[@]}" --bound gen/cube-1e300.obj --out x.png
expect 2 "--mesh-transform scaling by 1e308 (the mesh vanished)" "placed by --mesh-transform" -- "${limit[@]}" "$tool" "${box[@]}" --mesh gen/cube.obj --mesh-transform 0,0,0,1e308 --out x.png
expect 2 "camera \"view_angle\": \"5\" (ignored)" "must be a number of degrees" -- "${limit[@]}" "$tool" "${volume[@]}" --camera gen/camera-string.json --out x.png
long=$(printf 'a%.0s' $(seq 250)).png
expect 0 "a 254-character output name (refused naming a temporary file)" -- "${limit[@]}" "$tool" "${box[@]}" --out "$long"
[ -f "$long" ] && echo "ok: the long name was written" || fail "no file at the long name"
rm -f "$long"
expect 2 "a 256-character output name" "longer than the 255 characters" -- "${limit[@]}" "$tool" "${box[@]}" --out "$(printf 'a%.0s' $(seq 252)).png"
newline=$(printf 'no\nsuch.vti')
expect 2 "a newline in a file name (two lines before)" "no\\nsuch.vti" -- "${limit[@]}" "$tool" render --volume "$newline" "${small[@]}" --out x.png
rm -f big.png
( ulimit -f 1; "${limit[@]}" "$tool" "${box[@]}" --size 256x256 --out big.png > /dev/null 2> ulimit.txt; echo $? > ulimit.rc )
[ "$(cat ulimit.rc)" = 2 ] && grep -q "^deepshadow: cannot write big.png: File too large$" ulimit.txt && [ ! -e big.png ] &&
  echo "ok: a file-size limit: exit 2, one line, no file ($(cat ulimit.txt))" ||
  fail "a file-size limit: exit $(cat ulimit.rc): $(cat ulimit.txt)"
leftovers=$(ls -a | grep -c '^\.deepshadow-')
[ "$leftovers" -eq 0 ] && echo "ok: no temporary file left behind" || fail "$leftovers temporary files left behind"

echo "$failures failure(s)"
[ "$failures" -eq 0 ]
