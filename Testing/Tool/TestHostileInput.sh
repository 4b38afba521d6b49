#!/usr/bin/env bash
# Hostile input to the deepshadow tool (issue 17): each gives exit 0 with a right picture, or
# exit 2 with one line "deepshadow: ..." saying what is wrong and no output file left
# behind; never a signal, a hang, std::bad_alloc or a blank picture with exit 0. The inputs
# are the seed files of deepshadow-testkit, broken on purpose.
# Usage: TestHostileInput.sh path/to/deepshadow path/to/deepshadow-testkit work-directory
set -u
tool=$1
kit=$2
work=$3
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
mkdir -p "$work"
cd "$work" || exit 1
source "$here/expect.sh"
rm -rf seeds && mkdir seeds && "$kit" seeds seeds > /dev/null || { echo "FAILED: seeds"; exit 1; }
small=(--size 32x32 --frames 1)
box=(render --scene box --scale 0.1 "${small[@]}")

# Byte offset of the first data byte of a .vti's raw appended data (after '_' and its
# 4-byte UInt32 size).
appended_data() {
  local tag
  tag=$(grep -a -b -o '<AppendedData encoding="raw">' "$1" | cut -d: -f1)
  echo $((tag + $(tail -c +$((tag + 1)) "$1" | grep -a -b -o '_' | head -1 | cut -d: -f1) + 1 + 4))
}
# overwrite FILE OFFSET BYTES (printf escapes)
overwrite() {
  printf "$3" | dd of="$1" bs=1 seek="$2" conv=notrunc status=none
}

echo "== Meshes: crashes before (SIGSEGV, free() of a bad pointer)"
head -c 250 seeds/mesh.ply > truncated.ply
expect 2 "a truncated binary PLY as --mesh" "truncated" -- "$tool" "${box[@]}" --mesh truncated.ply --out x.png
expect 2 "a truncated binary PLY as --bound" "truncated" -- "$tool" "${box[@]}" --bound truncated.ply --out x.png
sed 's/^element vertex 50$/element vertex 100000000/' seeds/mesh.ply > huge.ply
expect 2 "a PLY declaring 1e8 vertices" "100000000 vertex" -- "$tool" "${box[@]}" --mesh huge.ply --out x.png
sed '$ s/.*/3 0 1 99/' seeds/mesh-ascii.ply > past.ply
expect 2 "a PLY --mesh with a face past its points" "vertex 99 of 50" -- "$tool" "${box[@]}" --mesh past.ply --out x.png
{ cat seeds/mesh.obj; echo "f 1 2 999"; } > past.obj
expect 2 "an OBJ --mesh with a face past its points" "out of range" -- "$tool" "${box[@]}" --mesh past.obj --out x.png
expect 2 "the same OBJ as --bound" "out of range" -- "$tool" "${box[@]}" --bound past.obj --out x.png
{ cat seeds/mesh.obj; echo "f 1//7 2//7 3//7"; } > normal.obj
expect 2 "an OBJ face naming a normal it lacks" "normal" -- "$tool" "${box[@]}" --mesh normal.obj --out x.png
sed 's/^element face 96$/element face 96\nelement face 96/' seeds/mesh.ply > twice.ply
expect 2 "a PLY declaring an element twice" "twice" -- "$tool" "${box[@]}" --mesh twice.ply --out x.png
# An element without properties: VTK's reader frees a pointer it never set (found by a
# mutation run: "free(): invalid pointer"); refused before it.
sed 's/^end_header$/element more 1\nend_header/' seeds/mesh.ply > bare.ply
expect 2 "a PLY element without properties" "element more has no properties" -- "$tool" "${box[@]}" --mesh bare.ply --out x.png
sed 's/^property float y$/property float why/' seeds/mesh.ply > noy.ply
expect 2 "a PLY without y" "x, y and z" -- "$tool" "${box[@]}" --mesh noy.ply --out x.png
head -c $(($(wc -c < seeds/mesh-ascii.ply) - 1)) seeds/mesh-ascii.ply > cut.ply
expect 2 "an ASCII PLY cut inside its last line" "truncated" -- "$tool" "${box[@]}" --mesh cut.ply --out x.png
head -c 150 seeds/mesh.stl > truncated.stl
expect 2 "a truncated binary STL (VTK kept what was there)" "truncated" -- "$tool" "${box[@]}" --mesh truncated.stl --out x.png
sed '1 s/.*/# vtk DataFile Version 5.x/' seeds/mesh.vtk > version.vtk
expect 2 "a legacy VTK file with a garbled version" "version" -- "$tool" "${box[@]}" --mesh version.vtk --out x.png
sed 's/NumberOfVerts="0"/NumberOfVerts="9223372036854775807"/' seeds/mesh.vtp > counts.vtp
expect 2 "a VTP declaring 2^63 vertices" "NumberOfVerts" -- "$tool" "${box[@]}" --mesh counts.vtp --out x.png

