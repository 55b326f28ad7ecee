#!/usr/bin/env bash
# The examples of the chapter "Verify your own integrator" that the CLI suites would otherwise
# run a second time, checked where the book build ran them (book/build_book.cmake: each report,
# its JSON and its standard error in the book's generated directory; the build stops when an
# exit status is not the one the chapter states). The same checks as the suites' cases: the
# stderr line, the report's lines, the JSON verdict. ./build.sh test builds the book first.
# Usage: book_examples.sh path/to/vibook BUILD/book/gen
set -u
V=$1
BOOK_GEN=$2
# shellcheck source=verify_case.sh
source "$(dirname "$0")/verify_case.sh"

# verify_constraint.sh: RATTLE on the spherical and the double pendulum (Cartesian coordinates):
# order 2, both constraints kept to round-off, symplectic on the constraint manifold. The double
# pendulum typed with two --constraint options (the book's example) gives the test problem's
# errors (the test problem run here).
book_case rattle-spherical verify-rattle.txt 0 "" 'order +(1\.9|2\.0)[0-9]* over .*: yes' \
  '^symplectic +on the constraint manifold.*: yes' '^position constraint .*: yes' \
  '^hidden constraint .*: yes'
case_ rattle-double 0 "" 'order +(1\.9|2\.0)[0-9]* over .*: yes' '^hidden constraint .*: yes' \
  -- --method rattle --problem double-pendulum
# The triple jump composed of RATTLE steps (verify_constraint.sh has the other compositions):
# order 4 by its conditions and measured, both constraints kept, symplectic on the manifold.
RATTLE_OK=(order conditions, order, consistency, symplectic, symmetric, time-reversible,
  position constraint, hidden constraint, energy)
book_case rattle-yoshida4 verify-rattle-yoshida4.txt 0 "" 'order 4 by the conditions' \
  'order +(3\.9|4\.0)[0-9]* over .*: yes' '^position constraint .*: yes' \
  '^hidden constraint .*: yes' '^symplectic +on the constraint manifold.*: yes' \
  '^variational order +not measured' "^verdict +PASS \(${RATTLE_OK[*]}\)"
book_case typed-rattle-double verify-constraint-double.txt 0 "" \
  'order +(1\.9|2\.0)[0-9]* over .*: yes' 'constraints g1 = .*, g2 = '
same_errors typed-double-same-errors "$BOOK_GEN/verify-constraint-double.json" "$tmp/v.json" 10
# The trapezoidal L_d's constrained DEL is RATTLE written variationally (HLW VII.5): order 2,
# symmetric, the same errors as RATTLE from another formulation (Newton on (q1, h lambda)
# through L_d's derivatives). Above errors of 1e-6: the DEL form's own rounding, through
# (q1 - q0)/h, differs from RATTLE's by about 1e-11 at the smallest steps.
book_case ld-trapezoid verify-constraint-ld.txt 0 "" 'constrained discrete Euler-Lagrange' \
  'order +(1\.9|2\.0)[0-9]* over .*: yes' 'symmetric .*: yes' '^hidden constraint .*: yes'
same_errors ld-trapezoid-is-rattle "$BOOK_GEN/verify-constraint-ld.json" \
  "$BOOK_GEN/verify-rattle.json" 20 1e-6
# verify_constraint.sh: RATTLE without its velocity projection leaves the hidden constraint and
# fails there, keeping the position constraint; the constrained DEL of V at q1 alone is of order
# 1 and fails when claimed of order 2.
book_case shake-spherical verify-shake.txt 5 "order,symmetric,time-reversible,hidden constraint" \
  '^position constraint .*: yes' '^hidden constraint .*h = 0\.05: [0-9.]+e-0[12].*: NO'
book_case ld-v-at-q1 verify-constraint-ld-v1.txt 5 "order,energy" \
  'order +(0\.9|1\.0)[0-9]* over .*: NO'
# verify_time.sh: the midpoint L_d with the forcing at the step's start time is of order 1.
book_case ld-midpoint-stale verify-time-ld-stale.txt 5 "order,symmetric,time-reversible" \
  'order +(0\.9|1\.0)[0-9]* over .*: NO'
# verify_stepper.sh: Ruth's third-order composition in Python with its pairs swapped is of
# order 2.
book_case py-ruth3-swapped verify-stepper-python.txt 5 "order,energy" \
  'order +(2\.0|1\.9)[0-9]* over .*: NO'

echo "book examples: $pass passed, $fail failed"
[ "$fail" = 0 ]
