#!/usr/bin/env bash
# How long a shear stage takes on 1 core and on 2 MPI ranks, from the
# restart files of one run of it: from prep.restart and from every
# shear.restart.<K> of RUNDIR, the real deck runs NSTEPS steps on 1 core
# and on 2 ranks (one after the other, on an otherwise idle machine), and
# the stage's time is the sum over the intervals between restart files of
# interval / (steps per second at its start).  The speed changes along the
# stage (the liquefied sample has few contacts), so one sample from its
# start would not do.  Nor do a few short ones: the speed also changes
# twofold within a post-liquefaction cycle, and 5 samples of 20000 steps
# overestimated the paper case's 2-rank time by 30% (doc/studies/shear-stage-sampling.md).
# Check the sum for the run's own rank count against its measured time.
#   bash bench/sample_shear_speed.sh RUNDIR [NSTEPS]     # default 20000
# Environment:
#   EVERY  use every EVERY-th restart file (default 1)
#   LMP    lmp binary (default build/lmp); INPUTS (default inputs/);
#          OUT scratch directory (default build/bench/sample)
# Prints a line per sample and the two sums.  RUNDIR must hold the run's
# prep.restart, its shear.restart.* and series.txt; a finished run's
# log.shear.lammps gives the last step (else series.txt's last row).
#   VARS   the run's own -var settings, as "name value ..." (e.g.
#          VARS="preset quick"); they are not in the restart files
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
rundir=$(cd "${1:?usage: sample_shear_speed.sh RUNDIR [NSTEPS]}" && pwd)
nsteps=${2:-20000}
every=${EVERY:-1}
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

# steps per second of NSTEPS steps from step K on NP ranks
sample() {
  local k=$1 np=$2 dir=$out/np$2.$1 resume=yes
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
  local cmd=("$lmp")
  if [ "$np" -gt 1 ]; then cmd=(mpirun --allow-run-as-root --oversubscribe -np "$np" "$lmp"); fi
  OMP_NUM_THREADS=1 "${cmd[@]}" -in "$inputs/cyclic_shear.lmp" -var inputs "$inputs" \
    -var stage shear -var resume "$resume" -var outdir "$dir" -var max_steps $((k + nsteps)) \
    "${extra[@]}" -log "$dir/log.driver.lammps" -screen none
  # the run is split into segments at every event: sum their loop times
  local loop
  loop=$(awk '/^Loop time/ {t += $4} END {print t}' "$dir/log.shear.lammps")
  rm -rf "$dir"
  awk -v n="$nsteps" -v t="$loop" 'BEGIN {printf "%.1f", n / t}'
}

echo "# $rundir: stage from step 0 to $last (finished: $finished), ${#sel[@]} samples of $nsteps steps"
echo "# step  steps/s(1 core)  steps/s(2 ranks)  ratio"
t1=0
t2=0
for i in "${!sel[@]}"; do
  k=${sel[$i]}
  next=$last
  [ $((i + 1)) -lt ${#sel[@]} ] && next=${sel[$((i + 1))]}
  r1=$(sample "$k" 1)
  r2=$(sample "$k" 2)
  printf "%9d  %8s  %8s  %.2f\n" "$k" "$r1" "$r2" "$(echo "$r2 / $r1" | bc -l)"
  t1=$(echo "$t1 + ($next - $k) / $r1" | bc -l)
  t2=$(echo "$t2 + ($next - $k) / $r2" | bc -l)
done
awk -v a="$t1" -v b="$t2" -v n="$last" 'BEGIN {
  printf "stage of %d steps: %.0f s (%.2f h) on 1 core, %.0f s (%.2f h) on 2 ranks, ratio %.2f\n",
         n, a, a / 3600, b, b / 3600, a / b }'
