#!/usr/bin/env bash
# Build GRFLOW (LAMMPS with the package, the plugin, the tests), build
# LIGGGHTS 3.8.0 with GRFLOW (scripts/build-liggghts.sh, into
# build-liggghts/), and run the whole test suite with ctest, the LIGGGHTS
# tests included.  GRFLOW_TEST_LIGGGHTS=0 leaves LIGGGHTS out (no build,
# no LIGGGHTS tests).  ctest runs as many tests at once as there are
# cores.  Extra arguments go to ctest.
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
cmake -S . -B "$build" -G Ninja -D CMAKE_BUILD_TYPE=Release "${liggghts_opt[@]}"
cmake --build "$build" -j "$(nproc)"
ctest --test-dir "$build" --output-on-failure -j "$(nproc)" "$@"
