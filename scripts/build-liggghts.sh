#!/usr/bin/env bash
# Build LIGGGHTS 3.8.0 with GRFLOW inside: fetch Debian's source package
# (scripts/fetch-liggghts-source.sh, cached in GRFLOW_CACHE_DIR, default
# ~/.cache/grflow), stage its src/ in BUILD_DIR with our patches
# (liggghts/patches/*.patch) and GRFLOW's files added (src/shared/*,
# src/LIGGGHTS/*, and the commands' classes of src/GRFLOW that
# src/LIGGGHTS/lammps-sources.txt lists), then build the liggghts executable and
# libliggghts.so with CMake (Ninja and ccache when there).  The cached tree
# is never written to.  See liggghts/README.md.
#
#   scripts/build-liggghts.sh [BUILD_DIR]
#
# BUILD_DIR (default $GRFLOW_LIGGGHTS_BUILD_DIR, else <repo>/build-liggghts):
#   src/          the staged source: LIGGGHTS's src/, patched, plus our files;
#                 LIGGGHTS's Make.sh writes its style_*.h headers here
#   cmake/        the CMake build; cmake/liggghts is the executable
#   staged-files  what staging put in src/ (to remove what left the repo)
#   models-declared  a sum of the contact models declared in src/
# A file is copied into src/ only when its content changed, so unchanged
# files keep their mtimes and a rebuild compiles only what a change touches.
# Always build through this script: a bare "cmake --build BUILD_DIR/cmake"
# neither restages src/ nor sees new styles in time.
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd -P)
build=${1:-${GRFLOW_LIGGGHTS_BUILD_DIR:-$top/build-liggghts}}
cache=${GRFLOW_CACHE_DIR:-$HOME/.cache/grflow}
# GRFLOW's compile contract: no -ffast-math, no fused multiply-adds
# (cmake/GRFLOWCompileSettings.cmake); the rest is LIGGGHTS's own default
# less its warnings, in C++17
cxx_flags="-O2 -funroll-loops -fstrict-aliasing -fPIC -std=c++17 -ffp-contract=off"

tree=$(bash "$top/scripts/fetch-liggghts-source.sh" "$cache")

