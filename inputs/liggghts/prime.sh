#!/bin/sh
# GRFLOW LIGGGHTS decks: a random-number seed that LIGGGHTS 3.8 accepts (a
# prime above 10000) made from the protocol's seed: the smallest prime
# >= 10000 + SEED.  Writes DIR/prime.SEED holding
#     variable grflow_prime equal P
# which the deck then includes (the content follows from the name alone).
#
#   usage: sh prime.sh DIR SEED
set -e
[ $# -eq 2 ] || { echo "usage: sh prime.sh DIR SEED" >&2; exit 1; }
dir=$1 seed=$2
case "$seed" in
  ''|*[!0-9]*) echo "prime.sh: seed $seed is not a whole number >= 0" >&2; exit 1 ;;
esac
p=$((10000 + seed))
# factor prints "n: n" for a prime
while [ "$(factor "$p" | cut -d' ' -f2-)" != "$p" ]; do p=$((p + 1)); done
mkdir -p "$dir"
tmp=$(mktemp "$dir/prime.$seed.XXXXXX")
printf 'variable grflow_prime equal %s\n' "$p" > "$tmp"
mv -f "$tmp" "$dir/prime.$seed"
