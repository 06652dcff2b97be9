#!/usr/bin/env bash
# Add the GRFLOW package to your own LAMMPS source tree (4Feb2025 or
# 4Jul2026), then build that LAMMPS as usual with -D PKG_GRFLOW=on (CMake)
# or make yes-grflow (traditional make).  This writes into the tree given:
# src/GRFLOW, src/OPENMP/*grflow*, src/KOKKOS/*grflow* (the /kk variants of
# the pair style, its history fix, the fixes and the compute, built by CMake
# with -D PKG_KOKKOS=on), and one line in each of
# cmake/CMakeLists.txt and src/Makefile (cmake/GRFLOWAddToLAMMPS.cmake).
#   bash scripts/add-to-lammps.sh /path/to/lammps
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
tree=${1:?usage: add-to-lammps.sh /path/to/lammps}
exec cmake -D LAMMPS_TREE="$tree" -P "$top/cmake/GRFLOWAddToLAMMPS.cmake"
