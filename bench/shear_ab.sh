#!/usr/bin/env bash
# Side by side: the paper case's shear-stage deck run NSTEPS steps from one
# restart file in several settings (variants), in interleaved rounds, so
# that the machine's changing speed hits all variants alike.  Prints, per
# round and variant, steps per second and where the time went (the LAMMPS
# timing breakdown summed over the deck's run segments, bench/profile_shear.py).
#   bash bench/shear_ab.sh RESTART NSTEPS ROUNDS "NAME|NP|ARGS[|LMP]" ...
# RESTART: a prep.restart or shear.restart.<K> of a run of the paper case.
# Each variant: a name, the number of MPI ranks, extra lmp arguments
# (-var settings, -sf omp -pk omp 2, ...), optionally its own lmp
# binary (e.g. one frozen by bench/timed_case.sh init, whose liblammps.so.0
# sits beside it; empty for the default) and optionally extra mpirun
# arguments (e.g. --bind-to core).  Example:
#   bash bench/shear_ab.sh runs/base/shear.restart.1750000 20000 3 \
#     "base|1|" "check100|1|-var check_every 100"
# Environment: LMP (default build/lmp), INPUTS (default inputs/), OUT
# (scratch, default build/bench/ab), VARS (-var settings of the run that
# wrote RESTART, added to every variant: they are not in restart files).
# profile_shear.py runs on grflow-python: on PATH, else in the build tree
# (bench/commands.sh).
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
. "$top/bench/commands.sh"
python=$(grflow_command grflow-python)
restart=$(realpath "${1:?usage: shear_ab.sh RESTART NSTEPS ROUNDS VARIANT ...}")
nsteps=${2:?NSTEPS}
rounds=${3:?ROUNDS}
shift 3
lmp=${LMP:-$top/build/lmp}
inputs=${INPUTS:-$top/inputs}
out=${OUT:-$top/build/bench/ab}
k=0
resume=no
case "$(basename "$restart")" in
  shear.restart.*) k=${restart##*.}; resume=yes ;;
esac
for round in $(seq 1 "$rounds"); do
  for variant in "$@"; do
    IFS='|' read -r name np args vlmp mpiargs <<< "$variant"
    dir=$out/$name
    rm -rf "$dir" && mkdir -p "$dir/snapshots"
    # the file and its checksum file (the deck resumes only from a file that verifies)
    link=$dir/prep.restart
    [ "$resume" = yes ] && link=$dir/shear.restart.$k
    ln -s "$restart" "$link"
    [ -f "$restart.cksum" ] && ln -s "$restart.cksum" "$link.cksum"
    bin=${vlmp:-$lmp}
    cmd=("$bin")
    # shellcheck disable=SC2206
    [ "$np" -gt 1 ] && cmd=(mpirun --allow-run-as-root --oversubscribe -np "$np" ${mpiargs:-}
                            -x LD_LIBRARY_PATH -x OMP_NUM_THREADS "$bin")
    # shellcheck disable=SC2086
    LD_LIBRARY_PATH=$(dirname "$(realpath "$bin")")${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH} \
    OMP_NUM_THREADS=${OMP_NUM_THREADS:-1} "${cmd[@]}" -in "$inputs/cyclic_shear.lmp" \
      -var inputs "$inputs" -var stage shear -var resume "$resume" -var outdir "$dir" \
      -var max_steps $((k + nsteps)) -var timing yes ${VARS:-} $args \
      -log "$dir/log.driver.lammps" -screen none
    "$python" "$top/bench/profile_shear.py" "$dir/log.shear.lammps" --whole \
      | awk -v r="$round" -v n="$name" '/^# all:/ {print "round " r " " n ": " $0}
                                        /^\| (Pair|Neigh|Comm|Output|Modify|Other|total) / {print "round " r " " n " " $0}'
  done
done
