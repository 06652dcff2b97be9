#!/usr/bin/env bash
# Timing of the paper's protocol (inputs/cyclic_shear.lmp, 8000 spheres) on
# 1 core and on 2 MPI ranks, in one run of this script:
#   1. the preparation stage (stages 1-4), timed whole, on each rank count;
#   2. the shear stage from that sample for STEPS steps (default 50000),
#      on each rank count, as steps per second.
# The whole shear stage is far longer than a benchmark; its duration is
# steps-to-finish / steps-per-second, where the number of steps comes from
# a finished run (runs/<name>/series.txt) or an estimate (see README.md).
#
#   bash bench/run_protocol_timing.sh [STEPS]
# Environment: LMP (default build/lmp), OUT (default build/bench/protocol),
# MPIRUN (default mpirun), EXTRA (more -var pairs, e.g. "-var N 2000").
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
cd "$top"
lmp=${LMP:-$top/build/lmp}
out=${OUT:-$top/build/bench/protocol}
mpirun=${MPIRUN:-mpirun}
steps=${1:-50000}
extra=${EXTRA:-}
mkdir -p "$out"

run() {    # ranks outdir args...
  local np=$1 dir=$2
  shift 2
  local cmd=("$lmp" -log none -screen none -in inputs/cyclic_shear.lmp -var outdir "$dir" $extra "$@")
  if [ "$np" -gt 1 ]; then
    cmd=("$mpirun" --allow-run-as-root --oversubscribe -np "$np" "${cmd[@]}")
  fi
  local t0=$(date +%s.%N)
  "${cmd[@]}"
  echo "$(date +%s.%N) - $t0" | bc
}

for np in 1 2; do
  dir=$out/np$np
  rm -rf "$dir"
  tprep=$(run "$np" "$dir" -var stage prep)
  grep -h "GRFLOW prep: done" "$dir/log.prep.lammps" | sed "s/^/np=$np: /"
  tshear=$(run "$np" "$dir" -var stage shear -var max_steps "$steps" -var n_post 1000)
  rate=$(echo "$steps / $tshear" | bc -l)
  printf 'np=%d: preparation %.0f s; shear %d steps in %.1f s = %.0f steps/s\n' \
    "$np" "$tprep" "$steps" "$tshear" "$rate" | tee -a "$out/timing.txt"
done
