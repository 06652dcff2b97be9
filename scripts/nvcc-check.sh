#!/usr/bin/env bash
# Compile GRFLOW's sources for an NVIDIA GPU with nvcc, on a machine with or
# without a GPU: the device-code check of the KOKKOS styles that needs no
# whole CUDA build of LAMMPS (an hour or more on 2 cores).
#
#   scripts/nvcc-check.sh KOKKOS [BUILD_DIR]
#
# KOKKOS     kokkos-4.5.01.tar.xz (or a source tree, or an installed CUDA
#            Kokkos 4.5.01), as for scripts/setup-kokkos.sh cuda
# BUILD_DIR  default build-nvcc-check in this repository
#
# It runs scripts/setup-kokkos.sh cuda up to the configure (Kokkos for CUDA
# built by scripts/build-kokkos.sh with kokkos/patches for CUDA 13;
# GRFLOW_KOKKOS_ARCH, default HOPPER90; the minimal set of LAMMPS KOKKOS
# styles), then compiles only the object files of GRFLOW's
# sources (those of src/GRFLOW, src/OPENMP and src/KOKKOS that the build
# compiles) through Kokkos's nvcc_wrapper, which compiles every file of a CUDA build
# as CUDA.  It links nothing and runs nothing.  Prints each file, whether
# its object holds device code (readelf: an .nv_fatbin section, which every
# file of src/KOKKOS must have), and "nvcc check: N of M files compiled" at
# the end; exit status 1 when one does not compile or a KOKKOS file has no
# device code.
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd -P)
kokkos=${1:?usage: nvcc-check.sh KOKKOS [BUILD_DIR]}
build=$(realpath -m "${2:-$top/build-nvcc-check}")
[ -e "$kokkos" ] || { echo "ERROR: no Kokkos source or install $kokkos" >&2; exit 1; }
command -v ninja > /dev/null || { echo "ERROR: the nvcc check needs ninja (apt-get install ninja-build)" >&2; exit 1; }
nvcc=$(command -v nvcc || echo "${CUDA_HOME:-/usr/local/cuda}/bin/nvcc")
[ -x "$nvcc" ] || { echo "ERROR: no nvcc (PATH, CUDA_HOME or /usr/local/cuda)" >&2; exit 1; }
export PATH="$(dirname "$nvcc"):$PATH"
echo "nvcc: $("$nvcc" --version | tail -n 2 | head -n 1)"
jobs=${GRFLOW_JOBS:-$(nproc)}
arch=${GRFLOW_KOKKOS_ARCH:-HOPPER90}
mkdir -p "$build"
start=$(date +%s)

# 1. a CUDA Kokkos (an install as it is, or the source built into the
#    build) and the configure of the CUDA build: scripts/setup-kokkos.sh cuda,
#    stopped before it builds
GRFLOW_CONFIGURE_ONLY=1 GRFLOW_KOKKOS_ARCH=$arch GRFLOW_KOKKOS_STYLES=minimal GRFLOW_JOBS=$jobs \
  bash "$top/scripts/setup-kokkos.sh" cuda "$kokkos" "$build" > "$build/configure.log" 2>&1 \
  || { tail -n 30 "$build/configure.log"; echo "ERROR: the Kokkos build or the configure failed ($build/configure.log)" >&2; exit 1; }
kokkos_done=$(date +%s)

# 2. the object files of GRFLOW's sources in the staged tree, as many at
#    once as jobs allow
mapfile -t objects < <(ninja -C "$build" -t targets all \
  | sed -n 's/^\(.*\/src\/\(GRFLOW\|OPENMP\|KOKKOS\)\/[^/]*\.cpp\.o\): .*/\1/p' \
  | grep -E '/(GRFLOW/|(OPENMP|KOKKOS)/.*grflow)' | sort -u)
[ ${#objects[@]} -gt 0 ] || { echo "ERROR: no GRFLOW object file among the build's targets" >&2; exit 1; }
echo "compiling ${#objects[@]} files with nvcc_wrapper (Kokkos_ARCH $arch), $jobs at once"
fail=0
ninja -C "$build" -j "$jobs" -k 0 "${objects[@]}" > "$build/compile.log" 2>&1 || fail=1
grep -E "^FAILED|error" "$build/compile.log" | head -n 40 || true
ok=0
for o in "${objects[@]}"; do
  if [ -f "$build/$o" ]; then
    ok=$((ok + 1))
    # the KOKKOS files hold their kernels as device code (an .nv_fatbin
    # section), the others need not
    device=
    if command -v readelf > /dev/null; then
      sections=$(readelf -S "$build/$o")
      if [[ $sections == *nv_fatbin* ]]; then
        device=" (device code)"
      elif [[ $o == */KOKKOS/* ]]; then
        device=" (NO device code)"
        fail=1
      fi
    fi
    echo "  compiled: ${o##*/src/}$device"
  else
    echo "  FAILED:   ${o##*/src/}"
  fi
done
end=$(date +%s)
echo "times: Kokkos and configure $(( kokkos_done - start )) s, compile $(( end - kokkos_done )) s"
echo "nvcc check: $ok of ${#objects[@]} files compiled (log: $build/compile.log)"
[ $fail = 0 ] && [ $ok = ${#objects[@]} ]
