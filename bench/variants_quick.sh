#!/usr/bin/env bash
# One change at a time at N = 1000: the whole protocol (quick preset) for
# each seed and each variant (a name and its -var settings), 1-core runs
# JOBS at a time, each with its figures and summary (grflow-figures); then
# one table of what the paper reports (doc/studies/wall-speed.md,
# doc/studies/rolling-arm.md, doc/studies/preparation-route.md).
#   bash bench/variants_quick.sh OUT_DIR "SEEDS" "NAME|ARGS" ...
#   bash bench/variants_quick.sh runs/arm "1 2 3" "base|" "arm2|-var kr_kn 0.4 -var mu_r 0.2"
# The wall speed (the runs of a seed share their sample to the last bit,
# since the preparation does not depend on v_x; bench/plot_sensitivity.py
# reads runs/vx):
#   bash bench/variants_quick.sh runs/vx "1 2 3" "v0.025|-var v_x 0.025" "v0.05|-var v_x 0.05"
# A run directory OUT_DIR/s<seed>_<name> that has figures/summary.json is
# not run again (delete it to rerun); one without it (a failed run, e.g.
# calibrate yes finding no friction) is run again and has a "failed or
# unfinished" row in the table.  Environment: LMP (default build/lmp),
# JOBS (default 2).  grflow-figures and grflow-python: on PATH, else in
# the build tree (bench/commands.sh).
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
. "$top/bench/commands.sh"
export FIGURES
FIGURES=$(grflow_command grflow-figures)
python=$(grflow_command grflow-python)
export OUT=${1:?usage: variants_quick.sh OUT_DIR SEEDS NAME|ARGS ...} LMP=${LMP:-$top/build/lmp} TOP=$top
seeds=${2:?SEEDS}
shift 2
mkdir -p "$OUT"
job() { # seed name args...
  local out=$OUT/s$1_$2
  [ -f "$out/figures/summary.json" ] && return 0
  rm -rf "$out"
  # shellcheck disable=SC2086
  /usr/bin/time -f "%e" -o "$out.time" "$LMP" -nocite -log none -screen none \
    -in "$TOP/inputs/cyclic_shear.lmp" -var inputs "$TOP/inputs" -var outdir "$out" \
    -var preset quick -var seed "$1" ${3:-}
  "$FIGURES" "$out" > "$out.figs.log" 2>&1
}
export -f job
for s in $seeds; do
  for v in "$@"; do
    IFS='|' read -r name args <<< "$v"
    printf '%s\0%s\0%s\0' "$s" "$name" "$args"
  done
done | xargs -0 -r -P "${JOBS:-2}" -n 3 bash -c 'job "$@"' _ \
  || echo "some runs failed (a preparation that did not converge, calibrate yes that found no friction, ...): their rows say so; see their logs" >&2
"$python" - "$OUT" <<'PY'
import json, os, sys
out = sys.argv[1]
keys = ["e_prep", "z_g_prep", "N_IL", "n_exits", "z_g_exit_mean", "z_g_post_IL_min",
        "z_g_post_IL_max", "p_min_post_IL", "inertial_max_pre_IL", "inertial_median_post_IL",
        "inertial_max"]
print("| run | " + " | ".join(keys) + " | wall (s) |")
print("| --- |" + " --- |" * (len(keys) + 1))
for name in sorted(os.listdir(out)):
    if not os.path.isdir(os.path.join(out, name)):
        continue
    f = os.path.join(out, name, "figures", "summary.json")
    if not os.path.isfile(f):
        print("| %s | failed or unfinished: no figures/summary.json |" % name)
        continue
    e = {x["name"]: x["measured"] for x in json.load(open(f))["entries"]}
    fmt = lambda v: ("%.4g" % v) if isinstance(v, (int, float)) else str(v)
    wall = open(os.path.join(out, name + ".time")).read().split()[-1]
    print("| %s | %s | %s |" % (name, " | ".join(fmt(e.get(k)) for k in keys), wall))
PY
