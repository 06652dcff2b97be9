#!/usr/bin/env bash
# Campaigns that share one GPU: R copies of the shear stage of the deck
# (inputs/cyclic_shear.lmp) from the same restart file, started together
# on one device, for R in RS; prints per R the wall time of the batch, the
# total steps per second (the steps the R runs made over the wall time,
# start-up included) and the mean of the runs' own steps per second (steps
# over loop times).  A run ends before NSTEPS if its stage does (n_post
# cycles after liquefaction, max_cycles); the steps are those of its loop
# lines.  What pays is the R beyond which the total stops growing.
#
#   bash bench/kokkos_campaign.sh LMP RUNDIR FILE NSTEPS OUTDIR
#
# LMP     lmp with GRFLOW and KOKKOS (scripts/setup-kokkos.sh cuda)
# RUNDIR  a run directory of the decks (its prep.restart, shear.restart.K)
# FILE    prep.restart (the jammed sample at the start of the shear stage)
#         or shear.restart.K (e.g. one after initial liquefaction)
# NSTEPS  steps of each run
# OUTDIR  one folder per run (logs), results.txt
# Environment:
#   RS="1 2 4 8"   the numbers of concurrent runs
#   KK="-k on g 1 -sf kk -pk kokkos newton off neigh half -var newton_pair off"
#                  the KOKKOS switches of every run (CPU threads for a test:
#                  "-k on t 1 -sf kk -pk kokkos newton off neigh half -var newton_pair off")
#   VARS           the run's own -var settings, "name value ..." (e.g. "preset quick")
#   INPUTS         the decks (default inputs/ of this repository)
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
usage="usage: kokkos_campaign.sh LMP RUNDIR FILE NSTEPS OUTDIR"
lmp=$(realpath "${1:?$usage}")
rundir=$(realpath "${2:?$usage}")
file=${3:?$usage}
nsteps=${4:?$usage}
out=$(realpath -m "${5:?$usage}")
rs=${RS:-1 2 4 8}
read -r -a kk <<< "${KK:--k on g 1 -sf kk -pk kokkos newton off neigh half -var newton_pair off}"
inputs=${INPUTS:-$top/inputs}
[ -x "$lmp" ] || { echo "kokkos_campaign.sh: no lmp $lmp" >&2; exit 1; }
[ -f "$rundir/$file" ] || { echo "kokkos_campaign.sh: no $rundir/$file" >&2; exit 1; }
[[ "$nsteps" =~ ^[1-9][0-9]*$ ]] || { echo "kokkos_campaign.sh: NSTEPS $nsteps is not a positive integer" >&2; exit 1; }
case "$file" in
  prep.restart) k=0 resume=no ;;
  shear.restart.*) k=${file##*.} resume=yes ;;
  *) echo "kokkos_campaign.sh: FILE $file: prep.restart or shear.restart.K" >&2; exit 1 ;;
esac
extra=()
read -r -a v <<< "${VARS:-}"
for ((j = 0; j + 1 < ${#v[@]}; j += 2)); do extra+=(-var "${v[$j]}" "${v[$((j + 1))]}"); done
mkdir -p "$out"
echo "# $rundir/$file, $nsteps steps per run, KOKKOS switches: ${kk[*]}" | tee "$out/results.txt"
echo "# R  wall_s  total_steps_per_s  mean_run_steps_per_s" | tee -a "$out/results.txt"
for r in $rs; do
  pids=()
  for ((j = 1; j <= r; j++)); do
    dir=$out/R$r/run$j
    rm -rf "$dir" && mkdir -p "$dir/snapshots"
    ln -s "$rundir/$file" "$dir/$file"
    [ -f "$rundir/$file.cksum" ] && ln -s "$rundir/$file.cksum" "$dir/$file.cksum"
  done
  start=$(date +%s.%N)
  for ((j = 1; j <= r; j++)); do
    dir=$out/R$r/run$j
    OMP_NUM_THREADS=1 "$lmp" -nocite -screen none -log "$dir/log.driver.lammps" "${kk[@]}" \
      -in "$inputs/cyclic_shear.lmp" -var inputs "$inputs" -var stage shear \
      -var resume "$resume" -var outdir "$dir" -var max_steps $((k + nsteps)) "${extra[@]}" &
    pids+=($!)
  done
  failed=0
  for p in "${pids[@]}"; do wait "$p" || failed=1; done
  end=$(date +%s.%N)
  [ "$failed" = 0 ] || { echo "kokkos_campaign.sh: a run of R = $r failed (logs in $out/R$r)" >&2; exit 1; }
  # each run's steps and loop time ("Loop time of T on P procs for S
  # steps"; the stage is split into runs at every event)
  made=()
  for ((j = 1; j <= r; j++)); do
    made+=("$(awk '/^Loop time/ {t += $4; n += $9} END {printf "%d:%.6f", n, t}' \
      "$out/R$r/run$j/log.shear.lammps")")
  done
  awk -v r="$r" -v s="$start" -v e="$end" -v made="${made[*]}" 'BEGIN {
    k = split(made, a, " "); steps = 0; m = 0
    for (i = 1; i <= k; i++) { split(a[i], b, ":"); steps += b[1]; m += b[1] / b[2] }
    printf "%3d  %7.1f  %10.1f  %10.1f\n", r, e - s, steps / (e - s), m / k }' \
    | tee -a "$out/results.txt"
done
