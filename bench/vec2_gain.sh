#!/usr/bin/env bash
# What the contact kernel's two vector lanes buy on the whole shear step
# (issue 40): two lmp binaries of the same commit, one with the lanes
# (the default build) and one with the scalar reference kernel (GRFLOW's
# sources compiled with -D GRFLOW_NO_VEC2), run the real shear deck on 1
# core from one or more states, NSTEPS steps each, in interleaved rounds.
# It builds nothing.  Each run is one call of bench/shear_ab.sh (one
# variant, one round), so the deck, its settings and its timing breakdown
# are exactly those of shear_ab.sh.
#
#   bash bench/vec2_gain.sh LMP_VEC2 LMP_SCALAR ROUNDS "STATE|RESTART|NSTEPS[|VARS]" ...
#   bash bench/vec2_gain.sh build/lmp build-scalar/lmp 5 \
#     "jammed|runs/paper/prep.restart|8000" \
#     "liquefied|runs/fast/shear.restart.900000|30000|-var v_x 0.05 -var tau_amp 60e3"
#
# STATE: a name; RESTART: a prep.restart or shear.restart.<K> of the paper
# case; NSTEPS: steps per run; VARS: the -var settings of the run that
# wrote RESTART (they are not in restart files; shear_ab.sh's VARS).
# Order: in round r every state in turn, the two binaries in the order
# vec2, scalar in odd rounds and scalar, vec2 in even ones, so that a
# drift of the machine's speed and any first-run effect hit both alike.
# Environment: OUT (default build/bench/vec2), PIN (a command put before
# every run, e.g. "taskset -c 1"; default none), LMP etc. as shear_ab.sh.
# Writes OUT/rounds.tsv (one row per run: round, state, variant, steps,
# loop time (the sum of the deck's run segments' "Loop time", wall
# clock), loop CPU time (each segment's loop time times its "% CPU use"),
# Pair time, CPU time of the run's process tree (user + sys,
# /usr/bin/time: lmp with its setup, and profile_shear.py), the 1-minute
# load average before the run) and OUT/shear_ab.log (shear_ab.sh's
# output, with `uptime` before each round); prints the rows and, per
# state, the per-round ratios scalar / vec2 of the loop time, the loop
# CPU time and the process CPU time, with their median, min and max.  On
# a machine that other jobs share, the wall-clock loop time carries the
# time the run waited for a core; the CPU times do not.  A ratio of 1.05
# means the lanes save 4.8% of a step (1 - 1/1.05).
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
. "$top/bench/commands.sh"
python=$(grflow_command grflow-python)
[ $# -ge 4 ] || { sed -n '2,35p' "$0" >&2; exit 2; }
lmp_vec2=$(realpath "$1")
lmp_scalar=$(realpath "$2")
rounds=$3
shift 3
out=${OUT:-$top/build/bench/vec2}
mkdir -p "$out"
tsv=$out/rounds.tsv
log=$out/shear_ab.log
printf 'round\tstate\tvariant\tsteps\tloop_s\tloop_cpu_s\tpair_s\tcpu_s\tload1\n' > "$tsv"
: > "$log"
for round in $(seq 1 "$rounds"); do
  echo "== round $round: $(uptime)" | tee -a "$log"
  for spec in "$@"; do
    IFS='|' read -r state restart nsteps vars <<< "$spec"
    order="vec2 scalar"
    [ $((round % 2)) -eq 0 ] && order="scalar vec2"
    for variant in $order; do
      bin=$lmp_vec2
      [ "$variant" = scalar ] && bin=$lmp_scalar
      load=$(cut -d' ' -f1 /proc/loadavg)
      # shellcheck disable=SC2086
      VARS="$vars" OUT="$out/$state" /usr/bin/time -f '%U %S' -o "$out/time.txt" \
        ${PIN:-} bash "$top/bench/shear_ab.sh" "$restart" "$nsteps" 1 "$variant|1||$bin" >> "$log"
      cpu=$(awk '{print $1 + $2}' "$out/time.txt")
      # the run segments of the deck: steps, loop time and Pair time summed
      awk -v r="$round" -v s="$state" -v v="$variant" -v c="$cpu" -v l="$load" '
        /^Loop time of/ {t += $4; n += $9; last = $4}
        /% CPU use with/ {u += last * $1 / 100}
        /^Pair +\|/ {split($0, f, "|"); p += f[3]}
        END {printf "%d\t%s\t%s\t%d\t%.3f\t%.3f\t%.3f\t%.2f\t%s\n", r, s, v, n, t, u, p, c, l}' \
        "$out/$state/$variant/log.shear.lammps" | tee -a "$tsv"
    done
  done
done
"$python" - "$tsv" <<'EOF'
import statistics, sys
rows = [l.rstrip("\n").split("\t") for l in open(sys.argv[1])][1:]
runs = {(int(r[0]), r[1], r[2]): r for r in rows}
# columns: 4 loop (wall), 5 loop CPU, 7 CPU of the run's processes
measures = (("loop", 4), ("loop CPU", 5), ("process CPU", 7))
for state in dict.fromkeys(r[1] for r in rows):
    rounds = sorted({k[0] for k in runs if k[1] == state})
    print(f"\n{state}: per round, steps/s vec2 | scalar (loop time), "
          "ratios scalar/vec2 of loop time | loop CPU time | process CPU time")
    ratios = {m: [] for m, _ in measures}
    # a time of 0 (a run too short for the clock: LAMMPS's "% CPU use" of
    # a millisecond loop can read 0.0%) gives no ratio; it is said, not
    # divided by
    def ratio(b, a):
        return b / a if a > 0.0 and b > 0.0 else None
    def rate(r):
        return f"{int(r[3]) / float(r[4]):7.1f}" if float(r[4]) > 0.0 else "    n/a"
    for r in rounds:
        a, b = runs[(r, state, "vec2")], runs[(r, state, "scalar")]
        line = []
        for m, col in measures:
            q = ratio(float(b[col]), float(a[col]))
            if q is not None:
                ratios[m].append(q)
            line.append(f"{q:.4f}" if q is not None else "n/a (a time of 0)")
        print(f"  round {r}: {rate(a)} | {rate(b)} steps/s, " + " | ".join(line)
              + f" (load {a[8]}, {b[8]})")
    for m, _ in measures:
        x = ratios[m]
        if not x:
            print(f"  {m} ratio scalar/vec2: no round with both times > 0")
            continue
        med = statistics.median(x)
        print(f"  {m} ratio scalar/vec2: median {med:.4f}, min {min(x):.4f}, max {max(x):.4f}"
              f" over {len(x)} rounds; the lanes save {100 * (1 - 1 / med):.1f}% of a step (median)")
EOF
