#!/usr/bin/env bash
# The engine's modified Lagrangian of Störmer–Verlet for a generic potential against an
# independent derivation in SymPy (tests/bench/sympy_lmod.py: the modified equation from the
# discrete Euler–Lagrange equation, no jets, the meshed Lagrangian along its flow), term by
# term, in 1, 2 and 3 degrees of freedom; and a deliberately wrong coefficient that must be
# told apart.
# Usage: modified_sympy.sh path/to/vibook path/to/sympy_lmod.py
set -u
V=$(realpath "$1")
S=$(realpath "$2")
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
pass=0 fail=0
for c in "1 10" "2 6" "3 4"; do
  set -- $c
  "$V" modified --method sv --potential generic --dim "$1" --order "$2" --what lagrangian \
    --format python > "$tmp/L.py" || { fail=$((fail + 1)); echo "FAIL: vibook modified --dim $1 --order $2"; continue; }
  if /usr/bin/python3 "$S" "$1" "$2" --compare "$tmp/L.py"; then pass=$((pass + 1))
  else fail=$((fail + 1)); echo "FAIL: --dim $1 --order $2: the engine and SymPy differ"; fi
done
# The h^2 coefficient of U_11 v1^2 is -1/12 (Vermeeren (23)); -1/11 must be told apart.
"$V" modified --method sv --potential generic --dim 1 --order 4 --what lagrangian --format python |
  sed 's|Rational(-1, 12)\*U_11\*v1\*\*2|Rational(-1, 11)*U_11*v1**2|' > "$tmp/wrong.py"
if grep -q 'Rational(-1, 11)' "$tmp/wrong.py" && ! /usr/bin/python3 "$S" 1 4 --compare "$tmp/wrong.py" 2>/dev/null
then pass=$((pass + 1))
else fail=$((fail + 1)); echo "FAIL: a wrong coefficient was not told apart"; fi
echo "modified_sympy: $pass passed, $fail failed"
[ "$fail" = 0 ]
