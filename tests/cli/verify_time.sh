#!/usr/bin/env bash
# #52: time-dependent systems (t in --lagrangian, --potential, --hamiltonian and --ld): the state
# carries the clock; a method that evaluates the forcing at the right times passes at its order,
# the same method with the time advanced by the wrong coefficient fails the order on the forced
# system and passes on the autonomous one; the energy of a time-dependent system is not judged;
# a route that does not step time-dependent systems refuses t by name (exit 2).
# Usage: verify_time.sh path/to/vibook path/to/forced_stepper.py
#        path/to/vibook_forced_steppers.so path/to/vibook_odeint_steppers.so
set -u
V=$1
STEPPER=$2
FORCED_LIB=$3
ODEINT_LIB=$4
# shellcheck source=verify_case.sh
source "$(dirname "$0")/verify_case.sh"

# A Galerkin method on a typed L(q, v, t): the forced oscillator (the issue's case, linear) and
# the forced pendulum (nonlinear), Gauss 2 at order 4
case_ gauss2-forced-oscillator 0 "" 'order +(3\.9|4\.0)[0-9]* over .*: yes' \
  'L\(q, v, t\)' '^energy +not judged: H depends on t' \
  '^verdict +PASS' \
  -- --method gauss:2 --lagrangian 'v^2/2 - q^2/2 + q*cos(t)' --q0 0.5 --p0 0 --expected-order 4
case_ gauss2-forced-pendulum 0 "" 'order +(3\.9|4\.0)[0-9]* over .*: yes' \
  'time-reversible .*: yes' \
  -- --method gauss:2 --lagrangian 'v^2/2 + cos(q) + q*cos(t)/2' --q0 0.5 --p0 0 --symmetric
case_ lobatto3-forced-potential 0 "" 'order +(3\.9|4\.0)[0-9]* over .*: yes' \
  'H\(q, p, t\)' -- --method lobatto:3 --potential 'x^2/2 - x*cos(t)' --q0 0.5 --p0 0

# A tableau on V(q, t) or H(q, p, t): the time a position of the extended system, stage i at
# t + c_i h (c the row sums of a). Gauss 2 and Lobatto IIIA-IIIB 3 keep their order 4.
TAB="$(dirname "$STEPPER")/../tableaus"
case_ tableau-gauss2-forced 0 "" 'order +(3\.9|4\.0)[0-9]* over .*: yes' \
  '^energy +not judged: H depends on t' \
  -- --tableau "$TAB/gauss2.json" --potential='-cos(x) - x*cos(t)/2' --q0 0.5 --p0 0 --symmetric
case_ tableau-lobatto3-forced-h 0 "" 'order +(3\.9|4\.0)[0-9]* over .*: yes' \
  -- --tableau "$TAB/lobatto3-iiia-iiib.json" --hamiltonian 'p^2/2*(1+q^2/4) - cos(q) - q*cos(t)/2' \
  --q0 0.5 --p0 0

# The midpoint rule as a typed L_d(t, q0, q1, h): the forcing at the midpoint's time t + h/2 is of
# order 2; at the step's start time t (the time advanced with the wrong coefficient) of order 1.
MID='h*(((q1-q0)/h)^2/2 + cos((q0+q1)/2) + (q0+q1)/2*cos(t+h/2)/2)'
STALE='h*(((q1-q0)/h)^2/2 + cos((q0+q1)/2) + (q0+q1)/2*cos(t)/2)'
case_ ld-midpoint 0 "" 'L_d\(t, q0, q1, h\)' 'order +(1\.9|2\.0)[0-9]* over .*: yes' \
  'symmetric .*: yes' \
  -- --ld "$MID" --potential='-cos(x) - x*cos(t)/2' --q0 0.5 --p0 0 --symmetric
# (the stale one alone, of order 1, is the book's example: checked in book_examples.sh)

# A composition of a typed L_d(t, q0, q1, h): each stage starts at the time the stages before it
# reached (the partial sums of the coefficients), the adjoint stage is -L_d(t + h, q1, q0, -h).
# Yoshida's fourth-order composition of the forced midpoint rule keeps order 4 and its symmetry;
# of the stale one (forcing at t), whose base is neither symmetric nor of order 2 on the forced
# system, it is of order 1 by its own order conditions and measured so.
case_ composition-ld-forced 0 "" 'L_d\(t, q0, q1, h\) = .*symmetric: L_d\(t, q0, q1, h\) \+ L_d\(t \+ h' \
  'order +(3\.9|4\.0)[0-9]* over .*: yes' 'symmetric .*: yes' \
  -- --composition ld --coefficients yoshida4 --ld "$MID" --potential='-cos(x) - x*cos(t)/2' \
  --q0 0.5 --p0 0 --symmetric
case_ composition-ld-stale 5 "order conditions,order,symmetric,time-reversible" \
  'order +(0\.9|1\.0)[0-9]* over .*: NO' \
  -- --composition ld --coefficients yoshida4 --ld "$STALE" --potential='-cos(x) - x*cos(t)/2' \
  --q0 0.5 --p0 0 --symmetric --expected-order 4

