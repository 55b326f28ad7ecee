#!/usr/bin/env bash
# The examples of the chapter "Verify your own integrator" that the CLI suites would otherwise
# run a second time, checked where the book build ran them (book/build_book.cmake: each report,
# its JSON and its standard error in the book's generated directory; the build stops when an
# exit status is not the one the chapter states). The same checks as the suites' cases: the
# stderr line, the report's lines, the JSON verdict. ./build.sh test builds the book first.
# Usage: book_examples.sh BUILD/book/gen
set -u
BOOK_GEN=$1
# shellcheck source=verify_case.sh
source "$(dirname "$0")/verify_case.sh"

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
