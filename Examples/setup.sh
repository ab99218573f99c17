#!/usr/bin/env bash
# Installs what is missing (Debian 12, as root or with sudo) and builds the project into build/.
#   Examples/setup.sh [extra cmake arguments]
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"

# ParaView 5.11's SDK; paraview-dev lacks the Qt and third-party -dev packages its CMake
# configuration looks for, so they are listed too.
packages=(
  build-essential cmake xvfb xauth mpi-default-bin
  paraview-dev python3-paraview libeigen3-dev
  qtbase5-dev qttools5-dev libqt5svg5-dev qtxmlpatterns5-dev-tools libqt5x11extras5-dev
  libqt5opengl5-dev
  libhdf5-dev libutfcpp-dev libtiff-dev libtheora-dev libpng-dev libnetcdf-dev libxml2-dev
  liblzma-dev liblz4-dev libjpeg-dev libglew-dev libgl2ps-dev libgdal-dev libfreetype-dev
  libavcodec-dev libavformat-dev libavutil-dev libswscale-dev libexpat1-dev libboost-dev
  zlib1g-dev libx11-dev libgl-dev libxt-dev libopenmpi-dev python3-mpi4py python3-numpy
  libdouble-conversion-dev
)
missing=()
for package in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" ||
    missing+=("$package")
done
if ((${#missing[@]})); then
  echo "Installing: ${missing[*]}"
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo="sudo"
  $sudo apt-get update -q
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -q --no-install-recommends "${missing[@]}"
fi

cmake -S "$here" -B "$here/build" -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTING=ON "$@"
cmake --build "$here/build" -j "$(nproc)"
