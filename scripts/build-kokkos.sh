#!/usr/bin/env bash
# Build and install Kokkos for the KOKKOS package of LAMMPS, from a source
# tarball or a source tree, for one backend:
#
#   scripts/build-kokkos.sh BACKEND SOURCE PREFIX [ARCH]
#
# BACKEND  openmp   Serial + OpenMP (CPU threads)
#          cuda     Serial + CUDA (an NVIDIA GPU); ARCH names the GPU's
#                   Kokkos architecture: HOPPER90 (H100, H200; the default),
#                   AMPERE80 (A100), ADA89, AMPERE86, TURING75, ...
# SOURCE   kokkos-4.5.01.tar.{xz,gz} or an unpacked Kokkos source tree (read
#          only: it is copied)
# PREFIX   where Kokkos is installed (PREFIX/lib/cmake/Kokkos); the build
#          tree is PREFIX.build
#
# LAMMPS 4Feb2025 needs Kokkos 4.5.01 (find_package(Kokkos 4.5.01) of its
# EXTERNAL_KOKKOS route).  For CUDA 13 and Kokkos 4.5.01 the patches in
# kokkos/patches/ are applied to the copy (kokkos/README.md says why); a
# Kokkos that already has them, or another version, is built as it is.
# A second call with the same backend, ARCH, source and patches finds
# PREFIX/.grflow-kokkos and only checks it.  Ninja and ccache are used when
# there.  Prints "kokkos: PREFIX" at the end.
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd -P)
backend=${1:?usage: build-kokkos.sh openmp|cuda SOURCE PREFIX [ARCH]}
source=${2:?usage: build-kokkos.sh openmp|cuda SOURCE PREFIX [ARCH]}
prefix=${3:?usage: build-kokkos.sh openmp|cuda SOURCE PREFIX [ARCH]}
arch=${4:-}
case "$backend" in
  openmp) [ -z "$arch" ] || { echo "ERROR: ARCH is for the cuda backend, not openmp" >&2; exit 1; } ;;
  cuda) arch=${arch:-HOPPER90} ;;
  *) echo "ERROR: unknown backend $backend: use openmp or cuda" >&2; exit 1 ;;
esac
[ -e "$source" ] || { echo "ERROR: no Kokkos source $source" >&2; exit 1; }
source=$(realpath "$source")
prefix=$(realpath -m "$prefix")
build=$prefix.build
jobs=${GRFLOW_JOBS:-$(nproc)}

# the stamp: what this install was made from
if [ -d "$source" ]; then
  source_id="tree $source"
else
  source_id="tarball $(sha256sum "$source" | cut -d' ' -f1)"
fi
patches_id=$(cat "$top"/kokkos/patches/*.patch | sha256sum | cut -d' ' -f1)
stamp_text="backend $backend
arch $arch
source $source_id
patches $patches_id"
if [ -f "$prefix/.grflow-kokkos" ] && [ "$(cat "$prefix/.grflow-kokkos")" = "$stamp_text" ] \
   && [ -f "$prefix/lib/cmake/Kokkos/KokkosConfig.cmake" ]; then
  echo "Kokkos ($backend${arch:+ $arch}) is installed in $prefix already"
  echo "kokkos: $prefix"
  exit 0
fi

# a fresh copy of the source in the build tree
rm -rf "$build"
mkdir -p "$build"
if [ -d "$source" ]; then
  cp -R "$source" "$build/src"
else
  mkdir -p "$build/unpack"
  tar -xf "$source" -C "$build/unpack"
  top_dirs=("$build"/unpack/*)
  [ ${#top_dirs[@]} -eq 1 ] && [ -d "${top_dirs[0]}" ] \
    || { echo "ERROR: $source does not unpack into one directory" >&2; exit 1; }
  mv "${top_dirs[0]}" "$build/src"
  rmdir "$build/unpack"
fi
src=$build/src
[ -f "$src/CMakeLists.txt" ] && [ -f "$src/core/src/Kokkos_Core.hpp" ] \
  || { echo "ERROR: $source is not a Kokkos source (no core/src/Kokkos_Core.hpp)" >&2; exit 1; }
version=$(sed -n 's/^ *set(Kokkos_VERSION_\(MAJOR\|MINOR\|PATCH\) \([0-9]*\)).*/\2/p' "$src/CMakeLists.txt" \
          | paste -sd. -)
echo "Kokkos $version from $source, backend $backend${arch:+, arch $arch}"

opts=(-D CMAKE_BUILD_TYPE=Release -D CMAKE_INSTALL_PREFIX="$prefix" -D CMAKE_INSTALL_LIBDIR=lib
      -D CMAKE_CXX_STANDARD=17 -D CMAKE_CXX_EXTENSIONS=OFF -D CMAKE_POSITION_INDEPENDENT_CODE=ON
      -D BUILD_SHARED_LIBS=OFF -D Kokkos_ENABLE_SERIAL=ON -D Kokkos_ENABLE_DEPRECATION_WARNINGS=OFF)
case "$backend" in
  openmp)
    opts+=(-D Kokkos_ENABLE_OPENMP=ON)
    command -v ccache > /dev/null && opts+=(-D CMAKE_CXX_COMPILER_LAUNCHER=ccache)
    ;;
  cuda)
    nvcc=$(command -v nvcc || echo "${CUDA_HOME:-/usr/local/cuda}/bin/nvcc")
    [ -x "$nvcc" ] || { echo "ERROR: no nvcc (PATH, CUDA_HOME or /usr/local/cuda)" >&2; exit 1; }
    cuda_major=$("$nvcc" --version | sed -n 's/.*release \([0-9]*\)\..*/\1/p')
    echo "nvcc: $nvcc (CUDA $cuda_major)"
    if [ "$version" = 4.5.1 ] && [ "${cuda_major:-0}" -ge 13 ]; then
      for p in "$top"/kokkos/patches/*.patch; do
        if patch -d "$src" -p1 --dry-run --forward --batch --fuzz=0 --quiet < "$p" > /dev/null 2>&1; then
          patch -d "$src" -p1 --forward --batch --fuzz=0 --no-backup-if-mismatch --quiet < "$p"
          echo "  applied $(basename "$p")"
        elif patch -d "$src" -p1 --dry-run --reverse --force --fuzz=0 --quiet < "$p" > /dev/null 2>&1; then
          echo "  $(basename "$p"): in the source already"
        else
          echo "ERROR: $p does not apply to $source" >&2
          exit 1
        fi
      done
    fi
    export PATH="$(dirname "$nvcc"):$PATH"
    opts+=(-D Kokkos_ENABLE_CUDA=ON -D "Kokkos_ARCH_$arch=ON" -D CMAKE_CXX_COMPILER="$src/bin/nvcc_wrapper")
    ;;
esac
generator=()
command -v ninja > /dev/null && generator=(-G Ninja)

start=$(date +%s)
cmake -S "$src" -B "$build/build" "${generator[@]}" "${opts[@]}"
cmake --build "$build/build" -j "$jobs"
cmake --install "$build/build" > "$build/install.log"
printf '%s\n' "$stamp_text" > "$prefix/.grflow-kokkos"
echo "Kokkos built and installed in $(( $(date +%s) - start )) s"
echo "kokkos: $prefix"
