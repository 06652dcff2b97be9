#!/usr/bin/env bash
# Steps per second of the shear deck in LAMMPS and in LIGGGHTS, jammed and
# liquefied: STEPS shear steps on 1 core, resumed from a restart file of a
# finished run of each host (bench/host_agreement.sh makes them:
# OUTDIR/lammps_sS, OUTDIR/liggghts_sS), in copies of the run directory.
# The wall time includes reading the restart file and the setup.
#
#   bench/host_steprate.sh OUTDIR SEED JAMMED_STEP LIQUEFIED_STEP [ROUNDS] [-var NAME VALUE ...]
#   e.g. bench/host_steprate.sh runs/hosts 1 0 400000 2 -var preset quick
#
# Both steps must be steps of restart files of both runs (shear.restart.*),
# the first before initial liquefaction, the second after it (events.txt).
# environment: LMP, LIGGGHTS (as host_agreement.sh), STEPS=20000.
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
usage="usage: host_steprate.sh OUTDIR SEED JAMMED_STEP LIQUEFIED_STEP [ROUNDS] [-var ...]"
out=${1:?$usage} seed=${2:?$usage} jammed=${3:?$usage} liquefied=${4:?$usage}
rounds=${5:-1}
shift 4; [ $# -gt 0 ] && shift
lmp=${LMP:-$top/build/lmp}
liggghts=${LIGGGHTS:-$top/build-liggghts/cmake/liggghts}
steps=${STEPS:-20000}
cd "$top"
echo "host phase start steps wall_s steps_per_s"
for ((r = 1; r <= rounds; r++)); do
  for host in lammps liggghts; do
    for phase in jammed liquefied; do
      start=$jammed; [ $phase = liquefied ] && start=$liquefied
      src=$out/${host}_s$seed
      dst=$(mktemp -d "${TMPDIR:-/tmp}/grflow-steprate.XXXXXX")
      cp -r "$src/prep.json" "$src/series.txt" "$src/events.txt" "$src/snapshots" "$dst/"
      # with its checksum file: the decks resume only from a file that verifies
      cp "$src/shear.restart.$start" "$src/shear.restart.$start.cksum" "$dst/"
      if [ $host = lammps ]; then
        cmd=("$lmp" -in inputs/cyclic_shear.lmp)
      else
        cmd=("$liggghts" -in inputs/liggghts/cyclic_shear.liggghts)
      fi
      t0=$(date +%s.%N)
      "${cmd[@]}" -log none -screen none -var seed "$seed" -var outdir "$dst" -var stage shear \
        -var resume yes -var max_steps $((start + steps)) "$@" > "$dst/out.txt" 2>&1 \
        || { echo "$host $phase: the run failed ($dst)"; continue; }
      t1=$(date +%s.%N)
      awk -v h=$host -v p=$phase -v s=$start -v n=$steps -v a="$t0" -v b="$t1" \
        'BEGIN {printf "%s %s %d %d %.3f %.0f\n", h, p, s, n, b - a, n / (b - a)}'
      rm -rf "$dst"
    done
  done
done
