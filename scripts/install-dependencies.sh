#!/usr/bin/env bash
# Installs the Debian 12 packages mcdda needs to build, test and run; skips what is present.
# Runs apt-get as root (directly, or through sudo when available).
set -euo pipefail

packages=(
  build-essential cmake ninja-build ccache pkg-config
  libeigen3-dev libcgal-dev libgmp-dev libmpfr-dev libsuitesparse-dev nlohmann-json3-dev
  # OpenBLAS for CHOLMOD: Debian's alternatives point libblas.so.3 and liblapack.so.3 to it
  # instead of the reference BLAS (about 3x faster factorisations, 1.7x less CPU per plastic
  # run, docs/benchmarks.md). The serial build: on a few cores the threaded one spun its threads
  # for little gain; users with many cores may install libopenblas0-pthread instead.
  libopenblas0-serial
  libgtest-dev libgmock-dev
  qt6-base-dev qt6-tools-dev qt6-l10n-tools qt6-tools-dev-tools libqt6opengl6-dev
  qt6-charts-dev qt6-svg-dev libgl1-mesa-dev
  # Qt's own German texts: Strg/Entf in shortcuts, Abbrechen on dialog buttons.
  qt6-translations-l10n
  libvtk9-dev
  # The Python module (pybind11, NumPy; tests with unittest) and DXF import (dxflib).
  python3-dev pybind11-dev python3-numpy libdxflib-dev
  # Parameter studies over MPI ranks (mpirun) and their tests (pkill).
  openmpi-bin libopenmpi-dev procps
  xvfb xauth mesa-utils libgl1-mesa-dri libglx-mesa0 fonts-dejavu-core
  # The Debian package (cpack -G DEB: dpkg-shlibdeps) and its test (desktop-file-validate,
  # appstreamcli).
  dpkg-dev desktop-file-utils appstream
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-dependencies: all ${#packages[@]} packages present"
  exit 0
fi

# ParaView's Python (python3-paraview, which Debian's paraview recommends) conflicts with
# python3-vtk9, which libvtk9-dev needs: apt-get -y would remove it unasked (README.md, "ParaView").
if [[ " ${missing[*]} " == *" libvtk9-dev "* ]] \
   && dpkg-query -W -f='${Status}' python3-paraview 2>/dev/null | grep -q "install ok installed"; then
  echo "install-dependencies: libvtk9-dev cannot be installed beside python3-paraview (ParaView's Python);" \
       "build in a container or install the .deb instead (README.md, \"ParaView\")" >&2
  exit 1
fi

if [ "$(id -u)" -eq 0 ]; then
  as_root=()
elif command -v sudo >/dev/null 2>&1; then
  as_root=(sudo)
else
  echo "install-dependencies: missing packages (${missing[*]}) and neither root nor sudo; install them and retry" >&2
  exit 1
fi
echo "install-dependencies: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
"${as_root[@]}" apt-get update -qq
"${as_root[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
