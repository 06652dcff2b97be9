#!/usr/bin/env bash
# Build GRFLOW (LAMMPS with the package, the plugin, the tests), build
# LIGGGHTS 3.8.0 with GRFLOW (scripts/build-liggghts.sh, into
# build-liggghts/), and run the whole test suite with ctest, the LIGGGHTS
# tests included.  GRFLOW_TEST_LIGGGHTS=0 leaves LIGGGHTS out (no build,
# no LIGGGHTS tests).  Given a Kokkos 4.5.01 source (tarball or tree) in
# GRFLOW_KOKKOS_SOURCE, it also builds LAMMPS with GRFLOW and KOKKOS for
# CPU threads (scripts/setup-kokkos.sh openmp, into build-kokkos-openmp/,
# the LAMMPS KOKKOS styles of GRFLOW_KOKKOS_STYLES, default minimal) and
# runs the KOKKOS tests (pytest.kokkos); without it they are left out.
# ctest runs as many tests at once as there are cores.  Extra arguments
# go to ctest.
#   scripts/test.sh [ctest args]
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
cd "$top"
build=${GRFLOW_BUILD_DIR:-$top/build}

scripts/install-deps.sh
liggghts_opt=()
if [ "${GRFLOW_TEST_LIGGGHTS:-1}" != 0 ]; then
  log=${GRFLOW_LIGGGHTS_BUILD_DIR:-$top/build-liggghts}.log
  echo "building LIGGGHTS with GRFLOW (log: $log)"
  scripts/build-liggghts.sh > "$log" 2>&1 || { tail -n 40 "$log"; echo "ERROR: the LIGGGHTS build failed"; exit 1; }
  liggghts=$(sed -n 's/^liggghts: //p' "$log" | tail -n 1)
  [ -x "$liggghts" ] || { echo "ERROR: the LIGGGHTS build did not give a binary (log: $log)"; exit 1; }
  liggghts_opt=(-D "GRFLOW_LIGGGHTS=$liggghts")
else
  liggghts_opt=(-D "GRFLOW_LIGGGHTS=OFF")
fi
kokkos_opt=()
if [ -n "${GRFLOW_KOKKOS_SOURCE:-}" ]; then
  kbuild=${GRFLOW_KOKKOS_BUILD_DIR:-$top/build-kokkos-openmp}
  # ccache with paths relative to the repository: the two LAMMPS builds
  # stage the same tree at the same relative place, so the default build
  # can take the KOKKOS build's objects of the files that do not depend on
  # KOKKOS (most of the LAMMPS core and GRANULAR; a file that includes
  # accelerator_kokkos.h differs)
  export CCACHE_BASEDIR="$top"
  log=$kbuild.log
  echo "building LAMMPS with GRFLOW and KOKKOS (OpenMP) from $GRFLOW_KOKKOS_SOURCE (log: $log)"
  GRFLOW_KOKKOS_STYLES=${GRFLOW_KOKKOS_STYLES-minimal} \
    scripts/setup-kokkos.sh openmp "$GRFLOW_KOKKOS_SOURCE" "$kbuild" > "$log" 2>&1 \
    || { tail -n 40 "$log"; echo "ERROR: the KOKKOS build failed"; exit 1; }
  grep "^times:" "$log" || true
  kokkos_opt=(-D "GRFLOW_KOKKOS_LMP=$kbuild/lmp")
else
  echo "no Kokkos source given (GRFLOW_KOKKOS_SOURCE): the KOKKOS build and its tests are left out"
  kokkos_opt=(-D "GRFLOW_KOKKOS_LMP=OFF")
fi
cmake -S . -B "$build" -G Ninja -D CMAKE_BUILD_TYPE=Release "${liggghts_opt[@]}" "${kokkos_opt[@]}"
cmake --build "$build" -j "$(nproc)"
ctest --test-dir "$build" --output-on-failure -j "$(nproc)" "$@"
