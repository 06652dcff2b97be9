#!/bin/bash
# GRFLOW pair benchmark driver.
#
# usage: bench/run_pair_bench.sh [LMP] [OUTDIR]
#   LMP     LAMMPS binary with the GRFLOW and GRANULAR packages
#           (default: <repo>/build/lmp)
#   OUTDIR  output directory (default: <repo>/build/bench)
#
# environment:
#   NSTEPS=10000   measured steps per pair style
#   NWARM=1000     unmeasured warm-up steps per pair style
#   ROUNDS=2       interleaved rounds (A B C A B C ...); each style's fastest
#                  round is reported, which damps the effect of other load
#   PREP=1         remake the packing even if OUTDIR/packing.data exists
# run_pair_bench.py runs on grflow-python: on PATH, else in the build tree
# (bench/commands.sh)
#
# 1. if OUTDIR/packing.data or OUTDIR/packing.vars is missing (or PREP=1),
#    run in.prep_packing (a few minutes) to make the dense sheared packing
# 2. run in.pair_bench: the three pair styles, one after the other, in one
#    LAMMPS process, 1 MPI rank, 1 OpenMP thread
# 3. run_pair_bench.py reads the log, prints the table and writes
#    OUTDIR/pair_bench_results.json

set -euo pipefail

BENCH="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
REPO="$(cd "$BENCH/.." && pwd)"
. "$BENCH/commands.sh"
PYTHON=$(grflow_command grflow-python)

LMP="${1:-$REPO/build/lmp}"
OUTDIR="${2:-$REPO/build/bench}"
NSTEPS="${NSTEPS:-10000}"
NWARM="${NWARM:-1000}"
ROUNDS="${ROUNDS:-2}"
styles=()
for ((k = 0; k < ROUNDS; k++)); do styles+=(grflow granular gran_hooke_history); done

if [ ! -x "$LMP" ]; then
  echo "run_pair_bench.sh: LAMMPS binary $LMP not found or not executable" >&2
  exit 1
fi
LMP="$(cd "$(dirname "$LMP")" && pwd)/$(basename "$LMP")"
mkdir -p "$OUTDIR"
OUTDIR="$(cd "$OUTDIR" && pwd)"

# one MPI rank (no mpirun), one OpenMP thread
export OMP_NUM_THREADS=1

cd "$OUTDIR"    # LAMMPS may write stray files (log.cite) into the cwd

if [ "${PREP:-0}" = "1" ] || [ ! -f packing.data ] || [ ! -f packing.vars ]; then
  echo "== preparing the packing (in.prep_packing), log: $OUTDIR/log.prep"
  start=$(date +%s)
  "$LMP" -in "$BENCH/in.prep_packing" -var outdir "$OUTDIR" \
    -log "$OUTDIR/log.prep" -screen "$OUTDIR/screen.prep" \
    || { echo "preparation failed, see $OUTDIR/log.prep" >&2; exit 1; }
  grep -h "^prepared packing" "$OUTDIR/log.prep" | tail -1
  echo "   ($(( $(date +%s) - start )) s)"
else
  echo "== reusing $OUTDIR/packing.data (PREP=1 to remake it)"
fi

echo "== measuring (in.pair_bench, $NSTEPS steps per style), log: $OUTDIR/log.pair_bench"
start=$(date +%s)
"$LMP" -in "$BENCH/in.pair_bench" -var outdir "$OUTDIR" \
  -var nsteps "$NSTEPS" -var nwarm "$NWARM" -var name "${styles[@]}" \
  -log "$OUTDIR/log.pair_bench" -screen "$OUTDIR/screen.pair_bench" \
  || { echo "benchmark run failed, see $OUTDIR/log.pair_bench" >&2; exit 1; }
echo "   ($(( $(date +%s) - start )) s)"

"$PYTHON" "$BENCH/run_pair_bench.py" "$OUTDIR/log.pair_bench" \
  --json "$OUTDIR/pair_bench_results.json" --lmp "$LMP" \
  --command "bench/run_pair_bench.sh $* (NSTEPS=$NSTEPS NWARM=$NWARM ROUNDS=$ROUNDS)"
