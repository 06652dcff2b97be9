#!/usr/bin/env bash
# Set up LIGGGHTS 3.8.0 with GRFLOW inside, from a clean clone: Debian
# packages (scripts/install-deps.sh), the build (scripts/build-liggghts.sh:
# Debian's source package, our patches, src/shared and src/LIGGGHTS), then
# the executable installed as liggghts to /usr/local/bin (root) or
# ~/.local/bin.  Then checks the installed liggghts: it runs a one-line
# input, and, when src/LIGGGHTS/normal_model_grflow.h is there, pair_style
# gran accepts "model grflow".  The LAMMPS setup (scripts/setup.sh) is
# separate and stays the default.
#
#   scripts/setup-liggghts.sh
#
# GRFLOW_LIGGGHTS_BUILD_DIR: the build directory (default <repo>/build-liggghts);
# GRFLOW_CACHE_DIR: where the source tarball is cached (default ~/.cache/grflow).
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
cd "$top"
build=${GRFLOW_LIGGGHTS_BUILD_DIR:-$top/build-liggghts}

scripts/install-deps.sh
scripts/build-liggghts.sh "$build"

# the executable holds all of LIGGGHTS (its objects, not libliggghts.so), and
# needs only system libraries (MPI, libjpeg): no library to install
if [ "$(id -u)" -eq 0 ]; then prefix=/usr/local; else prefix=$HOME/.local; fi
install -D -m 755 "$build/cmake/liggghts" "$prefix/bin/liggghts"

# the installed executable, as a user will call it from a new shell
export PATH="$prefix/bin:$PATH"
liggghts=$(command -v liggghts)
echo "liggghts: $liggghts"
# (grep without -q reads to the end: with -q it may exit first, liggghts then
# gets SIGPIPE and pipefail fails the check at random)
echo 'print "GRFLOW_LIGGGHTS_HELLO"' | "$liggghts" -log none 2>&1 \
  | grep "^GRFLOW_LIGGGHTS_HELLO" > /dev/null || { echo "ERROR: $liggghts does not run"; exit 1; }

if [ -f src/LIGGGHTS/normal_model_grflow.h ]; then
  out=$("$liggghts" -log none 2>&1 <<'EOF' || true
atom_style granular
atom_modify map array
communicate single vel yes
newton off
boundary p p p
units si
region box block 0 0.01 0 0.01 0 0.01 units box
create_box 1 box
pair_style gran model grflow
print "GRFLOW_MODEL_ACCEPTED"
EOF
)
  if ! grep "^GRFLOW_MODEL_ACCEPTED" > /dev/null <<< "$out"; then
    echo "$out"
    echo "ERROR: pair_style gran does not accept model grflow in $liggghts"
    exit 1
  fi
  echo "pair_style gran: model grflow"
fi
case "$prefix" in
  /usr/local) ;;
  *) echo "NOTE: add $prefix/bin to PATH" ;;
esac
echo "LIGGGHTS with GRFLOW is set up."

# ===========================================================================
# the quick protocol in LIGGGHTS (inputs/liggghts/, inputs/README.md
# "LIGGGHTS"), then its figures, as scripts/setup.sh does for LAMMPS
# ===========================================================================
[ "${GRFLOW_SKIP_RUN:-0}" = 1 ] && exit 0
# grflow-figures as the bench scripts find it: on PATH (scripts/setup.sh
# installs it), else in the build tree (bench/commands.sh); looked up
# before the run
. bench/commands.sh
figures=$(grflow_command grflow-figures)
np=$(( $(nproc) >= 2 ? 2 : 1 ))
echo "running the protocol in LIGGGHTS, quick preset, on $np MPI ranks: runs/quick-liggghts" \
  "(log: runs/quick-liggghts/log.*.lammps)"
rm -rf runs/quick-liggghts
start=$(date +%s)
mpirun --allow-run-as-root --oversubscribe -np "$np" "$liggghts" -log none -screen none \
  -in inputs/liggghts/cyclic_shear.liggghts -var preset quick -var outdir runs/quick-liggghts \
  || { echo "ERROR: the LIGGGHTS protocol run failed; see runs/quick-liggghts/log.*.lammps"; exit 1; }
echo "protocol done in $(( $(date +%s) - start )) s"
grep -h "^GRFLOW " runs/quick-liggghts/log.prep.lammps runs/quick-liggghts/log.shear.lammps \
  | grep -v "^GRFLOW shear: step " || true
"$figures" runs/quick-liggghts
