#!/usr/bin/env bash
# Installs iga's dependencies (Debian 12 packages only), configures a Release build in ./build and builds it.
# Safe to run again: installed packages and an up-to-date build are skipped.
# Environment: IGA_BUILD_DIR (default <repo>/build), IGA_JOBS (default: number of cores).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${IGA_BUILD_DIR:-$root/build}"
jobs="${IGA_JOBS:-$(nproc)}"

packages=(
  # Ninja builds (and ccache, when a build is repeated, e.g. CI on a fresh clone) are what README "Build times"
  # measures.
  build-essential cmake ninja-build ccache
  libeigen3-dev libsuitesparse-dev libopenblas0-pthread libnlopt-cxx-dev libosd-dev libvtk9-dev
  libgtest-dev nlohmann-json3-dev libcli11-dev libmuparser-dev
  # GiNaC: the exact (symbolic) derivatives of expressions (fem/symbolic.cpp).
  libginac-dev
  python3-matplotlib libbenchmark-dev
  # The distributed solver (--solver petsc): PETSc 3.18 (with hypre and MUMPS), OpenMPI (mpirun), METIS, PT-Scotch
  # (the partition, through PETSc's MatPartitioning), and pkg-config, through which CMake finds PETSc.
  libpetsc-real-dev libopenmpi-dev openmpi-bin libmetis-dev libscotch-dev libptscotch-dev pkg-config
)
# ParaView, to look at the output: Debian's python3-paraview (pvpython) declares Conflicts: python3-vtk9, which
# libvtk9-dev depends on, so apt would remove it to install ours. The paraview GUI package only recommends
# python3-paraview and co-installs (checked with apt-cache show on Debian 12, ParaView 5.11.0). Stop before apt.
if [[ "$(dpkg-query -W -f='${Status}' python3-paraview 2>/dev/null || true)" == "install ok installed" ]]; then
  echo "setup: python3-paraview conflicts with python3-vtk9 (needed by libvtk9-dev): remove it" \
       "(apt-get remove python3-paraview); the paraview GUI co-installs" \
       "(apt-get install --no-install-recommends paraview)" >&2
  exit 1
fi
# shellcheck source=scripts/packages.sh
source "$root/scripts/packages.sh"
install_packages setup "${packages[@]}"

if [[ ! -f "$build/CMakeCache.txt" ]]; then
  cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release
fi
cmake --build "$build" -j "$jobs"
