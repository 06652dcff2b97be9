#!/usr/bin/env bash
# How long a shear stage takes in several settings (variants; default: 1
# core and 2 MPI ranks), from the restart files of one run of it: from
# prep.restart and from every shear.restart.<K> of RUNDIR, the real deck
# runs NSTEPS steps in each variant (one after the other, on an otherwise
# idle machine), and the stage's time is the sum over the intervals
# between restart files of interval / (steps per second at its start).  The speed changes along the
# stage (the liquefied sample has few contacts), so one sample from its
# start would not do.  Nor do a few short ones: the speed also changes
# twofold within a post-liquefaction cycle, and 5 samples of 20000 steps
# overestimated the paper case's 2-rank time by 30% (doc/studies/shear-stage-sampling.md).
# Check the sum for the run's own rank count against its measured time.
#   bash bench/sample_shear_speed.sh RUNDIR [NSTEPS [VARIANT ...]]   # default 20000
# VARIANT: "NAME|NP|MPIARGS[|LMPARGS[|LMP]]" (MPIARGS: extra mpirun
# arguments, for NP > 1; LMPARGS: extra lmp arguments; LMP: another lmp
# than the default); default "1 core|1|" "2 ranks|2|".  The KOKKOS styles
# on a GPU against 2 ranks of the plain ones, e.g.:
#   bash bench/sample_shear_speed.sh runs/case 20000 "2 ranks|2|" \
#     "gpu|1||-k on g 1 -sf kk -pk kokkos newton off neigh half -var newton_pair off|build-kokkos-cuda/lmp"
# The variants run alike from the same
# file (the transport does not change the arithmetic), so their sums
# compare the whole stage, weighted by where its steps are.  Example, Open
# MPI's single-copy transfers off against the default, 2 rounds:
#   ROUNDS=2 bash bench/sample_shear_speed.sh runs/case 20000 "default|2|" \
#     "nocma|2|--mca btl_vader_single_copy_mechanism none"
# Environment:
#   EVERY  use every EVERY-th restart file (default 1)
#   ROUNDS repeat the whole sampling (default 1); even rounds run the
#          variants in the reverse order, so that neither always goes first
#   LMP    lmp binary (default build/lmp); INPUTS (default inputs/);
#          OUT scratch directory (default build/bench/sample)
# Prints a line per round and sample, and per round each variant's sum
# and its ratio to the first's.  RUNDIR must hold the run's
# prep.restart, its shear.restart.* and series.txt; a finished run's
# log.shear.lammps gives the last step (else series.txt's last row).
#   VARS   the run's own -var settings, as "name value ..." (e.g.
#          VARS="preset quick"); they are not in the restart files
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
rundir=$(cd "${1:?usage: sample_shear_speed.sh RUNDIR [NSTEPS [VARIANT ...]]}" && pwd)
nsteps=${2:-20000}
shift $(($# < 2 ? $# : 2))
variants=("$@")
[ ${#variants[@]} -gt 0 ] || variants=("1 core|1|" "2 ranks|2|")
every=${EVERY:-1}
rounds=${ROUNDS:-1}
lmp=${LMP:-$top/build/lmp}
inputs=${INPUTS:-$top/inputs}
out=${OUT:-$top/build/bench/sample}
[ -f "$rundir/prep.restart" ] || { echo "no prep.restart in $rundir" >&2; exit 1; }
[ -f "$rundir/series.txt" ] || { echo "no series.txt in $rundir" >&2; exit 1; }

last=$(sed -n 's/^GRFLOW shear: done at step \([0-9]*\),.*/\1/p' "$rundir/log.shear.lammps" 2>/dev/null | tail -n 1)
finished=yes
if [ -z "$last" ]; then
  last=$(awk '!/^#/ {s = $1} END {print s}' "$rundir/series.txt")
  finished=no
fi
points=(0)
for f in $(ls "$rundir" | sed -n 's/^shear\.restart\.\([0-9]*\)$/\1/p' | sort -n); do
  # step 0 is prep.restart's sample (the deck may write shear.restart.0 too)
  [ "$f" -gt 0 ] && [ "$f" -lt "$last" ] && points+=("$f")
done
sel=()
for i in "${!points[@]}"; do
  [ $((i % every)) -eq 0 ] && sel+=("${points[$i]}")
done

# steps per second of NSTEPS steps from step K on NP ranks (MPIARGS: extra
# mpirun arguments)
sample() {
  local k=$1 np=$2 mpiargs=$3 lmpargs=$4 bin=${5:-$lmp} dir=$out/sample resume=yes
  rm -rf "$dir" && mkdir -p "$dir/snapshots"
  # the file and its checksum file (the deck resumes only from a file that verifies)
  local file=shear.restart.$k
  if [ "$k" -eq 0 ]; then
    file=prep.restart
    resume=no
  fi
  ln -s "$rundir/$file" "$dir/$file"
  [ -f "$rundir/$file.cksum" ] && ln -s "$rundir/$file.cksum" "$dir/$file.cksum"
  local extra=() v
  read -r -a v <<< "${VARS:-}"
  for ((j = 0; j + 1 < ${#v[@]}; j += 2)); do extra+=(-var "${v[$j]}" "${v[$((j + 1))]}"); done
  local cmd=("$bin")
  # shellcheck disable=SC2206
  if [ "$np" -gt 1 ]; then cmd=(mpirun --allow-run-as-root --oversubscribe -np "$np" $mpiargs "$bin"); fi
  # shellcheck disable=SC2206
  cmd+=($lmpargs)
  OMP_NUM_THREADS=1 "${cmd[@]}" -in "$inputs/cyclic_shear.lmp" -var inputs "$inputs" \
    -var stage shear -var resume "$resume" -var outdir "$dir" -var max_steps $((k + nsteps)) \
    "${extra[@]}" -log "$dir/log.driver.lammps" -screen none
  # the run is split into segments at every event: sum their loop times
  local loop
  loop=$(awk '/^Loop time/ {t += $4} END {print t}' "$dir/log.shear.lammps")
  rm -rf "$dir"
  awk -v n="$nsteps" -v t="$loop" 'BEGIN {printf "%.1f", n / t}'
}

names=()
for v in "${variants[@]}"; do names+=("$(cut -d'|' -f1 <<< "$v")"); done
echo "# $rundir: stage from step 0 to $last (finished: $finished), ${#sel[@]} samples of $nsteps steps, $rounds round(s)"
echo "# round  step  steps/s: $(printf '%s; ' "${names[@]}")ratios to the first"
for round in $(seq 1 "$rounds"); do
  order=("${!variants[@]}")
  if [ $((round % 2)) -eq 0 ]; then
    order=()
    for ((j = ${#variants[@]} - 1; j >= 0; j--)); do order+=("$j"); done
  fi
  sums=()
  for j in "${!variants[@]}"; do sums[$j]=0; done
  for i in "${!sel[@]}"; do
    k=${sel[$i]}
    next=$last
    [ $((i + 1)) -lt ${#sel[@]} ] && next=${sel[$((i + 1))]}
    rates=()
    for j in "${order[@]}"; do
      IFS='|' read -r _ np mpiargs lmpargs bin <<< "${variants[$j]}"
      rates[$j]=$(sample "$k" "$np" "${mpiargs:-}" "${lmpargs:-}" "${bin:-}")
    done
    line=$(printf "%5d %9d " "$round" "$k")
    for j in "${!variants[@]}"; do
      line+=$(printf " %8s" "${rates[$j]}")
      sums[$j]=$(echo "${sums[$j]} + ($next - $k) / ${rates[$j]}" | bc -l)
    done
    for j in "${!variants[@]}"; do
      [ "$j" -gt 0 ] && line+=$(printf "  %.2f" "$(echo "${rates[$j]} / ${rates[0]}" | bc -l)")
    done
    echo "$line"
  done
  for j in "${!variants[@]}"; do
    awk -v a="${sums[$j]}" -v b="${sums[0]}" -v n="$last" -v r="$round" -v name="${names[$j]}" 'BEGIN {
      printf "round %d: stage of %d steps: %.0f s (%.2f h) %s, ratio to the first %.3f\n",
             r, n, a, a / 3600, name, b / a }'
  done
done
