#!/usr/bin/env bash
# Does the timestep change the results?  The whole protocol (preparation
# and shear, inputs/cyclic_shear.lmp) for every seed and dt_factor given,
# each run on one core, then grflow-figures on each, and one table of the
# quantities the paper reports (bench/timestep_table.py, on grflow-python;
# both commands: on PATH, else in the build tree, bench/commands.sh).
#   bash bench/timestep_study.sh OUTDIR "SEEDS" "FACTORS" [-var NAME VALUE ...]
# e.g. the quick preset at three timesteps over three seeds:
#   bash bench/timestep_study.sh runs/dt "5827 1 2" "0.1 0.2 0.3" -var preset quick
# Environment: LMP (default build/lmp), CPU (taskset core, default 0;
# with NP=2, mpirun places the ranks).
# Shear stage only, from the preparations of an earlier study:
#   PREP_FROM=runs/dt PREP_FACTOR=0.1 bash bench/timestep_study.sh runs/dt-shear ...
# takes PREP_FROM/s<seed>_f<PREP_FACTOR>/prep.restart (and prep.json) for
# seed <seed>, so that only the shear stage's timestep differs; NP=2 runs
# it on 2 MPI ranks and OMP=2 on 2 OpenMP threads (-sf omp; other
# summation orders: the chaotic scatter).  OUTDIR names the layout, so
# that runs of one seed and timestep in several layouts do not collide.
# A run directory that already has figures/summary.json is not run again.
# The decks are frozen into OUTDIR/inputs at the first call (edits of
# inputs/ during a study do not reach its runs); delete it to refreeze.
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
. "$top/bench/commands.sh"
figures=$(grflow_command grflow-figures)
python=$(grflow_command grflow-python)
out=${1:?usage: timestep_study.sh OUTDIR SEEDS FACTORS [-var ...]}
seeds=${2:?SEEDS}
factors=${3:?FACTORS}
shift 3
lmp=${LMP:-$top/build/lmp}
mkdir -p "$out"
[ -d "$out/inputs" ] || cp -r "$top/inputs" "$out/inputs"
inputs=$(cd "$out/inputs" && pwd)
for seed in $seeds; do
  for f in $factors; do
    dir=$out/s${seed}_f$f
    [ -f "$dir/figures/summary.json" ] && continue
    rm -rf "$dir"
    stage=()
    if [ -n "${PREP_FROM:-}" ]; then
      mkdir -p "$dir/snapshots"
      src=$(cd "$PREP_FROM/s${seed}_f${PREP_FACTOR:-0.1}" && pwd)
      ln -s "$src/prep.restart" "$dir/prep.restart"
      cp "$src/prep.json" "$src/snapshots/atoms.prep.txt" "$dir/" 2> /dev/null || true
      mv "$dir/atoms.prep.txt" "$dir/snapshots/" 2> /dev/null || true
      stage=(-var stage shear)
    fi
    cmd=(taskset -c "${CPU:-0}" "$lmp")
    [ "${NP:-1}" -gt 1 ] && cmd=(mpirun --allow-run-as-root --oversubscribe -np "$NP" "$lmp")
    [ "${OMP:-1}" -gt 1 ] && cmd=("$lmp" -sf omp -pk omp "$OMP")
    start=$(date +%s.%N)
    OMP_NUM_THREADS=${OMP:-1} "${cmd[@]}" -log none -screen none \
      -in "$inputs/cyclic_shear.lmp" -var inputs "$inputs" -var outdir "$dir" \
      -var seed "$seed" -var dt_factor "$f" "${stage[@]}" "$@"
    end=$(date +%s.%N)
    echo "$end - $start" | bc > "$dir/wall_seconds.txt"
    "$figures" "$dir" > "$dir/figures.log" 2>&1
    echo "seed $seed dt_factor $f: $(cat "$dir/wall_seconds.txt") s"
  done
done
"$python" "$top/bench/timestep_table.py" "$out"/s*_f*
