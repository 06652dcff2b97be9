#!/usr/bin/env bash
# Build GRFLOW (LAMMPS with the package, the plugin, the tests), build
# LIGGGHTS 3.8.0 with GRFLOW (scripts/build-liggghts.sh, into
# build-liggghts/), and run the whole test suite with ctest, the LIGGGHTS
# tests included.  GRFLOW_TEST_LIGGGHTS=0 leaves LIGGGHTS out (no build,
# no LIGGGHTS tests).  Extra arguments go to ctest.
#   scripts/test.sh [ctest args]
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
cd "$top"
build=${GRFLOW_BUILD_DIR:-$top/build}

scripts/install-deps.sh
liggghts_opt=()
if [ "${GRFLOW_TEST_LIGGGHTS:-1}" != 0 ]; then
  liggghts=$(scripts/build-liggghts.sh | tail -n 1 | sed -n 's/^liggghts: //p')
  [ -x "$liggghts" ] || { echo "ERROR: the LIGGGHTS build did not give a binary"; exit 1; }
  liggghts_opt=(-D "GRFLOW_LIGGGHTS=$liggghts")
else
  liggghts_opt=(-D "GRFLOW_LIGGGHTS=OFF")
fi
cmake -S . -B "$build" -G Ninja -D CMAKE_BUILD_TYPE=Release "${liggghts_opt[@]}"
cmake --build "$build" -j "$(nproc)"
ctest --test-dir "$build" --output-on-failure "$@"
