#!/usr/bin/env bash
# `vibook figures` run again must give, file for file and byte for byte, the tree the book
# build made. Usage: figures_reproducible.sh path/to/vibook BOOK_FIGURES_DIR
set -u
V=$1 ref=$2
[ -d "$ref" ] || { echo "no reference tree $ref: build the book first (./build.sh test does)"; exit 1; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# Long studies only when the reference has them (./build.sh book runs them, the test build not).
env -u VIBOOK_LONG_STUDIES "$V" figures --out "$tmp/figs" >/dev/null || { echo "vibook figures failed"; exit 1; }
pass=0 fail=0
for d in "$tmp"/figs/*/; do
  id=$(basename "$d")
  if diff -r "$d" "$ref/$id" >"$tmp/diff" 2>&1; then
    pass=$((pass + 1))
  else
    fail=$((fail + 1)); echo "FAIL: figure $id differs between two runs:"; head -5 "$tmp/diff"
  fi
done
# The ledger too: the checks without a figure run again (the figures' results read back, as the
# book build does) must write the book's claims.json byte for byte. The printed comparisons'
# formulas are GiNaC expressions whose shape and signs follow the order symbols were made in,
# which parallel checks change from run to run; this is where that shows.
if [ -f "$ref/../claims.json" ]; then
  # the same source commit as the book's (its provenance; the rest is measured again)
  commit=$(python3 -c 'import json, sys; print(json.load(open(sys.argv[1]))["provenance"]["commit"])' \
    "$ref/../claims.json")
  "$V" claims --json-out "$tmp/claims.json" --figures-dir "$ref" --commit "$commit" >/dev/null 2>&1 &&
    cmp -s "$tmp/claims.json" "$ref/../claims.json" && pass=$((pass + 1)) ||
    { fail=$((fail + 1)); echo "FAIL: claims.json differs from the book build's"; }
fi
# Nothing but the figures' own directories (no temporary ones) is left in the output.
extra=$(find "$tmp/figs" -mindepth 1 -maxdepth 1 -name '.*')
[ -z "$extra" ] && pass=$((pass + 1)) || { fail=$((fail + 1)); echo "FAIL: left behind: $extra"; }
echo "figures reproducible: $pass passed, $fail failed"
[ "$fail" = 0 ]
