#!/usr/bin/env bash
# GRFLOW against the newest LAMMPS in Debian (4Jul2026, lammps
# 20260704+dfsg from sid): fetch its source the same private, checksummed
# way as the default one, build GRFLOW against it (LAMMPS with the
# package, the plugin, the tests) and run the whole test suite.  CI tests
# the default 4Feb2025; this is the second supported version.
#   bash scripts/test-newest.sh [BUILD_DIR] [ctest args]   (default build-4Jul2026)
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$top/build-4Jul2026}
shift || true
cache=${GRFLOW_CACHE_DIR:-$HOME/.cache/grflow}
tree=$(bash "$top/scripts/fetch-lammps-source.sh" "$cache" 4Jul2026)
echo "LAMMPS tree: $tree ($(grep LAMMPS_VERSION "$tree/src/version.h"))"
t0=$(date +%s)
cmake -S "$top" -B "$build" -G Ninja -D CMAKE_BUILD_TYPE=Release -D LAMMPS_SOURCE_DIR="$tree" \
  -D GRFLOW_CACHE_DIR="$cache"
cmake --build "$build" -j "$(nproc)"
t1=$(date +%s)
rc=0
ctest --test-dir "$build" --output-on-failure -j "$(nproc)" "$@" || rc=$?
t2=$(date +%s)
echo "LAMMPS 4Jul2026: build $((t1 - t0)) s, tests $((t2 - t1)) s, ctest rc $rc"
exit "$rc"
