#!/usr/bin/env bash
# Renders every standard, bounded and hybrid scene with every shadow technique (and the
# cached variants) and prints one "sha256  scene technique" line per picture. A change
# that must not alter pictures (a restructuring) is shown bit-identical by comparing the
# lists before and after:
#   scripts/picture-hashes.sh build > before.txt   # on the old commit
#   scripts/picture-hashes.sh build --check before.txt   # on the new one; exit 1 on a change
# About 5 minutes on 2 cores (llvmpipe, 128x128, 2 frames each).
set -euo pipefail

build=${1:?usage: picture-hashes.sh BUILD_DIR [--check HASHES]}
check=
if [[ ${2:-} == --check ]]; then check=${3:?--check needs a file}; fi
tool="$build/bin/deepshadow"
[[ -x $tool ]] || { echo "picture-hashes: no $tool (build first)" >&2; exit 2; }

scenes=$("$tool" scenes | awk 'NF > 1 && $1 !~ /:$/ && $1 ~ /^[a-z0-9-]+$/ {print $1}')
techniques="none rays rays-opaque rays-color shadowmap dsm dsm-color dsm3 cssm
  rays-cached shadowmap-cached dsm-cached dsm3-cached cssm-cached
  shadowmap:pcf=poisson dsm:layers=2:epsilon=0.05 rays-opaque:threshold-on=opacity dsm-clustered dsm:chunk-nodes=4
  rmsm rmsm:pcf=poisson"

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
list="$work/hashes.txt"
for scene in $scenes; do
  for spec in $techniques; do
    name=${spec%%:*}
    args=(--technique "$name")
    # NAME:key=value -> --key value, as the tool's technique specs read.
    IFS=: read -r -a parts <<<"$spec"
    for kv in "${parts[@]:1}"; do args+=("--${kv%%=*}" "${kv#*=}"); done
    png="$work/$scene-${spec//[:=]/_}.png"
    "$tool" render --scene "$scene" "${args[@]}" --size 128x128 --frames 2 --out "$png" \
      >/dev/null
    echo "$(sha256sum "$png" | cut -c1-64)  $scene $spec" >>"$list"
  done
done

if [[ -n $check ]]; then
  if diff <(sort -k2 "$check") <(sort -k2 "$list"); then
    echo "picture-hashes: $(wc -l <"$list") pictures bit-identical to $check"
  else
    echo "picture-hashes: pictures differ from $check (lines above: < before, > now)" >&2
    exit 1
  fi
else
  cat "$list"
fi
