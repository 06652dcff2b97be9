#!/bin/sh
# The shear stage's settings, recorded in DIR/shear.json when the stage
# starts, and checked when it resumes, so that a resume never changes the
# physics of a stage half way (the restart files hold the state, not the
# -var values the stage was started with).
#
#   sh shear_record.sh OUT DIR RESUME STEP KEY=VALUE ...
#       RESUME yes and STEP > 0 (a resume from a restart file written
#       during the stage): every KEY must have the VALUE DIR/shear.json
#       holds (numbers compare as numbers: 0.01 = 1e-2); otherwise OUT is
#       an error naming each key that differs, and quits.  A DIR/shear.json
#       that is missing (a stage started before GRFLOW wrote it) is
#       written now, with a note.
#       Otherwise (a fresh start, or a resume from shear.restart.0, which
#       starts the stage again): DIR/shear.json is written with the values.
#
# shear.json has one "KEY": VALUE per line (VALUE a JSON number when it is
# a number, else a JSON string); grflow-figures reads it.  OUT and
# shear.json are written through OUT.tmp and a rename.  The decks (LAMMPS
# and LIGGGHTS) run this with shell and include OUT; its error ends with
# ${grflow_quit}, the deck's quit with a non-zero status.
set -eu

usage="usage: shear_record.sh OUT DIR RESUME STEP KEY=VALUE ..."
out=${1:?$usage}
dir=${2:?$usage}
resume=${3:?$usage}
step=${4:?$usage}
shift 4
[ $# -gt 0 ] || { echo "shear_record.sh: no KEY=VALUE given" >&2; exit 1; }
record=$dir/shear.json

emit() { printf '%s\n' "$2" > "$1.tmp" && mv "$1.tmp" "$1"; }

# a number as LAMMPS reads one, and one in JSON's stricter form
is_number() {
  awk -v v="$1" 'BEGIN { exit !(v ~ /^[-+]?([0-9]+\.?[0-9]*|\.[0-9]+)([eE][-+]?[0-9]+)?$/) }'
}
is_json_number() {
  awk -v v="$1" 'BEGIN { exit !(v ~ /^-?(0|[1-9][0-9]*)(\.[0-9]+)?([eE][-+]?[0-9]+)?$/) }'
}

write_record() {
  text="{" sep=""
  for kv in "$@"; do
    key=${kv%%=*} value=${kv#*=}
    if is_json_number "$value"; then
      text="$text$sep
  \"$key\": $value"
    else
      text="$text$sep
  \"$key\": \"$value\""
    fi
    sep=","
  done
  emit "$record" "$text
}"
}

# the value KEY has in shear.json (numbers as written, strings unquoted)
recorded() {
  sed -n "s/^ *\"$1\": *\"\{0,1\}\([^\",]*\)\"\{0,1\},\{0,1\} *\$/\1/p" "$record" | head -n 1
}

if [ "$resume" != yes ] || [ "$step" -le 0 ]; then
  write_record "$@"
  emit "$out" "# the settings of the shear stage are in $record"
  exit 0
fi

if [ ! -f "$record" ]; then
  write_record "$@"
  emit "$out" "print \"GRFLOW shear: $record was missing (the stage started before GRFLOW wrote it, or its restart file was copied without it): written with the settings of this resume, which are not checked\""
  exit 0
fi

differ=""
for kv in "$@"; do
  key=${kv%%=*} value=${kv#*=}
  was=$(recorded "$key")
  if is_number "$value" && is_number "$was"; then
    awk -v a="$value" -v b="$was" 'BEGIN { exit !(a + 0 == b + 0) }' && continue
  else
    [ "$value" = "$was" ] && continue
  fi
  differ="$differ${differ:+,} ${key} ${value} (the stage has ${was:-none})"
done
if [ -z "$differ" ]; then
  emit "$out" "# the resume's settings are those of $record"
else
  emit "$out" "print \"ERROR: GRFLOW resume: the shear stage in $dir was started with other settings than this resume gives:$differ; resume with the values of the stage ($record), or start the stage again without -var resume yes\"
\${grflow_quit}"
fi
