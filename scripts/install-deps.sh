#!/usr/bin/env bash
# Installs the Debian 12 packages ParaFluid builds, tests and runs with.
# Idempotent: packages already present are skipped, so a second run costs one dpkg query.
set -euo pipefail

packages=(
  # build tools and the numerical core
  build-essential cmake ninja-build pkg-config libeigen3-dev libgtest-dev libbenchmark-dev
  # the formatter .clang-format is checked with (pinned: scripts/check-format.sh)
  clang-format-14
  # ParaView 5.11 itself, its Python and development files
  paraview paraview-dev python3-paraview
  # what find_package(ParaView) pulls in on Debian 12 (see ../shared/ARCHITECTURE.md)
  qtbase5-dev qttools5-dev libqt5svg5-dev qtxmlpatterns5-dev-tools libqt5x11extras5-dev libqt5opengl5-dev
  libutfcpp-dev libdouble-conversion-dev libtheora-dev libnetcdf-dev libgl2ps-dev libglew-dev
  libgdal-dev libfreetype-dev libavcodec-dev libavformat-dev libavutil-dev libswscale-dev
  libboost-dev liblz4-dev liblzma-dev libtiff-dev libexpat1-dev libjpeg-dev libpng-dev
  libxml2-dev libopenmpi-dev python3-dev python3-mpi4py libx11-dev libxt-dev libgl-dev
  # HDF5 in the flavour ParaView's VTK links (one libhdf5 per process) and Python access for tests
  libhdf5-openmpi-dev python3-h5py-mpi python3-numpy python3-matplotlib
  # a real producer of PySPH output files for the reader tests
  python3-pysph
  # rendering without a screen, MPI launcher
  xvfb xauth openmpi-bin
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

echo "install-deps: installing ${#missing[@]} packages: ${missing[*]}"
sudo_cmd=()
[ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
