#!/usr/bin/env bash
# Test the drop-in package once, both ways a user builds LAMMPS: in two
# copies of a pristine LAMMPS tree (fetched as for the default build),
# scripts/add-to-lammps.sh, then
#   1. CMake:  -D PKG_GRFLOW=on -D PKG_OPENMP=on, target lmp
#   2. make:   make yes-grflow yes-openmp, make mpi (with -fopenmp)
# and with each lmp a short paper protocol (quick preset, 500 spheres,
# 20000 shear steps: every GRFLOW style) plain and with -sf omp, which must
# use granular/grflow/omp.  Two LAMMPS builds: 642 s on this 2-core
# machine (2026-11-24, LAMMPS 4Feb2025); not part of CI.
#   bash scripts/test-dropin.sh [WORK_DIR] [4Feb2025|4Jul2026]
# (WORK_DIR default /tmp/grflow-dropin, emptied first; needs about 2 GB.)
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
work=${1:-/tmp/grflow-dropin}
version=${2:-4Feb2025}
jobs=$(nproc)
cache=${GRFLOW_CACHE_DIR:-$HOME/.cache/grflow}
pristine=$(bash "$top/scripts/fetch-lammps-source.sh" "$cache" "$version")
rm -rf "$work" && mkdir -p "$work"
t0=$(date +%s)
stamp() { echo "[$(($(date +%s) - t0)) s] $*"; }

# the deck: the protocol with every GRFLOW style, in a few minutes
run_deck() { # lmp name [extra lmp args]
  local lmp=$1 name=$2
  shift 2
  local out=$work/run-$name
  "$lmp" -in "$top/inputs/cyclic_shear.lmp" -var inputs "$top/inputs" -var outdir "$out" \
    -var preset quick -var N 500 -var max_steps 20000 -log "$out.log" "$@" > "$out.screen" 2>&1 ||
    { tail -n 20 "$out.screen"; echo "FAIL: $name: lmp exited with an error"; exit 1; }
  grep -q "GRFLOW shear: done at step 20000" "$out/log.shear.lammps" ||
    { echo "FAIL: $name: the shear stage did not reach step 20000"; exit 1; }
  if [[ " $* " == *" -sf omp "* ]]; then
    grep -q "pair granular/grflow/omp, perpetual" "$out/log.shear.lammps" ||
      { echo "FAIL: $name: -sf omp did not select granular/grflow/omp"; exit 1; }
  fi
  stamp "ok: $name"
}

# 1. CMake
cp -a "$pristine" "$work/tree-cmake"
bash "$top/scripts/add-to-lammps.sh" "$work/tree-cmake" > /dev/null
cmake -S "$work/tree-cmake/cmake" -B "$work/build-cmake" -D PKG_GRFLOW=on -D PKG_OPENMP=on \
  -D BUILD_MPI=on -D BUILD_OMP=on > "$work/build-cmake.log" 2>&1 ||
  { tail -n 30 "$work/build-cmake.log"; echo "FAIL: cmake configure"; exit 1; }
cmake --build "$work/build-cmake" -j "$jobs" --target lmp >> "$work/build-cmake.log" 2>&1 ||
  { grep -m 20 -B2 -A5 "error" "$work/build-cmake.log"; echo "FAIL: cmake build"; exit 1; }
stamp "built $work/build-cmake/lmp"
run_deck "$work/build-cmake/lmp" cmake
run_deck "$work/build-cmake/lmp" cmake-omp -sf omp -pk omp 1

# 2. traditional make (yes-openmp after yes-grflow: OPENMP installs the
#    variants of the styles present)
cp -a "$pristine" "$work/tree-make"
bash "$top/scripts/add-to-lammps.sh" "$work/tree-make" > /dev/null
(cd "$work/tree-make/src" && make yes-grflow && make yes-openmp &&
   make -j "$jobs" mpi CCFLAGS="-g -O3 -fopenmp" LINKFLAGS="-g -O3 -fopenmp") \
  > "$work/build-make.log" 2>&1 ||
  { grep -m 20 -B2 -A5 "rror" "$work/build-make.log"; echo "FAIL: make"; exit 1; }
stamp "built $work/tree-make/src/lmp_mpi"
run_deck "$work/tree-make/src/lmp_mpi" make
run_deck "$work/tree-make/src/lmp_mpi" make-omp -sf omp -pk omp 1
stamp "drop-in package: both builds run every GRFLOW style (LAMMPS $version)"
