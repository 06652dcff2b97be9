#!/bin/sh
# Used by shear.lmp when a killed shear stage resumes from a restart file
# written at step STEP: keep the comment lines of FILE and its rows with
# step < STEP (the resumed run writes step STEP and later again).
# usage: sh trim_series.sh FILE STEP
set -e
[ -f "$1" ] || exit 0
awk -v s="$2" '/^#/ || ($1 + 0 < s + 0)' "$1" > "$1.tmp"
mv "$1.tmp" "$1"
