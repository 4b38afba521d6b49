#!/usr/bin/env bash
# Brings Debian 12 to what the ParaView plugin needs, keeping libvtk9-dev (VTK 9.1) and
# python3-vtk9 installed: only what is missing, safe to re-run.
#   - Debian's ParaView 5.11 runtime (`paraview`, without its recommends: they pull in
#     python3-paraview, which conflicts with python3-vtk9, and apt would remove libvtk9-dev);
#   - ParaView's SDK (`paraview-dev`, `python3-paraview`) unpacked with dpkg -x into a private
#     prefix, $DEEPSHADOW_PVSDK (default /opt/deepshadow-pvsdk), never installed; the SDK's
#     CMake targets find their libraries relative to it, so the runtime's files are linked in;
#   - Xvfb and Open MPI (Debian's pvbatch needs an X server, even offscreen);
#   - Qt 5's development files: the plugin's Properties-panel editors build against
#     ParaView's pqComponents;
#   - $DEEPSHADOW_PVSDK/env.sh, to source before cmake, pvbatch or mpirun.
set -euo pipefail
sdk=${DEEPSHADOW_PVSDK:-/opt/deepshadow-pvsdk}
export DEBIAN_FRONTEND=noninteractive
sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"

packages=(paraview xvfb openmpi-bin libopenmpi-dev python3-dev python3-numpy
  imagemagick # import: the GUI test's screenshot of the whole screen
  qtbase5-dev qttools5-dev libqt5opengl5-dev) # the Properties panel's editors (pqComponents)
missing=()
for package in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" ||
    missing+=("$package")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup-paraview: installing ${missing[*]}"
  $sudo apt-get update -q
  # Refuse anything that would remove a package (python3-paraview against python3-vtk9).
  if apt-get install -s --no-install-recommends "${missing[@]}" | grep '^Remv'; then
    echo "setup-paraview: apt would remove the packages above; nothing installed" >&2
    exit 1
  fi
  $sudo apt-get install -y -q --no-install-recommends "${missing[@]}"
fi

version=$(dpkg-query -W -f='${Version}' paraview)
if [ "$(cat "$sdk/.version" 2>/dev/null)" != "$version" ]; then
  echo "setup-paraview: unpacking ParaView $version's SDK into $sdk"
  debs=$(mktemp -d)
  chmod 755 "$debs" # apt's download user must write there
  (cd "$debs" && apt-get download -q "paraview-dev=$version" "python3-paraview=$version")
  $sudo rm -rf "$sdk.new"
  $sudo mkdir -p "$sdk.new"
  for deb in "$debs"/*.deb; do $sudo dpkg -x "$deb" "$sdk.new"; done
  rm -rf "$debs"
  # The runtime's libraries and tools, where the SDK's imported targets expect them.
  dpkg -L paraview | while IFS= read -r file; do
    case "$file" in /usr/bin/* | /usr/lib/x86_64-linux-gnu/*) ;; *) continue ;; esac
    [ -d "$file" ] && [ ! -L "$file" ] && continue
    [ -e "$sdk.new$file" ] || [ -L "$sdk.new$file" ] && continue
    $sudo mkdir -p "$(dirname "$sdk.new$file")"
    $sudo ln -s "$file" "$sdk.new$file"
  done
  $sudo tee "$sdk.new/env.sh" >/dev/null <<ENV
# source $sdk/env.sh: cmake against ParaView's SDK, pvbatch, pvpython and mpirun.
# pvbatch must find the SDK's paraview and vtkmodules (VTK 9.2) before python3-vtk9's (9.1):
# a process that loads both crashes.
export PYTHONPATH="$sdk/usr/lib/python3/dist-packages"
export ParaView_DIR="$sdk/usr/lib/x86_64-linux-gnu/cmake/paraview-5.11"
export PATH="$sdk/usr/bin:\$PATH"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
ENV
  echo "$version" | $sudo tee "$sdk.new/.version" >/dev/null
  $sudo rm -rf "$sdk"
  $sudo mv "$sdk.new" "$sdk"
fi
echo "setup-paraview: ParaView $version, SDK in $sdk"
