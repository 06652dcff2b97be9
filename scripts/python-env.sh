#!/usr/bin/env bash
# The Python of GRFLOW's analysis (analysis/, the package grflow_analysis
# with the commands grflow-figures, grflow-curve and grflow-study): one interpreter that
# imports numpy and matplotlib (Debian's python3-numpy and
# python3-matplotlib), and a venv on it, made with --system-site-packages
# so that it sees them, into which analysis/ is installed offline
# (pip install --no-deps --no-build-isolation --no-index).
#
#   scripts/python-env.sh --which               print the interpreter
#   scripts/python-env.sh [--editable] VENV     make or refresh VENV
#
# The interpreter: $GRFLOW_ANALYSIS_PYTHON if set (it must import numpy
# and matplotlib), else the first python3 on PATH that imports them, else
# /usr/bin/python3 if it does.  scripts/setup.sh and the tests' CMake
# configure (tests/CMakeLists.txt) record the choice in the CMake cache
# (GRFLOW_ANALYSIS_PYTHON) and pass it here, so that the installed venv
# and the tests' venv (build/python, --editable: the working tree's
# analysis/) use the same interpreter.  VENV/grflow-python-env holds what
# VENV was made from; an unchanged VENV is left as it is.
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
check='import numpy, matplotlib'

usage() { echo "usage: $0 --which | [--editable] VENV" >&2; exit 2; }

choose() {
  if [ -n "${GRFLOW_ANALYSIS_PYTHON:-}" ]; then
    "$GRFLOW_ANALYSIS_PYTHON" -c "$check" 2> /dev/null || {
      echo "ERROR: GRFLOW_ANALYSIS_PYTHON=$GRFLOW_ANALYSIS_PYTHON cannot import numpy and" \
        "matplotlib" >&2; return 1; }
    command -v "$GRFLOW_ANALYSIS_PYTHON"
    return 0
  fi
  local py
  for py in $(type -ap python3) /usr/bin/python3; do
    if [ -x "$py" ] && "$py" -c "$check" 2> /dev/null; then
      echo "$py"
      return 0
    fi
  done
  echo "ERROR: no python3 on PATH (nor /usr/bin/python3) imports numpy and matplotlib;" \
    "install python3-numpy and python3-matplotlib (scripts/install-deps.sh)" >&2
  return 1
}

editable=0
case "${1:-}" in
  --which) [ $# -eq 1 ] || usage; choose; exit ;;
  --editable) editable=1; shift ;;
  -*|"") usage ;;
esac
[ $# -eq 1 ] || usage
venv=$1
python=$(choose)

# what the venv is made from: an unchanged one is kept
want="python $python
editable $editable
source $top/analysis
pyproject $(cksum < "$top/analysis/pyproject.toml")"
if [ $editable = 0 ]; then   # a copy: changed sources need a new install
  want="$want
sources $(cat "$top"/analysis/grflow_analysis/*.py | cksum)"
fi
stamp=$venv/grflow-python-env
if [ -x "$venv/bin/python" ] && [ "$(cat "$stamp" 2> /dev/null)" = "$want" ]; then
  exit 0
fi

rm -f "$stamp"
"$python" -m venv --clear --system-site-packages "$venv" || {
  echo "ERROR: $python -m venv failed (on Debian: apt-get install python3-venv)" >&2; exit 1; }
pip=("$venv/bin/python" -m pip install --quiet --no-deps --no-build-isolation --no-index
     --disable-pip-version-check)
if [ $editable = 1 ]; then
  "${pip[@]}" --editable "$top/analysis"
else
  # from a copy: setuptools builds in place and would leave build/ and
  # *.egg-info in the source tree
  tmp=$(mktemp -d)
  trap 'rm -rf "$tmp"' EXIT
  cp -r "$top/analysis/pyproject.toml" "$top/analysis/grflow_analysis" "$tmp/"
  "${pip[@]}" "$tmp"
fi
# the package and its dependencies, from the venv, outside the source tree
(cd / && "$venv/bin/python" -c "import grflow_analysis.figures, grflow_analysis.curve, grflow_analysis.study") || {
  echo "ERROR: grflow_analysis does not import in $venv" >&2; exit 1; }
printf '%s\n' "$want" > "$stamp"
echo "python-env: $venv (on $python): grflow_analysis, $venv/bin/grflow-figures," \
  "$venv/bin/grflow-curve, $venv/bin/grflow-study"
