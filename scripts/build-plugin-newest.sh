#!/usr/bin/env bash
# GRFLOW against the newest LAMMPS in Debian (4Jul2026, lammps
# 20260704+dfsg from sid): fetches its source like the default one, then
# builds the plugin alone against it (plugin/CMakeLists.txt), which
# compiles every GRFLOW source with that version's headers.  It does not
# build an lmp of that version, so the plugin is not loaded or tested
# here (that is a LAMMPS build of about 20 minutes on 2 cores, not done
# yet).
#   bash scripts/build-plugin-newest.sh [BUILD_DIR]   (default build-plugin-4Jul2026)
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
out=${1:-$top/build-plugin-4Jul2026}
cache=${GRFLOW_CACHE_DIR:-$HOME/.cache/grflow}
tree=$(bash "$top/scripts/fetch-lammps-source.sh" "$cache" 4Jul2026)
echo "LAMMPS tree: $tree ($(grep LAMMPS_VERSION "$tree/src/version.h"))"
cmake -S "$top/plugin" -B "$out" -D LAMMPS_SOURCE_DIR="$tree" > "$out.configure.log" 2>&1 ||
  { cat "$out.configure.log"; exit 1; }
cmake --build "$out" 2>&1 | tee "$out.build.log" | grep -E "error|warning" || true
test -f "$out/grflowplugin.so"
echo "built $out/grflowplugin.so against $tree"
