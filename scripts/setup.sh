#!/usr/bin/env bash
# Set up GRFLOW from a clean clone: Debian packages, the LAMMPS 4Feb2025
# source (Debian's source package, cached), LAMMPS with GRFLOW built in,
# grflowplugin.so and the LAMMPS Python module, installed to /usr/local
# (root) or ~/.local; and the analysis (analysis/, the package
# grflow_analysis) in a venv under that prefix (lib/grflow/python, made by
# scripts/python-env.sh on the Python the CMake configure chose and
# recorded as GRFLOW_ANALYSIS_PYTHON), with its commands grflow-figures,
# grflow-curve and grflow-study linked into the prefix's bin, and grflow-python, that
# venv's Python.  Then checks the
# installed lmp, plugin, module and commands, runs the paper's protocol
# with the quick preset on 2 MPI ranks (runs/quick, about a minute) and
# makes its figures with grflow-figures (runs/quick/figures).
# GRFLOW_SKIP_RUN=1 skips the run.
#
#   scripts/setup.sh [extra cmake -D options]
#   e.g. scripts/setup.sh -D LAMMPS_SOURCE_DIR=$HOME/lammps-4Feb2025
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
cd "$top"
build=${GRFLOW_BUILD_DIR:-$top/build}

scripts/install-deps.sh
cmake -S . -B "$build" -G Ninja -D CMAKE_BUILD_TYPE=Release "$@"
cmake --build "$build" -j "$(nproc)"
cmake --install "$build" > "$build/install.log"
prefix=$(sed -n 's/^CMAKE_INSTALL_PREFIX:PATH=//p' "$build/CMakeCache.txt")
[ "$(id -u)" -eq 0 ] && ldconfig

# the installed pieces, as a user will call them from a new shell
export PATH="$prefix/bin:$PATH"
lmp=$(command -v lmp)
echo "lmp: $lmp"
# (grep without -q reads to the end: with -q it may exit first, lmp then gets
# SIGPIPE and pipefail fails the check at random)
"$lmp" -h | grep "granular/grflow" > /dev/null || { echo "ERROR: $lmp lacks granular/grflow"; exit 1; }
plugin=$prefix/lib/lammps/plugins/grflowplugin.so
printf 'plugin load %s\nplugin list\n' "$plugin" | "$lmp" -log none -nocite 2>&1 \
  | grep "pair style plugin granular/grflow" > /dev/null || { echo "ERROR: cannot load $plugin"; exit 1; }
echo "plugin: $plugin"
# the Python of the analysis, chosen once: the configure's choice (its
# cache), else the same rule (scripts/python-env.sh --which)
python=$(sed -n 's/^GRFLOW_ANALYSIS_PYTHON:FILEPATH=//p' "$build/CMakeCache.txt")
[ -n "$python" ] || python=$(scripts/python-env.sh --which)
pydir=$(sed -n 's/^GRFLOW_PYTHON_INSTALL_DIR:STRING=//p' "$build/CMakeCache.txt")
PYTHONPATH="$prefix/$pydir${PYTHONPATH:+:$PYTHONPATH}" "$python" -c \
  "import lammps; l = lammps.lammps(cmdargs=['-log', 'none', '-screen', 'none']); \
assert l.has_style('pair', 'granular/grflow'); print('python module: lammps', l.version())"
venv=$prefix/lib/grflow/python
GRFLOW_ANALYSIS_PYTHON=$python scripts/python-env.sh "$venv"
for cmd in grflow-figures grflow-curve grflow-study; do
  ln -sf "$venv/bin/$cmd" "$prefix/bin/$cmd"
done
# that Python, for scripts that import grflow_analysis (bench/*.py): a
# wrapper, since a link to a venv's python is not in the venv
printf '#!/bin/sh\nexec "%s" "$@"\n' "$venv/bin/python" > "$prefix/bin/grflow-python"
chmod 755 "$prefix/bin/grflow-python"
"$prefix/bin/grflow-figures" --help > /dev/null || { echo "ERROR: grflow-figures does not run"; exit 1; }
(cd / && "$prefix/bin/grflow-python" -c "import grflow_analysis") \
  || { echo "ERROR: grflow-python does not import grflow_analysis"; exit 1; }
echo "analysis: $prefix/bin/grflow-figures, grflow-curve, grflow-study, grflow-python (Python $python," \
  "grflow_analysis in $venv)"
case "$prefix" in
  /usr/local) ;;
  *) echo "NOTE: add $prefix/bin to PATH and $prefix/$pydir to PYTHONPATH" ;;
esac
echo "GRFLOW is set up."

[ "${GRFLOW_SKIP_RUN:-0}" = 1 ] && exit 0
# the main job: the protocol with the quick preset, then the figures
np=$(( $(nproc) >= 2 ? 2 : 1 ))
echo "running the protocol, quick preset, on $np MPI ranks: runs/quick (log: runs/quick/log.*.lammps)"
rm -rf runs/quick
start=$(date +%s)
mpirun --allow-run-as-root --oversubscribe -np "$np" "$lmp" -log none -screen none \
  -in inputs/cyclic_shear.lmp -var preset quick \
  || { echo "ERROR: the protocol run failed; see runs/quick/log.*.lammps"; exit 1; }
echo "protocol done in $(( $(date +%s) - start )) s"
grep -h "^GRFLOW " runs/quick/log.prep.lammps runs/quick/log.shear.lammps || true
grflow-figures runs/quick
