#!/bin/sh
# GRFLOW LIGGGHTS decks: inputs/params.lmp, the one source of the
# protocol's parameters, in a form LIGGGHTS 3.8 reads.  Called by
# cyclic_shear.liggghts (shell), which then includes OUT.
#
#   usage: sh params.sh IN OUT
#
# LIGGGHTS 3.8 (a 2013 LAMMPS) reads params.lmp as it is except for two
# constructs, which are rewritten here and nothing else:
#   - a string comparison in the condition of "if" or "elif",
#     ${NAME} == WORD or ${NAME} != WORD: LIGGGHTS's "if" compares numbers
#     only ("Invalid Boolean syntax in if command").  Before such an "if"
#     the value of NAME is compared with its WORDs by is.sh (shell), and the
#     result read back (include) as the variables grflow_is_NAME_WORD (1 or
#     0); the condition then tests those: (${grflow_is_NAME_WORD} == 1).
#   - "quit N": LIGGGHTS's quit takes no argument and always exits with
#     status 1, so "quit 1" becomes "quit".
# The output holds LIGGGHTS variables, ${inputs} and ${grflow_cache} (the
# directory of is.sh's files), which the including deck defines: it does
# not depend on any parameter value, only on IN.  Continued lines (&) are
# joined.  A comparison of two variables, one with the word first, or one
# inside a quoted command is left as it is (params.lmp has none).
set -e
[ $# -eq 2 ] || { echo "usage: sh params.sh IN OUT" >&2; exit 1; }
in=$1 out=$2
[ -f "$in" ] || { echo "params.sh: no file $in" >&2; exit 1; }
mkdir -p "$(dirname "$out")"
tmp=$(mktemp "$out.XXXXXX")
awk -v src="$in" '
# split s into words as LAMMPS does: blanks separate them, a word that
# starts with a quote runs to the same quote (quotes kept)
function split_words(s, w,    n, i, c, q, j) {
  n = 0; i = 1
  while (i <= length(s)) {
    c = substr(s, i, 1)
    if (c == " " || c == "\t") { i++; continue }
    if (c == "\"" || c == "\047") {
      q = c; j = i + 1
      while (j <= length(s) && substr(s, j, 1) != q) j++
      w[++n] = substr(s, i, j - i + 1); i = j + 1
    } else {
      j = i
      while (j <= length(s) && substr(s, j, 1) != " " && substr(s, j, 1) != "\t") j++
      w[++n] = substr(s, i, j - i); i = j
    }
  }
  return n
}
function unquote(t) {
  if (t ~ /^".*"$/ || t ~ /^\047.*\047$/) return substr(t, 2, length(t) - 2)
  return t
}
# a condition with its string comparisons replaced; the words compared
# with each variable are collected in seen[] for the lines before the "if"
function rewrite_condition(cond,    out, m, atom, name, op, word, p) {
  out = ""
  while (match(cond, /\$\{[A-Za-z0-9_]+\}[ \t]*[!=]=[ \t]*[A-Za-z_][A-Za-z0-9_]*/)) {
    atom = substr(cond, RSTART, RLENGTH)
    out = out substr(cond, 1, RSTART - 1)
    cond = substr(cond, RSTART + RLENGTH)
    p = index(atom, "}")
    name = substr(atom, 3, p - 3)
    atom = substr(atom, p + 1)
    sub(/^[ \t]*/, "", atom)
    op = substr(atom, 1, 2)
    word = substr(atom, 3)
    sub(/^[ \t]*/, "", word)
    if (!((name, word) in seen)) {
      seen[name, word] = 1
      if (!(name in words)) { names[++nnames] = name; words[name] = "" }
      words[name] = words[name] " " word
    }
    out = out "(${grflow_is_" name "_" word "} == " (op == "==" ? "1" : "0") ")"
  }
  return out cond
}
function quit_without_status(t) {
  if (unquote(t) ~ /^quit[ \t]+[0-9]+$/) return substr(t, 1, 1) "quit" substr(t, 1, 1)
  return t
}
function emit(line,    w, n, k, text, q, j, ws) {
  n = split_words(line, w)
  if (n == 2 && w[1] == "quit" && w[2] ~ /^[0-9]+$/) { print "quit"; return }
  if (n < 3 || w[1] != "if") { print line; return }
  nnames = 0
  split("", names); split("", words); split("", seen)
  for (k = 2; k <= n; k++) {
    if (k == 2 || w[k - 1] == "elif") {
      q = substr(w[k], 1, 1)
      if (q == "\"" || q == "\047") w[k] = q rewrite_condition(unquote(w[k])) q
      else w[k] = rewrite_condition(w[k])
    } else w[k] = quit_without_status(w[k])
  }
  for (j = 1; j <= nnames; j++) {
    ws = words[names[j]]
    gsub(/^ /, "", ws)
    print "shell           sh ${inputs}/liggghts/is.sh ${grflow_cache} " names[j] " ${" names[j] "} " ws
    gsub(/ /, ".", ws)
    print "include         ${grflow_cache}/is." names[j] ".${" names[j] "}." ws
  }
  text = w[1]
  for (k = 2; k <= n; k++) text = text " " w[k]
  print text
}
BEGIN {
  print "# GENERATED from " src " by inputs/liggghts/params.sh for LIGGGHTS 3.8:"
  print "# string comparisons in if/elif tested through is.sh, quit without a"
  print "# status.  Do not edit: it is written anew by every run."
}
{
  raw = $0
  sub(/[ \t\r]+$/, "", raw)
  if (raw ~ /&$/) { buf = buf substr(raw, 1, length(raw) - 1); next }
  line = buf raw; buf = ""
  emit(line)
}
END { if (buf != "") emit(buf) }
' "$in" > "$tmp"
mv -f "$tmp" "$out"
