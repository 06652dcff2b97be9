#!/bin/sh
# GRFLOW LIGGGHTS shear stage (shear_loop.liggghts), after a run segment
# with a cycle event and at the end of the stage: files the snapshots of
# the segment's last step and moves what the segments left in their
# scratch files of the run directory DIR to the documented files.  One
# call per event: a shell from LIGGGHTS costs a fork of the whole process.
#
#   usage: sh events.sh DIR [STEP LX LY]
#
#   STEP LX LY          the snapshots of step STEP (the box lengths in full):
#                       DIR/snapshots/atoms.STEP.txt and contacts.raw.STEP
#                       become the documented files (snapshot.sh)
#   DIR/events.pending  one line per check of fix grflow/shear (fix print:
#                       step time event reversals N N_IL step_IL); the
#                       lines of events (event != 0) are appended to
#                       DIR/events.txt
#   DIR/log.shear.segments  LIGGGHTS's log while the segments run (each
#                       segment prints a thermo header and line and a loop
#                       time); the progress lines of fix grflow/shear and
#                       any warning are appended to DIR/log.shear.lammps
# Both scratch files are then emptied (LIGGGHTS keeps them open for
# appending, so it goes on writing at their new end).
set -e
[ $# -eq 1 ] || [ $# -eq 4 ] || { echo "usage: sh events.sh DIR [STEP LX LY]" >&2; exit 1; }
dir=$1
here=$(dirname "$0")
if [ $# -eq 4 ]; then
  sh "$here/snapshot.sh" atoms "$dir/snapshots/atoms.$2.txt"
  sh "$here/snapshot.sh" contacts "$dir/snapshots/contacts.raw.$2" "$dir/snapshots/contacts.$2.txt" "$3" "$4"
fi
if [ -f "$dir/events.pending" ]; then
  awk 'NF >= 7 && $1 !~ /^#/ && $3 != 0' "$dir/events.pending" >> "$dir/events.txt"
  : > "$dir/events.pending"
fi
if [ -f "$dir/log.shear.segments" ]; then
  grep -a -E '^(grflow/shear |WARNING|ERROR)' "$dir/log.shear.segments" >> "$dir/log.shear.lammps" || true
  : > "$dir/log.shear.segments"
fi
