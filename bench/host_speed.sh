#!/usr/bin/env bash
# GRFLOW's contact law in its two hosts, timed in one go: LAMMPS's
# pair_style granular/grflow against LIGGGHTS's pair_style gran model
# grflow on the same packing, law, shear and settings (hosts/pair_speed.*),
# 1 MPI rank each, in interleaved rounds (LAMMPS, LIGGGHTS, LAMMPS, ...).
# Prints ns per neighbor pair per step of each host's Pair time (fastest
# and slowest round) and their ratio per round.
#
#   bench/host_speed.sh [OUTDIR]       (default build/bench-hosts)
#
# environment: LMP (default build/lmp), LIGGGHTS (default
# build-liggghts/cmake/liggghts), ROUNDS=3, NSTEPS=5000, NWARM=1000.
# The packing is bench/in.prep_packing's packing_compressed.data (8000
# spheres at 1e5 Pa, orthogonal box), made on the first call (minutes).
set -euo pipefail
bench=$(cd "$(dirname "$0")" && pwd)
top=$(cd "$bench/.." && pwd)
out=${1:-$top/build/bench-hosts}
lmp=${LMP:-$top/build/lmp}
liggghts=${LIGGGHTS:-$top/build-liggghts/cmake/liggghts}
rounds=${ROUNDS:-3}
nsteps=${NSTEPS:-5000}
nwarm=${NWARM:-1000}
export OMP_NUM_THREADS=1
mkdir -p "$out"
out=$(cd "$out" && pwd)
cd "$out"

if [ ! -f packing_compressed.data ]; then
  echo "== the packing (bench/in.prep_packing), log: $out/log.prep"
  "$lmp" -in "$bench/in.prep_packing" -var outdir "$out" -log "$out/log.prep" -screen none
fi
# the data file both hosts read: no '# style' comments after section names
sed -E 's/^(Atoms|Velocities)[[:space:]]*#.*/\1/' packing_compressed.data > packing_portable.data

args=(-var data "$out/packing_portable.data" -var nwarm "$nwarm" -var nsteps "$nsteps")
for ((k = 1; k <= rounds; k++)); do
  "$lmp" -in "$bench/hosts/pair_speed.lmp" "${args[@]}" -log "log.lammps.$k" -screen none
  "$liggghts" -in "$bench/hosts/pair_speed.liggghts" "${args[@]}" -log "log.liggghts.$k" -screen none
done

# Pair time, steps and neighbors of the measured run of each log
pair_ns() {
  awk '/GRFLOW_BENCH_BEGIN/ {on = 1}
       on && /^Loop time of/ {for (i = 1; i < NF; i++) if ($i == "for") steps = $(i + 1)}
       on && /^Pair/ {
         if ($2 == "|") pair = $5; else {for (i = 1; i <= NF; i++) if ($i == "=") {pair = $(i + 1); break}}
       }
       on && /^Total # of neighbors/ {nb = $NF}
       /GRFLOW_BENCH_END/ {on = 0}
       END {if (steps > 0 && nb > 0) printf "%.3f %d %d %.4g\n", pair / steps / nb * 1e9, steps, nb, pair}' "$1"
}
echo "round  LAMMPS ns/pair/step  LIGGGHTS ns/pair/step  LIGGGHTS/LAMMPS  (steps, neighbors, Pair s)"
for ((k = 1; k <= rounds; k++)); do
  read -r l ls ln lp < <(pair_ns "log.lammps.$k")
  read -r g gs gn gp < <(pair_ns "log.liggghts.$k")
  printf "%5d  %19s  %21s  %15.3f  (%s, %s/%s, %s/%s)\n" "$k" "$l" "$g" \
    "$(awk -v a="$g" -v b="$l" 'BEGIN {print a / b}')" "$ls" "$ln" "$gn" "$lp" "$gp"
done
