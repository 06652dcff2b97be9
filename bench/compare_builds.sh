#!/usr/bin/env bash
# Two builds of GRFLOW on the same protocol run, compared byte for byte: a
# refactor that claims to change no result keeps a frozen binary of the
# commit before it and runs this.  Each binary runs the decks (LAMMPS:
# inputs/cyclic_shear.lmp; with --liggghts: inputs/liggghts/
# cyclic_shear.liggghts) with the quick preset at N = 500, one cycle after
# initial liquefaction, a series row every 50 steps and a restart file
# every 5000 steps, on NP MPI ranks, in OUTDIR/a and OUTDIR/b; then every
# output file is compared with cmp: prep.json, shear.json, series.txt,
# events.txt, the restart files and their checksum files, the snapshots.
# The logs are not compared (they hold timings); generated inputs that
# name the run directory are compared with its path left out.  Extra arguments go to
# both runs (e.g. -var normal_force clipped).  Exit status 0 if all are
# identical, 1 if any differs (each named), 2 if a run failed.
#
#   bench/compare_builds.sh [--liggghts] [-np NP] BIN_A BIN_B OUTDIR [-var name value ...]
#
# e.g. (the binary of a commit before the change in /tmp/frozen):
#   bench/compare_builds.sh -np 2 /tmp/frozen/build/lmp build/lmp /tmp/cmp
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)

deck=$top/inputs/cyclic_shear.lmp
np=1
while [ $# -gt 0 ]; do
  case "$1" in
    --liggghts) deck=$top/inputs/liggghts/cyclic_shear.liggghts; shift ;;
    -np) np=$2; shift 2 ;;
    *) break ;;
  esac
done
[ $# -ge 3 ] || { sed -n '2,19p' "$0" >&2; exit 2; }
bin_a=$1 bin_b=$2 out=$3
shift 3

run() {
  local bin=$1 dir=$2
  shift 2
  rm -rf "$dir"
  mkdir -p "$dir"
  local mpi=()
  [ "$np" -gt 1 ] && mpi=(mpirun --allow-run-as-root --oversubscribe -np "$np")
  (cd "$top" && "${mpi[@]}" "$bin" -log none -screen none -in "$deck" -var inputs "$top/inputs" \
     -var preset quick -var N 500 -var n_post 1 -var series_every 50 -var restart_every 5000 \
     -var outdir "$dir" "$@") > "$dir.out" 2>&1 || {
    echo "ERROR: $bin failed (see $dir.out)" >&2
    tail -n 20 "$dir.out" >&2
    exit 2
  }
}

run "$bin_a" "$out/a" "$@"
run "$bin_b" "$out/b" "$@"

differ=0 same=0
while IFS= read -r rel; do
  case "$rel" in log.*|*.out) continue ;; esac
  if [ ! -f "$out/b/$rel" ]; then
    echo "only in a: $rel"
    differ=$((differ + 1))
  elif cmp -s "$out/a/$rel" "$out/b/$rel"; then
    same=$((same + 1))
  elif cmp -s <(sed "s|$out/a|RUN|g" "$out/a/$rel") <(sed "s|$out/b|RUN|g" "$out/b/$rel"); then
    same=$((same + 1))    # the same but for the run directory's path (generated inputs)
  else
    echo "differs: $rel"
    differ=$((differ + 1))
  fi
done < <(cd "$out/a" && find . -type f | sed 's|^\./||' | LC_ALL=C sort)
while IFS= read -r rel; do
  case "$rel" in log.*|*.out) continue ;; esac
  [ -f "$out/a/$rel" ] || { echo "only in b: $rel"; differ=$((differ + 1)); }
done < <(cd "$out/b" && find . -type f | sed 's|^\./||' | LC_ALL=C sort)

echo "compare_builds: $same files identical, $differ different ($(basename "$deck"), $np rank(s))"
[ "$differ" -eq 0 ]