# A splitting on V(q, t): the drifts carry the time (the extended Hamiltonian's T + p_t), the
# kicks read it. Forest-Ruth keeps its order 4 and its symmetry on the forced pendulum; the
# variant with its last half drift moved to the front fails there as on autonomous systems.
case_ splitting-forest-ruth-forced 0 "" 'order +(3\.9|4\.0)[0-9]* over .*: yes' \
  'V\(q, t\)' 'time-reversible .*: yes' \
  -- --splitting forest-ruth --potential='-cos(x) - x*cos(t)/2' --q0 0.5 --p0 0
case_ splitting-moved-forced 5 "order conditions,order" 'order +(0\.9|1\.0)[0-9]* over .*: NO' \
  -- --splitting "drift:1/(2-2^(1/3)),kick:1/(2-2^(1/3)),drift:(1-2^(1/3))/(2*(2-2^(1/3))),kick:-2^(1/3)/(2-2^(1/3)),drift:(1-2^(1/3))/(2*(2-2^(1/3))),kick:1/(2-2^(1/3))" \
  --potential='-cos(x) - x*cos(t)/2' --q0 0.5 --p0 0 --expected-order 4

# A Python stepper over line protocol 2 on the forced pendulum; its variant whose second half
# kick reads the force at the step's start time fails there, and passes on the autonomous one.
FORCED='p^2/2 - cos(q) - q*cos(t)/2'
case_ python-sv-forced 0 "" '\(line protocol 2\)' 'order +(1\.9|2\.0)[0-9]* over .*: yes' \
  -- --stepper-cmd "python3 $STEPPER sv forced-pendulum" --stepper-protocol 2 \
  --hamiltonian "$FORCED" --q0 0.5 --p0 0 --expected-order 2 --symmetric
case_ python-stale-forced 5 "order,symmetric,time-reversible" \
  'order +(0\.9|1\.0)[0-9]* over .*: NO' \
  -- --stepper-cmd "python3 $STEPPER sv_stale forced-pendulum" --stepper-protocol 2 \
  --hamiltonian "$FORCED" --q0 0.5 --p0 0 --expected-order 2 --symmetric
case_ python-stale-autonomous 0 "" 'order +(1\.9|2\.0)[0-9]* over .*: yes' \
  -- --stepper-cmd "python3 $STEPPER sv_stale pendulum" --stepper-protocol 2 \
  --hamiltonian 'p^2/2 - cos(q)' --q0 0.5 --p0 0 --expected-order 2 --symmetric

# The same two steppers in C, a library of the C ABI's version 2 (vibook_stepper_step_t)
case_ lib-sv-forced 0 "" '\(vibook stepper ABI 2\)' 'order +(1\.9|2\.0)[0-9]* over .*: yes' \
  -- --stepper-lib "$FORCED_LIB" --stepper-arg sv --hamiltonian "$FORCED" --q0 0.5 --p0 0 \
  --expected-order 2 --symmetric
case_ lib-stale-forced 5 "order,symmetric,time-reversible" \
  'order +(0\.9|1\.0)[0-9]* over .*: NO' \
  -- --stepper-lib "$FORCED_LIB" --stepper-arg sv_stale --hamiltonian "$FORCED" --q0 0.5 \
  --p0 0 --expected-order 2 --symmetric

# Refusals, by name, before any work
# a library of ABI version 1 has no time argument
arg lib-version-1-with-t --stepper-lib --stepper-lib "$ODEINT_LIB" --stepper-arg \
  symplectic_euler/pendulum --hamiltonian "$FORCED" --expected-order 1
arg protocol-1-with-t --stepper-protocol --stepper-cmd "python3 $STEPPER sv forced-pendulum" \
  --hamiltonian "$FORCED" --expected-order 2
arg protocol-3 --stepper-protocol --stepper-cmd "python3 $STEPPER sv pendulum" \
  --stepper-protocol 3 --hamiltonian 'p^2/2 - cos(q)' --expected-order 2
# an L_d in t on a system without it (the system must carry its own time dependence)
arg composition-ld-only-t --ld --composition ld --coefficients yoshida4 \
  --ld 'h*((q1-q0)/h)^2/2 - h*t*q0^2' --potential 'x^2'
arg ld-only-t --ld --ld 'h*((q1-q0)/h)^2/2 - h*cos(q0)*t' --potential='-cos(x)'
arg ld-calls-timed-v --ld --ld 'h*((q1-q0)/h)^2/2 - h*V(q0)' --potential 'x^2/2 - x*cos(t)'
arg ld-timed-adaptive --adaptive --ld "$MID" --potential='-cos(x) - x*cos(t)/2' --adaptive epavi
"$V" modified --order 2 --ld 'h*((q1-q0)/h)^2/2 - h*t*q0^2' >"$tmp/out" 2>"$tmp/err"
if [ $? = 2 ] && grep -q -- '--ld: uses the time t' "$tmp/err"; then ok; else
  bad "modified with t: $(cat "$tmp/err")"; fi

echo "verify_time: $pass passed, $fail failed"
[ "$fail" = 0 ]
