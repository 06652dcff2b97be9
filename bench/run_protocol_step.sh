#!/usr/bin/env bash
# Steps per second of the protocol's shear stage on 8000 spheres
# (bench/in.protocol_step), on 1 core and on 2 MPI ranks, in one run.
# Needs the packing of bench/run_pair_bench.sh (build/bench/packing.data;
# made here if missing).
#   bash bench/run_protocol_step.sh [NSTEPS]
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
cd "$top"
lmp=${LMP:-$top/build/lmp}
out=${OUT:-$top/build/bench}
nsteps=${1:-20000}
if [ ! -f "$out/packing.data" ]; then
  mkdir -p "$out"
  "$lmp" -log "$out/log.prep" -screen none -in bench/in.prep_packing -var outdir "$out"
fi
for np in 1 2; do
  cmd=("$lmp")
  if [ "$np" -gt 1 ]; then cmd=(mpirun --allow-run-as-root --oversubscribe -np "$np" "$lmp"); fi
  loop=$("${cmd[@]}" -log none -in bench/in.protocol_step -var outdir "$out" -var nsteps "$nsteps" \
         | grep "Loop time" | tail -1 | awk '{print $4}')
  awk -v n="$nsteps" -v t="$loop" -v np="$np" 'BEGIN { printf "%d rank(s): %d steps in %.2f s = %.0f steps/s\n", np, n, t, n / t }'
done
