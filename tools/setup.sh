#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-2.0-or-later
# Installs the Debian packages asperity needs to build and test, if any are missing.
# Needs root (or sudo) only when something has to be installed.
set -euo pipefail

# The core library needs FFTW only; the command reads scene files (toml++) and measured
# surfaces (.x3p: libzip, pugixml) and draws its pictures with gnuplot (optional at run time);
# the Python package needs NumPy; distributed grids need MPI (Open MPI) and FFTW's MPI
# transforms, and their Python side mpi4py; the tests build the Debian packages (dpkg-dev),
# check the ABI (abigail-tools) and build the API reference (doxygen).
packages=(g++ gfortran cmake make pkg-config libfftw3-dev googletest libgtest-dev
          libtomlplusplus-dev libzip-dev libpugixml-dev gnuplot-nox
          libopenmpi-dev openmpi-bin libfftw3-mpi-dev python3-mpi4py
          python3-numpy dpkg-dev abigail-tools doxygen)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0

echo "installing: ${missing[*]}"
as_root=()
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "need root or sudo to install ${missing[*]}" >&2; exit 1; }
  as_root=(sudo)
fi
export DEBIAN_FRONTEND=noninteractive
"${as_root[@]}" apt-get update
"${as_root[@]}" apt-get install -y --no-install-recommends "${missing[@]}"
