#!/usr/bin/env bash
# Build GRFLOW (LAMMPS with the package, the plugin, the tests) and run the
# whole test suite with ctest.  Extra arguments go to ctest.
#   scripts/test.sh [ctest args]
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
cd "$top"
build=${GRFLOW_BUILD_DIR:-$top/build}

scripts/install-deps.sh
cmake -S . -B "$build" -G Ninja -D CMAKE_BUILD_TYPE=Release
cmake --build "$build" -j "$(nproc)"
ctest --test-dir "$build" --output-on-failure "$@"
