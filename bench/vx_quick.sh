#!/usr/bin/env bash
# The wall speed's effect on the liquefied state at N = 1000 (quick
# preset: v_x = 0.05 m/s) against half of it, 3 seeds, 1-core runs two at
# a time, each the whole protocol (the preparation does not depend on v_x,
# so each pair shares its sample to the last bit) with its figures and
# summary; then one table (bench/README.md, "The wall speed at N = 1000").
#   bash bench/vx_quick.sh [OUT_DIR]   (default runs/vx; LMP: build/lmp; VX: the speeds, default "0.025 0.05"; SEEDS: default "1 2 3")
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
export OUT=${1:-$top/runs/vx} LMP=${LMP:-$top/build/lmp} TOP=$top
mkdir -p "$OUT"
job() { # seed v_x
  local out=$OUT/s$1_v$2
  rm -rf "$out"
  /usr/bin/time -f "%e" -o "$out.time" "$LMP" -nocite -log none -screen none \
    -in "$TOP/inputs/cyclic_shear.lmp" -var inputs "$TOP/inputs" -var outdir "$out" \
    -var preset quick -var seed "$1" -var v_x "$2"
  /usr/bin/python3 "$TOP/analysis/make_figures.py" "$out" > "$out.figs.log" 2>&1
}
export -f job
for s in ${SEEDS:-1 2 3}; do for v in ${VX:-0.025 0.05}; do echo "$s $v"; done; done |
  xargs -P 2 -L 1 bash -c 'job "$@"' _
/usr/bin/python3 - "$OUT" <<'PY'
import json, os, sys
out = sys.argv[1]
keys = ["e_prep", "N_IL", "n_exits", "z_g_exit_mean", "z_g_post_IL_min", "z_g_post_IL_max",
        "p_min_post_IL", "inertial_max_pre_IL", "inertial_median_post_IL", "inertial_max"]
print("| run | " + " | ".join(keys) + " | wall (s) |")
print("| --- |" + " --- |" * (len(keys) + 1))
for name in sorted(os.listdir(out)):
    f = os.path.join(out, name, "figures", "summary.json")
    if not os.path.isfile(f):
        continue
    e = {x["name"]: x["measured"] for x in json.load(open(f))["entries"]}
    fmt = lambda v: ("%.4g" % v) if isinstance(v, (int, float)) else str(v)
    wall = open(os.path.join(out, name + ".time")).read().split()[-1]
    print("| %s | %s | %s |" % (name, " | ".join(fmt(e.get(k)) for k in keys), wall))
PY
