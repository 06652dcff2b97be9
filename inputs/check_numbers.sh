#!/bin/sh
# Used by params.lmp: write the LAMMPS input OUT that stops the run with an
# error naming each parameter whose value is not a number, or that is empty
# when every value is one.  (LAMMPS's own message for a value such as
# -var N abc, "If command boolean can only operate on numbers", does not
# say which parameter.)  A number is what LAMMPS reads as one: an optional
# sign, digits with an optional decimal point, an optional exponent.  The
# error's last line is ${grflow_quit}, which the including deck defines as
# its host's quit with a non-zero status ("quit 1" in LAMMPS; "quit" in
# LIGGGHTS 3.8, whose quit takes no argument).
# OUT's folder (the run's outdir) is made first, parents included.
#   usage: sh check_numbers.sh OUT NAME VALUE [NAME VALUE ...]
set -eu
out=${1:?usage: check_numbers.sh OUT NAME VALUE ...}
shift
mkdir -p "$(dirname "$out")"
bad=""
while [ $# -ge 2 ]; do
  if ! printf '%s\n' "$2" | grep -Eq '^[+-]?([0-9]+[.]?[0-9]*|[.][0-9]+)([eE][+-]?[0-9]+)?$'; then
    bad="$bad$1 '$2', "
  fi
  shift 2
done
[ $# -eq 0 ] || { echo "check_numbers.sh: NAME without VALUE: $1" >&2; exit 1; }
if [ -n "$bad" ]; then
  printf '%s\n%s\n' "print \"ERROR: not a number: ${bad%, } (-var NAME VALUE needs a number here)\"" \
    '${grflow_quit}' > "$out.tmp"
else
  echo "# every numeric parameter is a number" > "$out.tmp"
fi
mv "$out.tmp" "$out"
