#!/usr/bin/env bash
# The class documentation builds with Doxygen without a warning (broken commands, unclosed
# comments, unknown tags in the headers' comments), and its pages name the public classes.
# Skipped (exit 77) where doxygen is not installed (scripts/setup.sh installs it).
# Usage: RunDoxygen.sh SOURCE_DIR OUTPUT_DIR
set -u
source_dir=$1
out=$2
command -v doxygen > /dev/null || { echo "skipped: no doxygen (scripts/setup.sh installs it)"; exit 77; }
rm -rf "$out" && mkdir -p "$out"
sed -e "s|@SOURCE_DIR@|$source_dir|g" -e "s|@OUTPUT_DIR@|$out|g" "$source_dir/Documentation/Doxyfile.in" > "$out/Doxyfile"
doxygen "$out/Doxyfile" > "$out/doxygen.txt" 2>&1 || { echo "FAILED: doxygen exited $?"; cat "$out/doxygen.txt"; exit 1; }
if [ -s "$out/warnings.txt" ]; then
  echo "FAILED: $(wc -l < "$out/warnings.txt") doxygen warning(s):"
  cat "$out/warnings.txt"
  exit 1
fi
for page in classvtkDeepShadowVolumeMapper.html classvtkDeepShadowTechnique.html classvtkDeepShadowRenderWindow.html; do
  [ -s "$out/html/$page" ] || { echo "FAILED: no $page"; exit 1; }
done
echo "doxygen $(doxygen --version): no warning, $(ls "$out/html" | grep -c '^class') class pages in $out/html"
