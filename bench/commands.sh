# shellcheck shell=bash
# Sourced by the bench scripts (not run): where they find the analysis's
# commands.  One rule (bench/README.md, "The analysis commands"):
#   grflow_command NAME      NAME: grflow-figures, grflow-curve or grflow-python
# prints the path of NAME on PATH (scripts/setup.sh installs the three
# into PREFIX/bin), else that of the build tree's venv
# ${BUILD:-<repository>/build}/python/bin (the CMake configure makes it;
# there grflow-python is the venv's python), else stops with an error.
# The scripts look their commands up before their first run, so that a
# missing one stops them before hours of runs, not after.

grflow_command() {
  local name=$1 found dir
  if found=$(command -v "$name"); then
    echo "$found"
    return 0
  fi
  dir=${BUILD:-$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)/build}/python/bin
  found=$dir/$name
  [ "$name" = grflow-python ] && found=$dir/python
  if [ -x "$found" ]; then
    echo "$found"
    return 0
  fi
  echo "ERROR: $name is neither on PATH (scripts/setup.sh installs it into PREFIX/bin)" \
    "nor in the build tree ($found: configure the build with cmake, or set BUILD)" >&2
  return 1
}
