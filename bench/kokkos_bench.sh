#!/usr/bin/env bash
# granular/grflow/kk against gran/hooke/history/kk in the same call: steps/s
# and ns per neighbor pair per step on a jammed packing tiled to several sizes
# (bench/kokkos_bench.lmp, one LAMMPS process per style and size, 1 MPI rank).
#
#   bench/kokkos_bench.sh LMP DATA OUTDIR
#
# LMP      lmp with GRFLOW, GRANULAR and KOKKOS (scripts/setup-kokkos.sh)
# DATA     the packing (in.prep_packing's packing.data: 8000 spheres)
# OUTDIR   logs (log.<style>.<n>) and results.json
# environment:
#   TILES="1 2 4"   tiles per side (8000 spheres: 8000, 64000, 512000)
#   KK="-k on g 1 -sf kk -pk kokkos newton off neigh half"   the KOKKOS switches
#                   (CPU threads: -k on t N -sf kk -pk kokkos newton off neigh half)
#   NSTEPS=1000 NWARM=200   timed and warm-up steps (per size: NSTEPS_<n>, NWARM_<n>)
#   ROUNDS=1        interleaved rounds (grflow hooke grflow hooke ...); the
#                   fastest round of each is reported
#   BLOCKING=1      one more granular/grflow run per size with
#                   CUDA_LAUNCH_BLOCKING=1 (label grflow_blocking): every
#                   kernel launch waits for the kernel, so that the Pair row
#                   is the pair kernels' time (LAMMPS does not fence the
#                   device in its timers); 0 leaves it out.  On CPU threads
#                   it changes nothing.
set -euo pipefail
bench=$(cd "$(dirname "$0")" && pwd)
lmp=${1:?usage: kokkos_bench.sh LMP DATA OUTDIR}
data=${2:?usage: kokkos_bench.sh LMP DATA OUTDIR}
out=${3:?usage: kokkos_bench.sh LMP DATA OUTDIR}
tiles=${TILES:-1 2 4}
read -r -a kk <<< "${KK:--k on g 1 -sf kk -pk kokkos newton off neigh half}"
rounds=${ROUNDS:-1}
[ -x "$lmp" ] || { echo "kokkos_bench.sh: no lmp $lmp" >&2; exit 1; }
[ -f "$data" ] || { echo "kokkos_bench.sh: no packing $data" >&2; exit 1; }
lmp=$(realpath "$lmp")
data=$(realpath "$data")
mkdir -p "$out"
out=$(realpath "$out")
cd "$out"
logs=()
for n in $tiles; do
  steps_var=NSTEPS_$n warm_var=NWARM_$n
  nsteps=${!steps_var:-${NSTEPS:-1000}}
  nwarm=${!warm_var:-${NWARM:-200}}
  for ((r = 1; r <= rounds; r++)); do
    for style in grflow hooke; do
      log=$out/log.$style.$n.$r
      start=$SECONDS
      "$lmp" -nocite -screen none -log "$log" "${kk[@]}" -in "$bench/kokkos_bench.lmp" \
        -var data "$data" -var n "$n" -var style "$style" -var nsteps "$nsteps" \
        -var nwarm "$nwarm" \
        || { tail -n 30 "$log"; echo "kokkos_bench.sh: the $style run at n = $n failed" >&2; exit 1; }
      case $style in grflow) name=granular/grflow ;; hooke) name=gran/hooke/history ;; esac
      grep -q "pair $name/kk" "$log" \
        || { echo "kokkos_bench.sh: $log did not use $name/kk (KK: ${kk[*]})" >&2; exit 1; }
      echo "$style n=$n round $r: $(( SECONDS - start )) s"
      logs+=("$log")
    done
  done
done
if [ "${BLOCKING:-1}" != 0 ]; then
  for n in $tiles; do
    steps_var=NSTEPS_$n warm_var=NWARM_$n
    log=$out/log.grflow_blocking.$n
    start=$SECONDS
    CUDA_LAUNCH_BLOCKING=1 "$lmp" -nocite -screen none -log "$log" "${kk[@]}" \
      -in "$bench/kokkos_bench.lmp" -var data "$data" -var n "$n" -var style grflow \
      -var label grflow_blocking -var nsteps "${!steps_var:-${NSTEPS:-1000}}" \
      -var nwarm "${!warm_var:-${NWARM:-200}}" \
      || { tail -n 30 "$log"; echo "kokkos_bench.sh: the blocking run at n = $n failed" >&2; exit 1; }
    echo "grflow_blocking n=$n: $(( SECONDS - start )) s"
    logs+=("$log")
  done
fi
python3 "$bench/kokkos_bench.py" "${logs[@]}" --json "$out/results.json"
