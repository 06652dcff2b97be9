#!/usr/bin/env bash
# Time a protocol run that may take hours, be paused and be resumed: the
# binary and decks are frozen into the run directory, and every start,
# pause, resume and end goes to DIR/segments.txt with its epoch seconds.
#   bash bench/timed_case.sh init DIR                 # copy build/lmp, its library, inputs/
#   bash bench/timed_case.sh run DIR NP CPUS [ARGS]   # lmp -in cyclic_shear.lmp ARGS on NP ranks
#                                                   # (CPUS: taskset list for 1 rank; mpirun places ranks)
#   bash bench/timed_case.sh pause DIR | cont DIR     # SIGSTOP / SIGCONT the run, logged
#   bash bench/timed_case.sh total DIR                # wall time of the segments minus pauses
#                                                   # (killed ones: up to the restart file resumed from)
# Example, the paper case on 2 ranks, then after a kill:
#   bash bench/timed_case.sh init runs/case
#   bash bench/timed_case.sh run runs/case 1 0 -var stage prep
#   bash bench/timed_case.sh run runs/case 2 0,1 -var stage shear
#   bash bench/timed_case.sh run runs/case 2 0,1 -var stage shear -var resume yes
# A killed segment has no end line (or one with rc != 0).  The run that
# resumes it (args with "resume yes") first logs the newest
# shear.restart.* file and its time; the killed segment counts up to that
# time (minus its pauses before it), since the steps after it are made
# again.  A segment killed with its wrapper, that nothing resumed, is not
# counted.  Environment: BUILD (default build/); MPIARGS, extra mpirun
# arguments for NP > 1 (logged in segments.txt), e.g.
#   MPIARGS="--mca btl_vader_single_copy_mechanism none"
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
    if [[ " $* " == *" resume yes "* ]]; then
      last=$(ls -t "$dir"/shear.restart.*[0-9] 2> /dev/null | head -n 1 || true)
      [ -n "$last" ] && echo "restartfile $(stat -c %Y "$last") $(date -Is -r "$last") $(basename "$last")" >> "$dir/segments.txt"
    fi
    log start "np $np cpus $cpus${MPIARGS:+ mpirun args: $MPIARGS} args: $*"
    rc=0
    if [ "$np" = 1 ]; then
      taskset -c "$cpus" "$dir/bin/lmp" "${lmpargs[@]}" > "$dir/screen.$(date +%s).txt" 2>&1 || rc=$?
    else
      # shellcheck disable=SC2086
      mpirun --allow-run-as-root --oversubscribe -np "$np" ${MPIARGS:-} \
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
    # pauses are clipped to the end of what counts: the end line, or the
    # restart file a killed segment was resumed from
    awk 'function paused(t,   k, a, b, s) {
           s = 0
           for (k = 0; k in ps; k++) { a = ps[k]; b = (k in pe) ? pe[k] : t
                                      if (b > t) b = t; if (b > a) s += b - a }
           return s }
         function close_segment(t, how,   w, p) {
           p = paused(t); w = t - t0 - p; if (w < 0) w = 0
           n++; sum += w; open = 0
           printf "segment %d: %d s (%d s paused), %s\n", n, w, p, how }
         # a run that failed (rc != 0) stays open until the next line says
         # whether a resume followed it
         $1 == "start" {if (open == 2) close_segment(te, rc); t0 = $2; np = 0
                        delete ps; delete pe; open = 1}
         $1 == "pause" && open == 1 {ps[np] = $2}
         $1 == "resume" && open == 1 {pe[np] = $2; np++}
         $1 == "end" && open == 1 {if ($5 == 0) close_segment($2, $4 " " $5)
                                   else {te = $2; rc = $4 " " $5; open = 2}}
         $1 == "restartfile" && open {t = (open == 2 && te < $2) ? te : $2
                                      close_segment(t, "killed, counted to its restart file " $4)}
         END {if (open == 2) close_segment(te, rc)
              printf "total: %d s = %.2f h in %d segments%s\n", sum, sum / 3600, n,
                     open ? "; one segment still running or killed (not counted)" : ""}' \
      "$dir/segments.txt"
    ;;
  *)
    echo "unknown command $cmd: use init, run, pause, cont or total" >&2
    exit 1
    ;;
esac
