#!/usr/bin/env bash
# Time a protocol run that may take hours, be paused and be resumed: the
# binary and decks are frozen into the run directory, and every start,
# pause, resume and end goes to DIR/segments.txt with its epoch seconds.
#   bash bench/timed_case.sh init DIR                 # copy build/lmp, its library, inputs/
#   bash bench/timed_case.sh run DIR NP CPUS [ARGS]   # lmp -in cyclic_shear.lmp ARGS on NP ranks
#                                                   # (CPUS: taskset list for 1 rank; mpirun places ranks)
#   bash bench/timed_case.sh pause DIR | cont DIR     # SIGSTOP / SIGCONT the run, logged
#   bash bench/timed_case.sh total DIR                # wall time of the ended segments minus pauses
# Example, the paper case on 2 ranks, then after a kill:
#   bash bench/timed_case.sh init runs/case
#   bash bench/timed_case.sh run runs/case 1 0 -var stage prep
#   bash bench/timed_case.sh run runs/case 2 0,1 -var stage shear
#   bash bench/timed_case.sh run runs/case 2 0,1 -var stage shear -var resume yes
# A killed segment has no end line and is not counted: the steps it made
# after its last restart file are made again by the resumed one, whose time
# is counted.  Environment: BUILD (default build/).
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
cmd=${1:?usage: timed_case.sh init|run|pause|cont|total DIR ...}
dir=${2:?usage: timed_case.sh $cmd DIR ...}
log() { echo "$1 $(date +%s) $(date -Is)${2:+ $2}" >> "$dir/segments.txt"; }
case "$cmd" in
  init)
    build=${BUILD:-$top/build}
    mkdir -p "$dir/bin" "$dir/snapshots"
    cp "$build/lmp" "$build"/liblammps.so.0 "$dir/bin/"
    rm -rf "$dir/inputs" && cp -r "$top/inputs" "$dir/inputs"
    git -C "$top" rev-parse --short HEAD > "$dir/bin/COMMIT" 2>/dev/null || true
    echo "frozen $(cat "$dir/bin/COMMIT" 2>/dev/null) into $dir"
    ;;
  run)
    np=${3:?NP}
    cpus=${4:?CPUS}
    shift 4
    dir=$(cd "$dir" && pwd)
    [ -x "$dir/bin/lmp" ] || { echo "no $dir/bin/lmp: run init first" >&2; exit 1; }
    export LD_LIBRARY_PATH=$dir/bin OMP_NUM_THREADS=1
    lmpargs=(-in "$dir/inputs/cyclic_shear.lmp" -var inputs "$dir/inputs" -var outdir "$dir"
             -log "$dir/log.driver.lammps" "$@")
    log start "np $np cpus $cpus args: $*"
    rc=0
    if [ "$np" = 1 ]; then
      taskset -c "$cpus" "$dir/bin/lmp" "${lmpargs[@]}" > "$dir/screen.$(date +%s).txt" 2>&1 || rc=$?
    else
      mpirun --allow-run-as-root --oversubscribe -np "$np" \
        -x LD_LIBRARY_PATH -x OMP_NUM_THREADS "$dir/bin/lmp" "${lmpargs[@]}" \
        > "$dir/screen.$(date +%s).txt" 2>&1 || rc=$?
    fi
    log end "rc $rc"
    exit "$rc"
    ;;
  pause | cont)
    pids=$(pgrep -f "$(cd "$dir" && pwd)/bin/lmp" || true)
    [ -n "$pids" ] || { echo "no run in $dir" >&2; exit 1; }
    if [ "$cmd" = pause ]; then kill -STOP $pids; log pause; else kill -CONT $pids; log resume; fi
    ;;
  total)
    awk '$1 == "start" {t0 = $2; p = 0; open = 1}
         $1 == "pause" && open {tp = $2}
         $1 == "resume" && open {p += $2 - tp}
         $1 == "end" && open {n++; w = $2 - t0 - p; sum += w; open = 0
                               printf "segment %d: %d s (%d s paused), %s %s\n", n, w, p, $4, $5}
         END {printf "total: %d s = %.2f h in %d ended segments%s\n", sum, sum / 3600, n,
                     open ? "; one segment still running or killed (not counted)" : ""}' \
      "$dir/segments.txt"
    ;;
  *)
    echo "unknown command $cmd: use init, run, pause, cont or total" >&2
    exit 1
    ;;
esac