echo "== The frame: OSMesa died at about 15 GB"
expect 2 "--size 16384x16384" "would take 17179869184 bytes" -- "$tool" render --scene box --size 16384x16384 --memory-budget 8G --out x.png
expect 2 "--size beyond --memory-budget" "memory budget of 1048576 bytes" -- "$tool" "${box[@]}" --size 256x256 --memory-budget 1M --out x.png
expect 2 "a 16384^2 deep shadow map" "shadow structures" -- "$tool" "${box[@]}" --technique dsm --shadow-map-size 16384 --memory-budget 8G --out x.png
expect 2 "an rmsm atlas of 16384^2" "shadow structures" -- "$tool" "${box[@]}" --technique rmsm --atlas-size 16384 --memory-budget 512M --out x.png

echo "== Volumes: exit 0 with a wrong or blank picture before"
head -c 2000 seeds/volume-raw.vti > truncated.vti
expect 2 "a truncated .vti" "truncated" -- "$tool" render --volume truncated.vti "${small[@]}" --out x.png
sed 's/^sizes: 16 16 16$/sizes: 16 16/' seeds/volume.nrrd > twosizes.nrrd
expect 2 "a NRRD of dimension 3 with two sizes" "does not have dimension: 3 sizes" -- "$tool" render --volume twosizes.nrrd "${small[@]}" --out x.png
# --verbose means more output, never a different exit: the same code, the same last line.
"$tool" render --volume twosizes.nrrd "${small[@]}" --out x.png --verbose > /dev/null 2> verbose.txt
[ $? -eq 2 ] && [ "$(tail -1 verbose.txt)" = "$(cat err.txt)" ] && echo "ok: --verbose: exit 2 and the same line" ||
  fail "--verbose changed the outcome: $(tail -1 verbose.txt)"
sed 's/^spacings: 2 2 2.5$/spacings: nan nan nan/' seeds/volume.nrrd > nan.nrrd
expect 2 "NRRD spacings: nan" "spacing" -- "$tool" render --volume nan.nrrd "${small[@]}" --out x.png
cp seeds/volume.mha corrupt.mha
overwrite corrupt.mha 360 '\x5a\x5a\x5a\x5a\x5a\x5a\x5a\x5a\x5a\x5a\x5a\x5a\x5a\x5a\x5a\x5a'
expect 2 "a corrupt compressed .mha" "Uncompress failed" -- "$tool" render --volume corrupt.mha "${small[@]}" --out x.png
sed 's/^encoding: raw$/encoding: ascii/' seeds/volume.nrrd > ascii.nrrd
expect 2 "an ASCII NRRD (VTK 9.1 misreads it)" "ASCII" -- "$tool" render --volume ascii.nrrd "${small[@]}" --out x.png
sed 's/^sizes: 16 16 16$/sizes:16 16 16/' seeds/volume.nrrd > nospace.nrrd
expect 2 "a NRRD field without its space (VTK read no size and crashed)" "sizes" -- "$tool" render --volume nospace.nrrd "${small[@]}" --out x.png
printf 'NRRD0004\ntype: uchar\ndimension: 3\nsizes: 16 16 16\nencoding: raw\ndata file: volume-nhdr.raw' > seeds/cut.nhdr
expect 2 "a NRRD header cut inside a line (VTK waited forever)" "inside a line" -- "$tool" render --volume seeds/cut.nhdr "${small[@]}" --out x.png
# +Inf samples: an error, or with --replace-nonfinite the data's largest finite value, with
# the default transfer function over the finite range (it spanned infinity: blank).
cp seeds/volume-float.vti inf.vti
overwrite inf.vti $(($(appended_data inf.vti) + 4 * 100)) '\x00\x00\x80\x7f'
expect 2 "+Inf samples" "+Inf" -- "$tool" render --volume inf.vti "${small[@]}" --out x.png
expect 0 "+Inf samples, --replace-nonfinite" -- "$tool" render --volume inf.vti "${small[@]}" --replace-nonfinite --out inf.png
expect 0 "the same without the +Inf" -- "$tool" render --volume seeds/volume-float.vti "${small[@]}" --out finite.png
not_flat inf.png "+Inf replaced"
rmse_at_most inf.png finite.png 0.02 "+Inf replaced looks like the finite volume"
for s in 1e-30 1e30; do
  sed "s/Spacing=\"2 2 2.5\"/Spacing=\"$s $s $s\"/" seeds/volume-raw.vti > spacing$s.vti
  expect 2 "spacing $s (blank before)" "voxel edge" -- "$tool" render --volume spacing$s.vti "${small[@]}" --out x.png
