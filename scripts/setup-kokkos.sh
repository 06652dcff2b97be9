#!/usr/bin/env bash
# Build LAMMPS 4Feb2025 with GRFLOW and the KOKKOS package
# (pair_style granular/grflow/kk, -sf kk), for CPU threads or an NVIDIA GPU,
# and check it:
#
#   scripts/setup-kokkos.sh openmp KOKKOS [BUILD_DIR] [-- CMAKE_ARGS...]
#   scripts/setup-kokkos.sh cuda KOKKOS [BUILD_DIR] [-- CMAKE_ARGS...]
#
# openmp   Kokkos Serial + OpenMP: run with  lmp -k on t N -sf kk -pk kokkos newton off ...
# cuda     Kokkos Serial + CUDA (nvcc on PATH or in /usr/local/cuda); the
#          GPU's Kokkos architecture in GRFLOW_KOKKOS_ARCH (default
#          HOPPER90: H100, H200; AMPERE80: A100; ...): run with
#          lmp -k on g 1 -sf kk -pk kokkos newton off neigh half ...
# KOKKOS   kokkos-4.5.01.tar.xz (or .tar.gz), a Kokkos 4.5.01 source tree, or
#          an installed Kokkos 4.5.01 (a prefix with lib/cmake/Kokkos) of the
#          same backend
# BUILD_DIR  default build-kokkos-<backend> in this repository; a Kokkos
#          built from source is installed in BUILD_DIR/kokkos
#          (scripts/build-kokkos.sh, which applies kokkos/patches for CUDA 13)
#
# The LAMMPS tree is the default build's (Debian's lammps 20250204+dfsg.1,
# fetched once; or -D LAMMPS_SOURCE_DIR=... after --), staged with GRFLOW's
# src/GRFLOW, src/OPENMP and src/KOKKOS (CMakeLists.txt with
# -D GRFLOW_KOKKOS=ON).  GRFLOW_KOKKOS_STYLES=minimal builds only the LAMMPS
# KOKKOS styles a GRFLOW run uses (cmake/GRFLOWKokkos.cmake), in a third
# of the time.  The default build (scripts/setup.sh) is not touched; this
# one is used from BUILD_DIR (BUILD_DIR/lmp).  Prints "lmp: PATH" at the end.
# GRFLOW_CONFIGURE_ONLY=1 stops after the configure (scripts/nvcc-check.sh
# then compiles only GRFLOW's files) and prints "configured: BUILD_DIR".
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd -P)
usage="usage: setup-kokkos.sh openmp|cuda KOKKOS [BUILD_DIR] [-- CMAKE_ARGS...]"
backend=${1:?$usage}
kokkos=${2:?$usage}
shift 2
build=$top/build-kokkos-$backend
if [ $# -gt 0 ] && [ "$1" != "--" ]; then
  build=$1
  shift
fi
[ $# -gt 0 ] && [ "$1" = "--" ] && shift
case "$backend" in
  openmp) arch= ;;
  cuda) arch=${GRFLOW_KOKKOS_ARCH:-HOPPER90} ;;
  *) echo "ERROR: unknown backend $backend: use openmp or cuda" >&2; exit 1 ;;
esac
[ -e "$kokkos" ] || { echo "ERROR: no Kokkos source or install $kokkos" >&2; exit 1; }
build=$(realpath -m "$build")
mkdir -p "$build"
jobs=${GRFLOW_JOBS:-$(nproc)}
start=$(date +%s)

# 1. Kokkos: an install as it is, or a source built and installed into the build
if [ -f "$kokkos/lib/cmake/Kokkos/KokkosConfig.cmake" ] || [ -f "$kokkos/lib64/cmake/Kokkos/KokkosConfig.cmake" ]; then
  kokkos_root=$(realpath "$kokkos")
  config=$kokkos_root/include/KokkosCore_config.h
  has_cuda=0
  grep -q "^#define KOKKOS_ENABLE_CUDA$" "$config" 2> /dev/null && has_cuda=1
  if [ "$backend" = cuda ] && [ $has_cuda = 0 ]; then
    echo "ERROR: the Kokkos in $kokkos_root has no CUDA backend" >&2; exit 1
  fi
  if [ "$backend" = openmp ] && [ $has_cuda = 1 ]; then
    echo "ERROR: the Kokkos in $kokkos_root is a CUDA build: use the cuda backend" >&2; exit 1
  fi
  echo "Kokkos: installed in $kokkos_root"
else
  kokkos_root=$build/kokkos
  bash "$top/scripts/build-kokkos.sh" "$backend" "$kokkos" "$kokkos_root" $arch
fi
kokkos_done=$(date +%s)

# 2. LAMMPS with GRFLOW and KOKKOS against it
opts=(-D CMAKE_BUILD_TYPE=Release -D GRFLOW_KOKKOS=ON -D "Kokkos_ROOT=$kokkos_root"
      -D "GRFLOW_KOKKOS_STYLES=${GRFLOW_KOKKOS_STYLES:-}")
if [ "$backend" = cuda ]; then
  nvcc=$(command -v nvcc || echo "${CUDA_HOME:-/usr/local/cuda}/bin/nvcc")
  export PATH="$(dirname "$nvcc"):$PATH"
  opts+=(-D "CMAKE_CXX_COMPILER=$kokkos_root/bin/nvcc_wrapper")
fi
generator=()
command -v ninja > /dev/null && generator=(-G Ninja)
cmake -S "$top" -B "$build" "${generator[@]}" "${opts[@]}" "$@"
if [ "${GRFLOW_CONFIGURE_ONLY:-0}" = 1 ]; then
  echo "times: Kokkos $(( kokkos_done - start )) s"
  echo "configured: $build"
  exit 0
fi
cmake --build "$build" -j "$jobs"
lmp=$build/lmp
lammps_done=$(date +%s)

# 3. checks: the style is there; a short run of the KOKKOS style where the
#    backend can run here
"$lmp" -h | grep "granular/grflow/kk" > /dev/null \
  || { echo "ERROR: $lmp lacks granular/grflow/kk" >&2; exit 1; }
run_check=1
if [ "$backend" = cuda ] && ! nvidia-smi -L > /dev/null 2>&1; then
  run_check=0
  echo "no GPU here: the check run is left out (scripts/gpu-check.sh runs the tests on a GPU)"
fi
if [ $run_check = 1 ]; then
  if [ "$backend" = cuda ]; then
    kk=(-k on g 1 -sf kk -pk kokkos newton off neigh half)
  else
    kk=(-k on t 1 -sf kk -pk kokkos newton off neigh half)
  fi
  # two spheres rolling across a periodic boundary (a test deck)
  out=$(cd "$build" && "$lmp" -log none -nocite "${kk[@]}" -var newton off \
          -var pairstyle granular/grflow -var paircoeff "* * 1.0e6 1.15" \
          -var dump "$build/check.dump" -in "$top/tests/decks/boundary_crossing.lmp" 2>&1) \
    || { echo "$out" | tail -n 20; echo "ERROR: the check run of $lmp failed" >&2; exit 1; }
  echo "$out" | grep "pair granular/grflow/kk" > /dev/null \
    || { echo "$out" | tail -n 20; echo "ERROR: the check run did not use granular/grflow/kk" >&2; exit 1; }
  echo "check run: $(echo "$out" | grep '^Loop time' | tail -n 1)"
fi
echo "times: Kokkos $(( kokkos_done - start )) s, LAMMPS $(( lammps_done - kokkos_done )) s"
echo "lmp: $lmp"
