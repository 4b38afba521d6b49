#!/usr/bin/env bash
# The measured tables' pages (Documentation/Measured/) are as scripts/measured-tables.py wrote
# them (each page's digest matches its text; none is a quick test run), and the script itself
# works: a quick run with the built tool writes a page that passes the same check.
# Usage: MeasuredTables.sh SOURCE_DIR TOOL WORK_DIR
set -euo pipefail
source=$1 tool=$2 work=$3
script="$source/scripts/measured-tables.py"
shopt -s nullglob
pages=("$source"/Documentation/Measured/*.md)
(( ${#pages[@]} > 0 )) || { echo "no page in Documentation/Measured/"; exit 1; }
python3 "$script" --check "${pages[@]}"
echo "${#pages[@]} measured pages as written by the script"

rm -rf "$work" && mkdir -p "$work"
python3 "$script" vtk-mapper --quick --tool "$tool" --out "$work" 2>"$work/progress.txt"
page="$work/vtk-mapper.md"
python3 "$script" --allow-quick --check "$page"
grep -q '^| spheres | 32x32x32 | yes | composite |' "$page" || { cat "$page"; echo "no spheres row"; exit 1; }
grep -q '^Measured at commit .* cores' "$page" || { cat "$page"; echo "no stamp"; exit 1; }
# A quick page is not a measurement, and an edited one is refused.
if python3 "$script" --check "$page" >/dev/null; then echo "a quick page passed the check"; exit 1; fi
sed -i 's/^| spheres | 32x32x32 | yes | composite | [0-9.]*/| spheres | 32x32x32 | yes | composite | 1.0/' "$page"
if python3 "$script" --allow-quick --check "$page" >/dev/null; then echo "an edited page passed the check"; exit 1; fi
echo "quick run written and checked"

# The frame budget's page, under another name (a GPU's run): each row judged against its
# target (a CPU rasterizer's 1.2 for dsm-fixed, 1.3 for dsm) and counted below the table.
python3 "$script" frame-budget --quick --page frame-budget-gpu --tool "$tool" --out "$work" 2>>"$work/progress.txt"
page="$work/frame-budget-gpu.md"
python3 "$script" --allow-quick --check "$page"
grep -q 'measured-tables.py frame-budget --page frame-budget-gpu`' "$page" || { cat "$page"; echo "no command"; exit 1; }
grep -Eq '^\| box \| dsm \| - \| [0-9.]+ \| [0-9.]+ \| [0-9.]+ \| 1\.3 \| (yes|no) \|' "$page" ||
  { cat "$page"; echo "no dsm row with its target"; exit 1; }
grep -Eq '^\| box \| dsm-fixed:dsm-bits=64 \| 64 \| .* \| 1\.2 \| (yes|no) \|' "$page" ||
  { cat "$page"; echo "no dsm-fixed row with llvmpipe's target"; exit 1; }
# "within" says ratio <= target, and the count is of those rows.
awk -F' \\| ' '/^\| box \| dsm/ { ok = ($6 + 0 <= $7 + 0) ? "yes" : "no"; if (ok != $8) bad = 1; n += (ok == "yes") }
  /^Within the target:/ { if ($0 != "Within the target: " n " of 2 rows.") bad = 1; counted = 1 }
  END { exit bad || !counted }' "$page" || { cat "$page"; echo "a row misjudged, or miscounted"; exit 1; }
echo "frame budget page written and checked"
