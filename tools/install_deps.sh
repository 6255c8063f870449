#!/usr/bin/env bash
# Installs what sphjet needs to build, test and plot, from Debian's packages (clang and
# libclang-rt-dev: the fuzz smoke of the test set, tests/fuzz/README.md).
# Run as root (or with sudo available) when a package is missing; with every package
# installed it changes nothing and needs neither. Safe to run again.
set -euo pipefail
packages=(
  g++ gfortran cmake make git ca-certificates
  libeigen3-dev libhdf5-dev hdf5-tools libcli11-dev libtomlplusplus-dev libfmt-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  clang libclang-rt-dev
  python3 python3-numpy python3-matplotlib python3-h5py
)
installed=$(dpkg-query -W -f='${db:Status-Status}\n' "${packages[@]}" 2>/dev/null | grep -cx installed || true)
if [ "$installed" -eq ${#packages[@]} ]; then
  echo "install_deps.sh: all ${#packages[@]} packages are installed"
  exit 0
fi
SUDO=""
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null 2>&1 || { echo "install_deps.sh: run as root or install sudo" >&2; exit 1; }
  SUDO="sudo"
fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update
$SUDO apt-get install -y --no-install-recommends "${packages[@]}"
