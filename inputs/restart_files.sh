#!/bin/sh
# The decks' restart files and their checksum files FILE.cksum (one line
# "CRC SIZE NAME" in the format of POSIX cksum: written by fix
# grflow/checksum for the files of the restart command, and by "sum" here
# for those of write_restart).  A file verifies when `cksum FILE` gives the
# CRC and SIZE of its checksum file.  A file whose write was cut short by a
# kill has no checksum file, or one that does not match: it is never read.
#
#   sh restart_files.sh sum FILE
#       write FILE.cksum (through FILE.cksum.tmp and a rename)
#   sh restart_files.sh copy SRC DST
#       copy a verified SRC to DST with its checksum (through DST.tmp)
#   sh restart_files.sh check OUT FILE
#       write the LAMMPS input OUT that sets the string variable
#       restart_file to FILE when FILE verifies or has no checksum file (a
#       file from before checksums: with a note); an error and quit when
#       FILE does not match its checksum or is missing
#   sh restart_files.sh pick OUT DIR PREFIX
#       write the LAMMPS input OUT that sets the string variable
#       restart_file to the file DIR/PREFIX<step> of the largest step that
#       verifies, and prints a line for each newer file it skipped and why;
#       with no file that verifies, an error and quit
#   sh restart_files.sh shear OUT DIR RESUME
#       the file the shear stage starts from: pick OUT DIR shear.restart.
#       when RESUME is yes, else check OUT DIR/prep.restart
# OUT is written through OUT.tmp and a rename.  The decks (LAMMPS and
# LIGGGHTS) run this with shell and include OUT; its error ends with
# ${grflow_quit}, the deck's quit with a non-zero status ("quit 1" in
# LAMMPS, "quit" in LIGGGHTS 3.8).
set -eu

die() { echo "restart_files.sh: $*" >&2; exit 1; }

# the CRC and size cksum gives FILE
sum_of() { cksum < "$1" | awk '{print $1, $2}'; }

# why FILE does not verify, or nothing when it does
problem() {
  if [ ! -f "$1" ]; then echo "missing"; return; fi
  if [ ! -f "$1.cksum" ]; then
    echo "no checksum file $(basename "$1").cksum: its write was cut short, or it was written before GRFLOW wrote checksums"
    return
  fi
  want=$(awk 'NR == 1 {print $1, $2}' "$1.cksum")
  have=$(sum_of "$1")
  [ "$want" = "$have" ] || echo "damaged: CRC and size $have, its checksum file says $want"
}

# write LAMMPS input text to OUT (through OUT.tmp and a rename)
emit() { printf '%s\n' "$2" > "$1.tmp" && mv "$1.tmp" "$1"; }

cmd=${1:-}
case "$cmd" in
  sum)
    f=${2:?usage: restart_files.sh sum FILE}
    [ -f "$f" ] || die "no file $f"
    printf '%s %s\n' "$(sum_of "$f")" "$(basename "$f")" > "$f.cksum.tmp"
    mv "$f.cksum.tmp" "$f.cksum"
    ;;
  copy)
    src=${2:?usage: restart_files.sh copy SRC DST}
    dst=${3:?usage: restart_files.sh copy SRC DST}
    [ -f "$src" ] || die "no file $src"
    # a file from before checksums is copied as it is, and summed
    if [ -f "$src.cksum" ]; then
      why=$(problem "$src")
      [ -z "$why" ] || die "not copying $src: $why"
    fi
    cp "$src" "$dst.tmp" && mv "$dst.tmp" "$dst"
    sh "$0" sum "$dst"
    ;;
  check)
    out=${2:?usage: restart_files.sh check OUT FILE}
    f=${3:?usage: restart_files.sh check OUT FILE}
    why=$(problem "$f")
    if [ -z "$why" ]; then
      emit "$out" "# $f verifies against $(basename "$f").cksum
variable restart_file string $f"
    elif [ -f "$f" ] && [ ! -f "$f.cksum" ]; then
      emit "$out" "print \"GRFLOW: $f has no checksum file (written before GRFLOW wrote checksums?): read unverified\"
variable restart_file string $f"
    else
      emit "$out" "print \"ERROR: GRFLOW: restart file $f is not usable ($why); write it again\"
\${grflow_quit}"
    fi
    ;;
  pick)
    out=${2:?usage: restart_files.sh pick OUT DIR PREFIX}
    dir=${3:?usage: restart_files.sh pick OUT DIR PREFIX}
    prefix=${4:?usage: restart_files.sh pick OUT DIR PREFIX}
    text="" chosen="" tried=""
    steps=$(for f in "$dir/$prefix"*; do
              s=${f#"$dir/$prefix"}
              case $s in '' | *[!0-9]*) continue ;; esac
              echo "$s"
            done | sort -rn)
    for s in $steps; do
      f=$dir/$prefix$s
      why=$(problem "$f")
      if [ -z "$why" ]; then chosen=$f; break; fi
      text="${text}print \"GRFLOW resume: skipped restart file $f: $why\"
"
      tried="$tried $prefix$s"
    done
    if [ -n "$chosen" ]; then
      emit "$out" "${text}variable restart_file string $chosen"
    elif [ -z "$steps" ]; then
      emit "$out" "print \"ERROR: GRFLOW resume: no restart file $dir/$prefix<step> to resume from; run the stage without -var resume yes\"
\${grflow_quit}"
    else
      emit "$out" "${text}print \"ERROR: GRFLOW resume: none of the restart files in $dir verifies (${tried# }); run the stage again without -var resume yes (a file known to be complete can be given its checksum file with: sh restart_files.sh sum FILE)\"
\${grflow_quit}"
    fi
    ;;
  shear)
    out=${2:?usage: restart_files.sh shear OUT DIR RESUME}
    dir=${3:?usage: restart_files.sh shear OUT DIR RESUME}
    if [ "${4:?usage: restart_files.sh shear OUT DIR RESUME}" = yes ]; then
      sh "$0" pick "$out" "$dir" shear.restart.
    else
      sh "$0" check "$out" "$dir/prep.restart"
    fi
    ;;
  *)
    die "usage: restart_files.sh sum|copy|check|pick|shear ..."
    ;;
esac
