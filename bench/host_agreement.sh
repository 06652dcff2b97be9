#!/usr/bin/env bash
# The protocol in LAMMPS and in LIGGGHTS over seeds: the quick preset (or
# any -var settings) with each host's decks (inputs/cyclic_shear.lmp,
# inputs/liggghts/cyclic_shear.liggghts), the figures and summary of each
# run (grflow-figures), and one table of the summaries side by side.
# Runs that are complete (figures/summary.json there) are not run again.
#
#   bench/host_agreement.sh OUTDIR "SEEDS" [-var NAME VALUE ...]
#   e.g. bench/host_agreement.sh runs/hosts "1 2 3" -var preset quick
#
# environment: LMP (default build/lmp), LIGGGHTS (default
# build-liggghts/cmake/liggghts), NP=1 MPI ranks per run.  grflow-figures
# and grflow-python: on PATH, else in the build tree (bench/commands.sh).
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
. "$top/bench/commands.sh"
figures=$(grflow_command grflow-figures)
python=$(grflow_command grflow-python)
out=${1:?usage: host_agreement.sh OUTDIR "SEEDS" [-var NAME VALUE ...]}
seeds=${2:?usage: host_agreement.sh OUTDIR "SEEDS" [-var NAME VALUE ...]}
shift 2
lmp=${LMP:-$top/build/lmp}
liggghts=${LIGGGHTS:-$top/build-liggghts/cmake/liggghts}
np=${NP:-1}
mpi=()
[ "$np" -gt 1 ] && mpi=(mpirun --allow-run-as-root --oversubscribe -np "$np")
mkdir -p "$out"
cd "$top"

for s in $seeds; do
  for host in lammps liggghts; do
    dir=$out/${host}_s$s
    [ -f "$dir/figures/summary.json" ] && continue
    if [ $host = lammps ]; then
      cmd=("${mpi[@]}" "$lmp" -in inputs/cyclic_shear.lmp)
    else
      cmd=("${mpi[@]}" "$liggghts" -in inputs/liggghts/cyclic_shear.liggghts)
    fi
    start=$(date +%s)
    "${cmd[@]}" -log none -screen none -var seed "$s" -var outdir "$dir" "$@" \
      || { echo "$host seed $s: the run failed (logs in $dir)"; continue; }
    echo "$host seed $s: $(( $(date +%s) - start )) s" | tee -a "$out/times.txt"
    "$figures" "$dir" > "$dir/figures.log"
  done
done

# the summaries side by side (numbers as analysis/ wrote them)
"$python" - "$out" $seeds <<'PY'
import json, os, sys
out, seeds = sys.argv[1], sys.argv[2:]
keys = [("e_prep", "e"), ("z_g_prep", "z_g after prep"), ("N_IL", "N_IL"),
        ("z_g_at_IL", "z_g at IL"), ("z_g_exit_mean", "exits: mean"),
        ("z_g_exit_std", "exits: sd"), ("n_exits", "exits: count"),
        ("z_g_post_IL_min", "smallest z_g after IL"), ("z_g_post_IL_max", "largest z_g after IL")]
print("| seed | host | " + " | ".join(k[1] for k in keys) + " |")
print("| --- | --- | " + " | ".join("---" for _ in keys) + " |")
for s in seeds:
    for host in ("lammps", "liggghts"):
        path = os.path.join(out, f"{host}_s{s}", "figures", "summary.json")
        if not os.path.exists(path):
            print(f"| {s} | {host} | " + " | ".join("-" for _ in keys) + " |")
            continue
        entries = {e["name"]: e["measured"] for e in json.load(open(path))["entries"]}
        cells = []
        for k, _ in keys:
            v = entries.get(k)
            cells.append("-" if v is None else (f"{v:.4g}" if isinstance(v, float) else str(v)))
        print(f"| {s} | {'LAMMPS' if host == 'lammps' else 'LIGGGHTS'} | " + " | ".join(cells) + " |")
PY