# write only into a build directory of ours: a new or empty one, or one this
# script made before; never into the fetched tree or into this repo's src/
build=$(realpath -m "$build")
case "$build/" in
  "$(realpath "$tree")"/*|"$top/src/"*|"$top/liggghts/"*)
    echo "ERROR: BUILD_DIR $build lies inside a source tree" >&2; exit 1 ;;
esac
mkdir -p "$build"
if [ ! -f "$build/.grflow-liggghts-build" ]; then
  if [ -n "$(ls -A "$build")" ]; then
    echo "ERROR: $build is not empty and not a GRFLOW LIGGGHTS build directory" >&2
    exit 1
  fi
  touch "$build/.grflow-liggghts-build"
fi
# one build at a time in BUILD_DIR
exec {lock}> "$build/.lock"
flock "$lock"

# 1. the wanted source, made afresh in next/: LIGGGHTS's src/, patched, plus
#    our files, flat in src/ (LIGGGHTS's CMakeLists.txt globs src/*.cpp and
#    its Make.sh scans src/*.h for style macros)
next=$build/next
rm -rf "$next"
mkdir -p "$next"
cp -R "$tree/src" "$next/src"
for p in "$top"/liggghts/patches/*.patch; do
  [ -e "$p" ] || continue
  patch -d "$next" -p1 --batch --fuzz=0 --no-backup-if-mismatch --quiet < "$p" \
    || { echo "ERROR: $p does not apply to LIGGGHTS 3.8.0" >&2; exit 1; }
done
# src/shared, src/LIGGGHTS (less its list) and the files of src/GRFLOW that
# src/LIGGGHTS/lammps-sources.txt lists
common=()
while read -r name; do
  case "$name" in ''|'#'*) continue ;; esac
  [ -f "$top/src/GRFLOW/$name" ] || { echo "ERROR: src/LIGGGHTS/lammps-sources.txt lists $name," \
    "which src/GRFLOW does not have" >&2; exit 1; }
  common+=("$top/src/GRFLOW/$name")
done < "$top/src/LIGGGHTS/lammps-sources.txt"
for f in "$top"/src/shared/* "$top"/src/LIGGGHTS/* "${common[@]}"; do
  [ -f "$f" ] || continue
  name=$(basename "$f")
  [ "$name" = lammps-sources.txt ] && continue
  if [ -e "$next/src/$name" ]; then
    echo "ERROR: $f: LIGGGHTS's src/ (or another GRFLOW file) already has $name" >&2
    exit 1
  fi
  cp "$f" "$next/src/$name"
done

# 2. bring src/ to it: copy what differs (a copy gets a new mtime, so
#    Ninja rebuilds what depends on it), remove what staging put there
#    before and is no longer wanted; leave Make.sh's generated files alone
mkdir -p "$build/src"
(cd "$next" && find src -type f | LC_ALL=C sort) > "$build/staged-files.new"
copied=0
while IFS= read -r rel; do
  if ! cmp -s "$next/$rel" "$build/$rel"; then
    mkdir -p "$(dirname "$build/$rel")"
    cp "$next/$rel" "$build/$rel"
    copied=$((copied + 1))
  fi
done < "$build/staged-files.new"
removed=0
if [ -f "$build/staged-files" ]; then
  while IFS= read -r rel; do
    rm -f "$build/$rel"
    removed=$((removed + 1))
  done < <(LC_ALL=C comm -23 "$build/staged-files" "$build/staged-files.new")
fi
mv "$build/staged-files.new" "$build/staged-files"
rm -rf "$next"
echo "staged $build/src: $copied file(s) copied, $removed removed" >&2

# 3. Make.sh models generates the list of contact-model combinations once
#    (style_contact_model.whitelist, slow) and reuses it ever after: drop it
#    when the set of declared models changes, so that it is made again
models=$(cd "$build/src" && grep -s -E '^(SURFACE|NORMAL|TANGENTIAL|COHESION|ROLLING)_MODEL\(' \
           surface_model_*.h normal_model_*.h tangential_model_*.h cohesion_model_*.h rolling_model_*.h \
           | md5sum | cut -d' ' -f1)
if [ "$models" != "$(cat "$build/models-declared" 2>/dev/null || true)" ]; then
  rm -f "$build/src/style_contact_model.whitelist"
  echo "$models" > "$build/models-declared"
fi
# make the style headers now, before Ninja looks at the mtimes: the
# GenerateHeaders target makes them again during the build (then changing
# nothing), but what it changes there is seen only by the next build, as it
# declares no outputs (a new FixStyle would reach modify.cpp a build late)
(cd "$build/src" && sh Make.sh style && sh Make.sh models) >&2

# 4. configure (again each time: new or removed .cpp files must reach the
#    glob of LIGGGHTS's CMakeLists.txt) and build
cmake_opts=(-D "CMAKE_CXX_FLAGS=$cxx_flags" -D CMAKE_DISABLE_FIND_PACKAGE_VTK=ON -Wno-dev)
if [ ! -f "$build/cmake/CMakeCache.txt" ] && command -v ninja > /dev/null; then
  cmake_opts+=(-G Ninja)
fi
if command -v ccache > /dev/null; then
  cmake_opts+=(-D CMAKE_CXX_COMPILER_LAUNCHER=ccache -D CMAKE_C_COMPILER_LAUNCHER=ccache)
  # paths relative to the build dir, so that another checkout's build hits too
  export CCACHE_BASEDIR=${CCACHE_BASEDIR:-$build}
fi
mkdir -p "$build/cmake"
cmake -S "$build/src" -B "$build/cmake" "${cmake_opts[@]}" > "$build/cmake/configure.log" \
  || { cat "$build/cmake/configure.log" >&2; echo "ERROR: CMake configure failed" >&2; exit 1; }
cmake --build "$build/cmake" --target liggghts_bin liggghts_shared -j "$(nproc)"
echo "liggghts: $build/cmake/liggghts"
