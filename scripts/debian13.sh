#!/usr/bin/env bash
# The second platform: builds vtkDeepShadow and runs its tests on Debian 13 (VTK 9.3, CGAL 6,
# GCC 14, Python 3.13) in a Debian 13 root made with debootstrap from the host's Debian
# package mirror, reused when it exists. The checkout (tracked and untracked files, not the
# ignored ones) is copied in and built there by scripts/setup.sh, as on Debian 12.
# Usage (as root): scripts/debian13.sh [--build-only] [ctest arguments...]
#   DEEPSHADOW_DEBIAN13_ROOT  where the root lives (default /var/tmp/deepshadow-debian13)
# Exit 77 (skipped, said on one line) when this machine cannot make or enter the root (no
# debootstrap download, no mount); otherwise setup's or ctest's status.
# Not yet built here: the ParaView plugin against ParaView 5.13 (Debian 13's paraview-dev
# removes libvtk9-dev, as on Debian 12: it needs setup-paraview.sh's private prefix).
set -euo pipefail
checkout=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
target=${DEEPSHADOW_DEBIAN13_ROOT:-/var/tmp/deepshadow-debian13}
build_only=
if [ "${1:-}" = "--build-only" ]; then build_only=1; shift; fi

skip() { echo "debian13: SKIPPED, $1" >&2; exit 77; }
[ "$(id -u)" -eq 0 ] || { echo "debian13: run as root (debootstrap and chroot)" >&2; exit 2; }
if ! command -v debootstrap >/dev/null; then
  DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends debootstrap ||
    skip "debootstrap cannot be installed"
fi

# The host's mirror: the first Debian archive its apt sources name.
mirror=$({ grep -rhoE '^(URIs:|deb) *\S+' /etc/apt/sources.list /etc/apt/sources.list.d/ 2>/dev/null || true; } |
  awk '{print $NF}' | grep -E '/debian/?$' | head -n 1 || true)
[ -n "$mirror" ] || skip "no Debian mirror in /etc/apt/sources*"
if [ ! -x "$target/usr/bin/apt-get" ]; then
  echo "debian13: making a Debian 13 root in $target"
  debootstrap --variant=minbase trixie "$target" "$mirror" || skip "debootstrap could not make the root"
fi

mounted=()
cleanup() {
  for point in "${mounted[@]}"; do umount "$point" 2>/dev/null || true; done
}
trap cleanup EXIT
for point in proc dev; do
  if ! mountpoint -q "$target/$point"; then
    if [ "$point" = proc ]; then
      mount -t proc proc "$target/proc" || skip "cannot mount /proc in the root"
    else
      mount --bind /dev "$target/dev" || skip "cannot bind /dev into the root"
    fi
    mounted+=("$target/$point")
  fi
done
cp /etc/resolv.conf "$target/etc/resolv.conf"

# The checkout as git sees it (its build directories stay out), over the previous copy so
# that its build directory is reused.
source="$target/src/deepshadow"
mkdir -p "$source"
(cd "$checkout" && git ls-files -z --cached --others --exclude-standard |
  tar --null -cf - -T -) | tar -xf - -C "$source"

chroot "$target" bash -c "cd /src/deepshadow && scripts/setup.sh"
[ -n "$build_only" ] && exit 0
chroot "$target" bash -c 'cd /src/deepshadow/build && ctest --output-on-failure --timeout 900 -j 2 "$@"' ctest "$@"
