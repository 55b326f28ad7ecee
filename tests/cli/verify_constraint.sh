#!/usr/bin/env bash
# #52: constrained mechanical systems. RATTLE on the test problems and on constraints typed after
# --constraint (H = |p|^2/2 + V with --potential), the constrained discrete Euler-Lagrange
# equations of a typed --ld, a Python RATTLE as a black box; the deliberately wrong inputs fail
# the part they break, the edges pass; bad arguments are refused by name before any work (exit
# 2). The cases that are the book's examples are checked in book_examples.sh.
# Usage: verify_constraint.sh path/to/vibook path/to/examples/black_box/rattle_stepper.py
set -u
V=$1
RATTLE_PY=$2
# shellcheck source=verify_case.sh
source "$(dirname "$0")/verify_case.sh"

# #52: constraints. RATTLE on the spherical and the double pendulum (Cartesian coordinates),
# shake (RATTLE without its velocity projection), the double pendulum typed with two
# --constraint options, and the constrained DEL of the trapezoidal L_d (RATTLE written
# variationally) and of V at q1 alone claimed of order 2 are the book's examples, or compared
# with them: book_examples.sh checks them where the book build ran them. Here: the bad
# arguments of the test problems, and the first-order edge.
arg rattle-off-manifold --q0 --method rattle --q0 1,0,0.1
arg rattle-not-tangent --p0 --method rattle --q0 1,0,0 --p0 1,0,0
arg rattle-unconstrained --problem --method rattle --problem kepler
arg rattle-potential --potential --method rattle --potential 'x^2'

# Constraints typed as expressions, and the constrained DEL of a typed --ld: with V at q1 alone
# it is of order 1, and passes, at the first-order edge, when claimed of order 1.
SPH_Q=0.8414709848078965,0,-0.5403023058681398
SPH_G='(x^2+y^2+z^2-1)/2'
TRAP='h*((q1-q0)^2/(2*h^2) - (V(q0)+V(q1))/2)'
SE='h*((q1-q0)^2/(2*h^2) - V(q1))'
# --report is checked before any work on this route too (a regular file is no report directory).
: >"$tmp/not-a-dir"
arg ld-constraint-report --report --ld "$TRAP" --potential z --constraint "$SPH_G" \
  --q0 "$SPH_Q" --p0 0,0.8,0 --report "$tmp/not-a-dir"
case_ ld-v-at-q1-first-order 0 "" 'order +(0\.9|1\.0)[0-9]* over .*: yes' \
  '^position constraint .*: yes' '^hidden constraint .*: yes' \
  -- --ld "$SE" --potential z --constraint "$SPH_G" --q0 "$SPH_Q" --p0 0,0.8,0 --expected-order 1

# A black box stepping a constrained system (a Python RATTLE over line protocol 1): measured
# with the typed constraints' reference, residuals and manifold symplecticity; its unprojected
# variant fails the hidden constraint.
case_ blackbox-rattle 0 "" 'order +(1\.9|2\.0)[0-9]* over .*: yes' \
  '^system +H = p\^2/2 \+ V\(q\) \(--potential\), 3 degrees of freedom, constraints g1 = ' \
  '^symplectic +on the constraint manifold.*: yes' '^hidden constraint .*: yes' \
  -- --stepper-cmd "python3 $RATTLE_PY rattle" --potential z --constraint "$SPH_G" \
  --q0 "$SPH_Q" --p0 0,0.8,0 --expected-order 2 --symmetric --steps 4096
case_ blackbox-shake 5 "order,symmetric,time-reversible,hidden constraint" \
  '^hidden constraint .*: NO' \
  -- --stepper-cmd "python3 $RATTLE_PY shake" --potential z --constraint "$SPH_G" \
  --q0 "$SPH_Q" --p0 0,0.8,0 --expected-order 2 --symmetric --steps 4096
arg blackbox-constraint-hamiltonian --hamiltonian --stepper-cmd "python3 $RATTLE_PY rattle" \
  --hamiltonian 'p^2/2 + q[3]' --constraint "$SPH_G" --q0 "$SPH_Q" --p0 0,0.8,0 \
  --expected-order 2
arg blackbox-constraint-off --q0 --stepper-cmd "python3 $RATTLE_PY rattle" --potential z \
  --constraint "$SPH_G" --q0 1,0,0.1 --p0 0,0.8,0 --expected-order 2

# Bad arguments, each named before any work.
arg constraint-off-manifold --q0 --method rattle --potential z --constraint "$SPH_G" \
  --q0 1,0,0.1 --p0 0,0.8,0
