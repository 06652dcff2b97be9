#!/usr/bin/env bash
# The wall speed's effect on the liquefied state at N = 1000 (quick
# preset: v_x = 0.05 m/s) against other speeds, 3 seeds, 1-core runs two
# at a time, each the whole protocol (the preparation does not depend on
# v_x, so the runs of a seed share their sample to the last bit) with its
# figures and summary; then one table (doc/studies/wall-speed.md, "The wall speed at
# N = 1000").  A thin front end of bench/variants_quick.sh.
#   bash bench/vx_quick.sh [OUT_DIR]   (default runs/vx; LMP: build/lmp; VX: the speeds, default "0.025 0.05"; SEEDS: default "1 2 3")
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
variants=()
for v in ${VX:-0.025 0.05}; do variants+=("v$v|-var v_x $v"); done
exec bash "$top/bench/variants_quick.sh" "${1:-$top/runs/vx}" "${SEEDS:-1 2 3}" "${variants[@]}"
