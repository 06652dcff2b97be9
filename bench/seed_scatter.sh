#!/usr/bin/env bash
# The paper's case for several seeds, each prepared with -var calibrate yes
# (e = 0.647 +- 0.005 whatever the seed), for the seed scatter of e, z_g,
# N_IL and the liquefaction exits (issue 16).  Resumable: run the same
# command again after a stop and every seed continues where it stopped
# (a finished preparation is kept, a shear stage resumes from its newest
# restart file, a finished seed is skipped).  Each seed is a
# bench/timed_case.sh directory DIR/s<seed> (binary and decks frozen at its
# first start, segments timed).
#   bash bench/seed_scatter.sh DIR "SEEDS" NP CPUS [ARGS]
#   bash bench/seed_scatter.sh runs/seeds "1 2 3" 1 1 -var dt_factor_shear 0.3
# ARGS go to both stages.  Environment: as bench/timed_case.sh (BUILD, MPIARGS);
# STAGE=prep stops every seed after its preparation.
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
dir=${1:?usage: seed_scatter.sh DIR "SEEDS" NP CPUS [ARGS]}
seeds=${2:?SEEDS}
np=${3:?NP}
cpus=${4:?CPUS}
shift 4
tc="$top/bench/timed_case.sh"
mkdir -p "$dir"
for s in $seeds; do
  d=$dir/s$s
  [ -x "$d/bin/lmp" ] || bash "$tc" init "$d"
  if [ ! -f "$d/prep.json" ]; then
    echo "seed $s: preparation (calibrate yes) in $d"
    bash "$tc" run "$d" "$np" "$cpus" -var stage prep -var seed "$s" -var calibrate yes "$@" \
      || { echo "seed $s: preparation failed (see $d/log.prep.lammps, $d/calibration.txt)" >&2; continue; }
  fi
  [ "${STAGE:-all}" = prep ] && continue
  if grep -q "^GRFLOW shear: done" "$d/log.shear.lammps" 2> /dev/null; then
    echo "seed $s: done ($(grep "^GRFLOW shear: done" "$d/log.shear.lammps" | tail -1))"
    continue
  fi
  resume=()
  ls "$d"/shear.restart.* > /dev/null 2>&1 && resume=(-var resume yes)
  echo "seed $s: shear stage in $d ${resume[*]}"
  bash "$tc" run "$d" "$np" "$cpus" -var stage shear -var seed "$s" "${resume[@]}" "$@" \
    || echo "seed $s: shear stage stopped (rc $?)" >&2
done