done
expect 2 "spacing 1e-30, CPU reference (blank before: VTK's camera cannot frame it)" "voxel edge" -- \
  "$tool" reference --volume spacing1e-30.vti --size 32x32 --out x.png
# A volume a millionth the size (spacing and origin scaled) looks the same; only where float
# positions cannot resolve its voxels is it refused.
sed 's/Spacing="2 2 2.5"/Spacing="2e-6 2e-6 2.5e-6"/; s/Origin="-15 -15 -18.75"/Origin="-15e-6 -15e-6 -18.75e-6"/' \
  seeds/volume-raw.vti > micro.vti
expect 0 "a volume a millionth the size" -- "$tool" render --volume micro.vti "${small[@]}" --out micro.png
expect 0 "the same at its size" -- "$tool" render --volume seeds/volume-raw.vti "${small[@]}" --out unit.png
rmse_at_most micro.png unit.png 0.004 "a millionth the size looks the same"
sed 's/Spacing="2 2 2.5"/Spacing="2e-6 2e-6 2.5e-6"/' seeds/volume-raw.vti > far.vti
expect 2 "the same 15 units from the origin (1e6 times its size)" "from the origin" -- "$tool" render --volume far.vti "${small[@]}" --out x.png

echo "== Lights: black or vanished volume before"
expect 0 "--light-dir 1,0,1" -- "$tool" "${box[@]}" --technique dsm --light-dir 1,0,1 --out light.png
expect 0 "--light-dir 1e308,0,1e308" -- "$tool" "${box[@]}" --technique dsm --light-dir 1e308,0,1e308 --out far.png
rmse_at_most far.png light.png 0 "--light-dir 1e308,0,1e308 lights as 1,0,1"
expect 2 "--light-pos 1e300,0,0" "1e18" -- "$tool" "${box[@]}" --light-pos 1e300,0,0 --out x.png
# Sample distances beyond what a ray may take (65535 samples across the volume): refused at
# once, naming the smallest that fits (the GPU marched 21 s and drew a cut-off picture; the
# CPU reference ran for hours).
expect 2 "--sample-distance 1e-9" "use at least" -- "$tool" "${box[@]}" --sample-distance 1e-9 --out x.png
expect 2 "reference --sample-distance 1e-6" "use at least" -- timeout 60 "$tool" reference --scene box --size 32x32 --sample-distance 1e-6 --out x.png
expect 2 "--light pos:1e300,0,0" "1e18" -- "$tool" "${box[@]}" --light pos:1e300,0,0 --out x.png

echo "== Misleading exits before"
sed 's/^ElementType = MET_UCHAR$/ElementType = MET_BANANA/' seeds/volume.mhd > banana-type.mhd
expect 2 "an unknown MetaImage element type (was: zero extent along x)" "MET_BANANA" -- "$tool" render --volume banana-type.mhd "${small[@]}" --out x.png
sed 's/^NDims = 3$/NDims = banana/' seeds/volume.mhd > banana-dims.mhd
expect 2 "NDims = banana" "NDims = banana" -- "$tool" render --volume banana-dims.mhd "${small[@]}" --out x.png
sed 's/0 15 0 15 0 15/0 99999 0 99999 0 99999/g' seeds/volume-raw.vti > huge.vti
sed 's/^DimSize = 16 16 16$/DimSize = 100000 100000 100000/' seeds/volume.mhd > huge.mhd
sed 's/^sizes: 16 16 16$/sizes: 100000 100000 100000/' seeds/volume.nrrd > huge.nrrd
for f in huge.vti huge.mhd huge.nrrd; do
  expect 2 "$f declaring 100000^3 (was: std::bad_alloc)" "would take 1000000000000000 bytes" -- "$tool" render --volume $f "${small[@]}" --out x.png
done
sed '/<Piece/ s/Extent="0 15 0 15 0 15"/Extent="-2147483648 15 0 15 0 15"/' seeds/volume-base64.vti > piece.vti
expect 2 "a .vti piece outside its whole extent" "WholeExtent" -- "$tool" render --volume piece.vti "${small[@]}" --out x.png
rm -f x.png
expect 2 "--json /nonexistent/x.json (the PNG was left behind)" "no such directory" -- "$tool" "${box[@]}" --json /nonexistent/x.json --out x.png
[ -e x.png ] && fail "--json /nonexistent: x.png was written"
expect 2 "--out into a missing directory" "no such directory" -- "$tool" "${box[@]}" --out /nonexistent/x.png

echo "== CSG"
nested=$(printf 'union(A,%.0s' $(seq 100))B$(printf ')%.0s' $(seq 100))
expect 2 "a CSG expression nested 100 deep" "nested deeper than 64" -- "$tool" "${box[@]}" --bound seeds/bound.obj --bound seeds/mesh.obj --csg "$nested" --out x.png

echo "$failures failure(s)"
[ "$failures" -eq 0 ]
