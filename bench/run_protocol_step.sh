#!/usr/bin/env bash
# Steps per second of the paper case's shear stage: the real deck
# (inputs/cyclic_shear.lmp -var stage shear, 8000 spheres, walls, glue,
# network compute, series, snapshots at events, restart files) run for
# NSTEPS steps from a prepared sample, on 1 core and on 2 MPI ranks, in
# one run of this script.
#   bash bench/run_protocol_step.sh [NSTEPS]        # default 40000
# Environment:
#   PREP  a prep.restart of the paper case (default: $OUT/paper/prep.restart,
#         made here with -var stage prep if missing: about 6 min on 1 core)
#   LMP   lmp binary (default build/lmp); OUT (default build/bench)
#   PAIRS the decks' pair settings to run, in this order (default grflow;
#         "grflow stock" also runs the same deck with stock pair granular,
#         -var pair stock, from the same sample: its contact springs start
#         unstretched, as the restart file holds granular/grflow's history)
#   VARS  extra lmp arguments for every run, the preparation included
#         (e.g. VARS="-var preset quick -var N 100": they are not in
#         restart files, so give a PREP's own settings again)
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
cd "$top"
lmp=${LMP:-$top/build/lmp}
out=${OUT:-$top/build/bench}
nsteps=${1:-40000}
prep=${PREP:-$out/paper/prep.restart}
if [ ! -f "$prep" ]; then
  echo "making the paper case's prepared sample in $out/paper (stage prep, 1 core)"
  mkdir -p "$out/paper"
  # shellcheck disable=SC2086
  "$lmp" -in inputs/cyclic_shear.lmp -var stage prep -var outdir "$out/paper" ${VARS:-} \
    -log "$out/paper/log.driver.lammps" -screen none
  prep=$out/paper/prep.restart
fi
for pair in ${PAIRS:-grflow}; do
for np in 1 2; do
  run="$out/protocol_step.$pair.np$np"
  rm -rf "$run" && mkdir -p "$run"
  cp "$prep" "$run/prep.restart"
  cmd=("$lmp")
  if [ "$np" -gt 1 ]; then cmd=(mpirun --allow-run-as-root --oversubscribe -np "$np" "$lmp"); fi
  start=$(date +%s.%N)
  # shellcheck disable=SC2086
  "${cmd[@]}" -in inputs/cyclic_shear.lmp -var stage shear -var outdir "$run" -var pair "$pair" ${VARS:-} \
    -var max_steps "$nsteps" -log "$run/log.driver.lammps" -screen none
  end=$(date +%s.%N)
  # the stage's run is split into segments at every event: sum their loop times
  loop=$(grep "^Loop time" "$run/log.shear.lammps" | awk '{t += $4} END {print t}')
  events=$(ls "$run/snapshots" | grep -c '^atoms' || true)
  awk -v n="$nsteps" -v t="$loop" -v w="$(echo "$end - $start" | bc)" -v np="$np" -v ev="$events" \
    -v pair="$pair" 'BEGIN { printf "%s, %d rank(s): %d steps, loop time %.1f s = %.0f steps/s (wall %.1f s with setup; %d snapshot pairs)\n", pair, np, n, t, n / t, w, ev }'
done
done