arg constraint-not-tangent --p0 --method rattle --potential z --constraint "$SPH_G" \
  --q0 "$SPH_Q" --p0 0.1,0.8,0
arg constraint-no-q0 --q0 --method rattle --potential z --constraint "$SPH_G"
arg constraint-time --constraint --method rattle --potential z --constraint 'x^2+y^2+z^2-t' \
  --q0 "$SPH_Q" --p0 0,0.8,0
arg constraint-constant --constraint --method rattle --potential z --constraint '1' \
  --q0 "$SPH_Q" --p0 0,0.8,0
arg constraint-too-many --constraint --method rattle --potential z --constraint x --constraint y \
  --constraint z --q0 0,0,0 --p0 0,0,0
arg constraint-dim --dim --method rattle --potential x --constraint x-y --q0 1,1 --p0 1,-1 --dim 5
arg constraint-galerkin --constraint --method gauss:2 --potential z --constraint "$SPH_G"
arg constraint-tableau --constraint --tableau x.json --constraint "$SPH_G"
arg constraint-splitting --constraint --splitting leapfrog --constraint "$SPH_G"
arg constraint-no-potential --potential --method rattle --constraint "$SPH_G" --q0 "$SPH_Q" \
  --p0 0,0.8,0
arg constraint-ld-lagrangian --lagrangian --ld "$TRAP" --lagrangian 'v^2/2' \
  --constraint "$SPH_G" --q0 "$SPH_Q" --p0 0,0.8,0
arg constraint-ld-adaptive --adaptive --ld "$TRAP" --potential z --adaptive epavi \
  --constraint "$SPH_G" --q0 "$SPH_Q" --p0 0,0.8,0
arg constraint-empty --constraint --method rattle --potential z --constraint ' ' --q0 "$SPH_Q" \
  --p0 0,0.8,0

# Compositions of RATTLE (the chapter's "Compositions of RATTLE"): the triple jump reaches order
# 4 on both test problems and keeps both constraints; the edge, Yoshida's sixth order, measured
# in double; the wrong input, the triple jump with its middle coefficient's sign flipped, is not
# consistent and fails on its conditions and its order while each stage keeps the constraints.
# (The triple jump on the spherical pendulum is the book's example: book_examples.sh.)
case_ rattle-yoshida4-double 0 "" 'order +(3\.9|4\.0)[0-9]* over .*: yes' \
  '^hidden constraint .*: yes' -- --composition rattle --coefficients yoshida4 \
  --problem double-pendulum
case_ rattle-yoshida6 0 "" 'order +(5\.[89]|6\.[01])[0-9]* over .*: yes' 'in double only' \
  -- --composition rattle --coefficients yoshida6 --problem spherical-pendulum
case_ rattle-yoshida4-typed 0 "" 'order +(3\.9|4\.0)[0-9]* over .*: yes' \
  'V = z \(--potential\), constraints g1 = \(x\^2\+y\^2\+z\^2-1\)/2' \
  -- --composition rattle --coefficients yoshida4 --potential z --constraint "$SPH_G" \
  --q0 "$SPH_Q" --p0 0,0.8,0
case_ rattle-flipped 5 "order conditions,order,consistency,energy" \
  'order 0 by the conditions.*NO' '^position constraint .*: yes' '^hidden constraint .*: yes' \
  -- --composition rattle --expected-order 4 --problem spherical-pendulum \
  --coefficients 1.35120719195965763405,1.70241438391931526810,1.35120719195965763405 \
  --h-list 0.1,0.05,0.025,0.0125
arg composition-constraint-sv --constraint --composition sv --coefficients yoshida4 \
  --potential z --constraint "$SPH_G" --q0 "$SPH_Q" --p0 0,0.8,0
arg composition-rattle-unconstrained --constraint --composition rattle --coefficients yoshida4
arg composition-rattle-kepler --problem --composition rattle --coefficients yoshida4 \
  --problem kepler
arg composition-rattle-both --problem --composition rattle --coefficients yoshida4 \
  --problem spherical-pendulum --potential z --constraint "$SPH_G"
arg composition-rattle-ld --ld --composition rattle --coefficients yoshida4 \
  --problem spherical-pendulum --ld "$TRAP"
arg composition-rattle-off --q0 --composition rattle --coefficients yoshida4 --potential z \
  --constraint "$SPH_G" --q0 1,0,0.1 --p0 0,0.8,0

echo "verify_constraint: $pass passed, $fail failed"
[ "$fail" = 0 ]
