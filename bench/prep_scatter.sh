#!/usr/bin/env bash
# e and z_g after the preparation stage at N = 500 over seeds 1-6, three
# ways (the quick preset; mu_prep 0.0407 without and with the agitation
# stage): the scatter behind the thresholds of tests/python/test_protocol.py
# (doc/studies/prep-scatter.md).  Lines "name seed e z_g p" on stdout;
# 2 runs at a time; the lines come in seed order once all have run.
#   bash bench/prep_scatter.sh [OUT_DIR]     (default runs/escatter)
# Environment: LMP (default build/lmp), SEEDS (default "1 2 3 4 5 6"),
# N (default 500).  prep.json is read by grflow-python: on PATH, else in
# the build tree (bench/commands.sh).
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
. "$top/bench/commands.sh"
export PYTHON
PYTHON=$(grflow_command grflow-python)
export OUT=${1:-$top/runs/escatter} LMP=${LMP:-$top/build/lmp} TOP=$top SIZE=${N:-500}
mkdir -p "$OUT"
job() { # name seed [lmp args]
  local name=$1 seed=$2
  shift 2
  local out=$OUT/$name-s$seed
  "$LMP" -nocite -echo none -log none -screen none -in "$TOP/inputs/cyclic_shear.lmp" \
    -var inputs "$TOP/inputs" -var outdir "$out" -var preset quick -var N "$SIZE" -var stage prep \
    -var seed "$seed" "$@"
  "$PYTHON" -c "import json; d = json.load(open('$out/prep.json')); open('$out/line', 'w').write(f\"$name $seed {d['e']} {d['z_g']} {d['p']}\\n\")"
}
export -f job
for s in ${SEEDS:-1 2 3 4 5 6}; do
  echo "small $s"
  echo "plain $s -var mu_prep 0.0407 -var agitate_dilation 1.0 -var mu_rec 0.25"
  echo "agitated $s -var mu_prep 0.0407 -var agitate_dilation 1.003 -var mu_rec 0.25"
done | xargs -P 2 -L 1 bash -c 'job "$@"' _
# One line per job, printed here in order: two jobs writing to one pipe
# could interleave their pieces.
for s in ${SEEDS:-1 2 3 4 5 6}; do
  for name in small plain agitated; do cat "$OUT/$name-s$s/line"; done
done
