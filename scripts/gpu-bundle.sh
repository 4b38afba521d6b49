#!/usr/bin/env bash
# Packs build/ for a Linux machine with a GPU but without Debian's VTK (a GPU host of another
# distribution): the executables, our libraries and test files, and every shared library they
# load from this machine except the C runtime and the GL dispatch libraries (the host's own
# driver provides those). Writes OUT (default out/gpu-bundle.tar.xz); on the other machine,
# from a checkout of the same commit at any path:
#   tar -xJf gpu-bundle.tar.xz -C "$PWD" && source .gpu-env.sh && scripts/gpu-check.sh
# .gpu-env.sh puts the libraries on LD_LIBRARY_PATH and, where the checkout is not at this
# machine's path, links that path to it (ctest's files name absolute paths).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
out=${1:-$root/out/gpu-bundle.tar.xz}
cd "$root"
[ -x build/bin/deepshadow ] || { echo "gpu-bundle: build first (scripts/setup.sh)" >&2; exit 2; }
stage=$(mktemp -d)
trap 'rm -rf "$stage"' EXIT
mkdir -p "$stage/.gpu-libs"
# The C runtime and GL dispatch stay the host's: newer there, and its driver hooks into them.
host='^(libc|libm|libdl|libpthread|librt|libresolv|ld-linux-x86-64|libstdc\+\+|libgcc_s|libGL|libEGL|libGLX|libGLdispatch|libOpenGL|libGLESv2)\.'
mapfile -t objects < <(find build/bin build/lib -type f \( -perm -u+x -o -name '*.so*' \))
ldd "${objects[@]}" 2>/dev/null | awk '/=> \// { print $3 }' | sort -u | while read -r lib; do
  case $lib in "$root"/*) continue ;; esac
  name=$(basename "$lib")
  [[ $name =~ $host ]] && continue
  cp -L "$lib" "$stage/.gpu-libs/$name"
done
cat > "$stage/.gpu-env.sh" <<EOF
# Made by scripts/gpu-bundle.sh on $(hostname) at $(git rev-parse --short HEAD).
here=\$(pwd)
export LD_LIBRARY_PATH=\$here/.gpu-libs:\$here/build/lib\${LD_LIBRARY_PATH:+:\$LD_LIBRARY_PATH}
if [ "\$here" != "$root" ] && [ ! -e "$root" ]; then mkdir -p "$(dirname "$root")" && ln -s "\$here" "$root"; fi
EOF
tar -C "$root" -cf "$stage/build.tar" --exclude='*.o' --exclude='*.a' --exclude='.ninja*' \
  --exclude='CMakeFiles/*.dir' build
tar -C "$stage" -rf "$stage/build.tar" .gpu-libs .gpu-env.sh
mkdir -p "$(dirname "$out")"
xz -T0 -6 -c "$stage/build.tar" > "$out"
echo "gpu-bundle: $out ($(du -h "$out" | cut -f1); $(ls "$stage/.gpu-libs" | wc -l) libraries)"
