#!/bin/sh
# GRFLOW LIGGGHTS decks: a string comparison for LIGGGHTS 3.8, whose "if"
# compares numbers only.  Writes DIR/is.NAME.VALUE.WORD1.WORD2... holding
# one line per WORD:
#     variable grflow_is_NAME_WORD equal 1     (VALUE is WORD)
#     variable grflow_is_NAME_WORD equal 0     (otherwise)
# which the deck then includes.  The file's content follows from its name
# alone, so runs that share DIR never disagree about it (it is replaced
# atomically).
#
#   usage (from a deck):
#     shell   sh ${inputs}/liggghts/is.sh ${grflow_cache} stage ${stage} all prep shear
#     include ${grflow_cache}/is.stage.${stage}.all.prep.shear
#     if "${grflow_is_stage_prep} == 1" then ...
#
# VALUE must be one word (a value with blanks reaches this script as more
# words: it is then none of the WORDs, and the deck's include fails).
set -e
[ $# -ge 4 ] || { echo "usage: sh is.sh DIR NAME VALUE WORD..." >&2; exit 1; }
dir=$1 name=$2 value=$3
shift 3
file="$dir/is.$name.$value"
for w in "$@"; do file="$file.$w"; done
mkdir -p "$(dirname "$file")"
tmp=$(mktemp "$file.XXXXXX")
for w in "$@"; do
  if [ "$value" = "$w" ]; then v=1; else v=0; fi
  printf 'variable grflow_is_%s_%s equal %s\n' "$name" "$w" "$v"
done > "$tmp"
mv -f "$tmp" "$file"
