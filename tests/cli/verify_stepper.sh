#!/usr/bin/env bash
# `vibook verify --stepper-lib / --stepper-cmd`: other programs' steppers judged as black boxes
# against Hamilton's equations of the system they are meant for. Boost.Odeint's symplectic
# steppers (through the C ABI) and Python steppers (through the line protocol) meet their
# documented orders; the deliberately wrong ones fail the verdict that should fail (explicit
# Euler and an eighth-order Runge-Kutta method: symplecticity; a composition with base and
# adjoint swapped: order; odeint's velocity Verlet without reset, whose map depends on the
# previous call: symplecticity); a stepper that fails mid-run exits 3 with one line; bad
# arguments exit 2 before any work; two runs write the same bytes.
# Usage: verify_stepper.sh path/to/vibook path/to/vibook_odeint_steppers.so path/to/stepper.py
set -u
V=$1 LIB=$2 PY=$3
# shellcheck source=verify_case.sh
source "$(dirname "$0")/verify_case.sh"

# --- Boost.Odeint through the C ABI ---------------------------------------------------------
case_ odeint-mclachlan4 0 "" 'library .*mclachlan4/kepler' 'order +(3\.9|4\.0)[0-9]* over .*: yes' \
  '^verdict +PASS' -- --stepper-lib "$LIB" --stepper-arg mclachlan4/kepler --problem kepler \
  --expected-order 4
case_ odeint-m4-hh 0 "" 'order +(3\.9|4\.0)[0-9]* over .*: yes' \
  -- --stepper-lib "$LIB" --stepper-arg mclachlan4_m4/henon-heiles --problem henon-heiles \
  --expected-order 4
case_ odeint-euler 0 "" 'order +(1\.0|0\.9)[0-9]* over .*: yes' \
  '^energy +bounded over 100000 steps of h = 0\.05: no trend' \
  -- --stepper-lib "$LIB" --stepper-arg symplectic_euler/pendulum --problem pendulum \
  --expected-order 1
case_ odeint-verlet 0 "" 'time-reversible .*: yes' \
  -- --stepper-lib "$LIB" --stepper-arg velocity_verlet/kepler --expected-order 2 --symmetric
# odeint's header brief calls sb3a_mclachlan "sixth order": the measurement says 4
case_ odeint-mclachlan4-as-6 5 "order,energy" 'expected 6 .*: NO' \
  -- --stepper-lib "$LIB" --stepper-arg mclachlan4/kepler --expected-order 6
case_ explicit-euler 5 "symplectic,energy" 'symplectic +defect .*: NO' \
  -- --stepper-lib "$LIB" --stepper-arg explicit_euler/pendulum --problem pendulum \
  --expected-order 1
# odeint's Runge-Kutta-Fehlberg 7(8): order 8, not symplectic; its defect at h = 0.05 (4e-11)
# is below what a single size could call a defect, but it is resolved at 4h and 8h and grows
# like h^(p+1). (--order-tol 0.5: a black box is measured in double only, where its fit reads
# 8.32, pre-asymptotic, as the report's line says; this case is about the symplecticity verdict.)
case_ rk78 5 "symplectic,energy" 'h = 0\.2: [0-9.]+e-0[5-7],.*: NO$' \
  'grows at least like h\^[4-9]\.[0-9]+' \
  '^ +in double only \(the method has no step in double-double\): from order 6 on' \
  -- --stepper-lib "$LIB" --stepper-arg rk78/kepler --expected-order 8 --order-tol 0.5
# odeint's velocity Verlet called without reset carries the previous force from call to call:
# its map is not a function of the state alone, its Jacobian cannot be measured (difference
# quotients at two increments disagree in the first digits), and symplecticity says NO.
case_ verlet-cached 5 "order,symplectic,symmetric,time-reversible,energy" \
  'symplectic +defect .*: NO' 'the Jacobian cannot be measured' \
  -- --stepper-lib "$LIB" --stepper-arg velocity_verlet_cached/kepler --expected-order 2 \
  --symmetric

# --- Python through the line protocol ---------------------------------------------------------
case_ py-sv 0 "" "command 'python3 .*' \(line protocol 1\)" '^verdict +PASS' \
  -- --stepper-cmd "python3 $PY sv pendulum" --problem pendulum --expected-order 2 --symmetric \
  --steps 8192
case_ py-yoshida4 0 "" 'order +(3\.9|4\.0)[0-9]* over .*: yes' \
  -- --stepper-cmd "python3 $PY yoshida4 kepler" --expected-order 4 --steps 4096
case_ py-ruth3 0 "" 'order +(3\.0|2\.9)[0-9]* over .*: yes' \
  -- --stepper-cmd "python3 $PY ruth3 pendulum" --problem pendulum --expected-order 3 \
  --steps 4096
# (ruth3 with its pairs swapped, of order 2: the book's example, checked in book_examples.sh)
case_ py-euler 5 "symplectic,energy" 'symplectic +defect .*: NO' \
  -- --stepper-cmd "python3 $PY euler pendulum" --problem pendulum --expected-order 1 \
  --steps 4096
# --hamiltonian names the system instead of --problem
case_ py-hamiltonian 0 "" 'H = p\^2/2 - cos\(q\[1\]\) \(--hamiltonian\)' \
  -- --stepper-cmd "python3 $PY sv pendulum" --hamiltonian 'p^2/2 - cos(q[1])' --q0 1 --p0 0.5 \
  --expected-order 2 --steps 4096

# Work against precision beside vibook's own Störmer–Verlet and RK4 on the same system: the
# Python Störmer–Verlet gives vibook's Störmer–Verlet errors (relative 1e-9), and McLachlan's
# fourth-order method from Boost.Odeint does not (its errors are 1e3 times smaller at every
# step size); with --timings each run's seconds are added, and the RK4 column is order 4.
"$V" verify --stepper-cmd "python3 $PY sv pendulum" --problem pendulum --expected-order 2 \
  --steps 2048 --json-out "$tmp/wp1.json" >"$tmp/wp1.out" 2>&1
"$V" verify --stepper-lib "$LIB" --stepper-arg mclachlan4/kepler --expected-order 4 --timings \
  --json-out "$tmp/wp2.json" >"$tmp/wp2.out" 2>&1
python3 - "$tmp/wp1.json" "$tmp/wp2.json" <<'PY' && grep -q "^work-precision  *steps" "$tmp/wp1.out" && ok ||
import json, math, sys
a, b = (json.load(open(f))["work_precision"] for f in sys.argv[1:3])
m = a["methods"]
assert set(m) == {"black_box", "stormer_verlet", "rk4"} and len(a["h"]) == 5, a
for x, y in zip(m["black_box"]["error"], m["stormer_verlet"]["error"]):
    assert abs(x - y) <= 1e-9 * y, (x, y)
assert "seconds" not in m["black_box"], m
n = b["methods"]
for x, y in zip(n["black_box"]["error"], n["stormer_verlet"]["error"]):
    assert x < 1e-3 * y, (x, y)
assert all(len(n[k]["seconds"]) == 5 and min(n[k]["seconds"]) > 0 for k in n), n
e, h = n["rk4"]["error"], b["h"]
slope = math.log(e[0] / e[3]) / math.log(h[0] / h[3])
assert abs(slope - 4) < 0.2, slope
PY
  bad "work-precision: $(grep -A5 '^work-precision' "$tmp/wp1.out" "$tmp/wp2.out")"

# A stepper that fails mid-run: status 3, one stderr line naming the part, the step and state.
"$V" verify --stepper-cmd "python3 $PY refuse pendulum" --problem pendulum --expected-order 2 \
  --h 0.005 --h-list 0.02,0.01,0.005 --steps 2048 >"$tmp/out" 2>"$tmp/err"
got=$?
if [ "$got" = 3 ] && [ "$(wc -l <"$tmp/err")" = 1 ] &&
   grep -q "order: .*steps of h = 0.02 from q = (1), p = (0.5): the stepper answered 'error': step" "$tmp/err" &&
   grep -Eq '^verdict +FAIL' "$tmp/out"; then
  ok
else
  bad "refuse: exit $got: $(cat "$tmp/err")"
fi

# Bad arguments (arg, verify_case.sh): exit 2, one line naming the argument, nothing on stdout.
L=(--stepper-lib "$LIB" --stepper-arg mclachlan4/kepler)
arg both --stepper-lib "${L[@]}" --stepper-cmd 'cat' --expected-order 4
arg no-order --expected-order "${L[@]}"
arg no-file --stepper-lib --stepper-lib ./no-such-stepper.so --expected-order 2
arg not-a-library --stepper-lib --stepper-lib "$PY" --expected-order 2
arg bad-create --stepper-lib --stepper-lib "$LIB" --stepper-arg rk45/kepler --expected-order 2
arg wrong-dof --stepper-lib --stepper-lib "$LIB" --stepper-arg mclachlan4/kepler \
  --problem pendulum --expected-order 4
arg with-ld --ld "${L[@]}" --expected-order 4 --ld 'h*((q1-q0)^2/(2*h^2))' --potential x
arg problem --problem "${L[@]}" --expected-order 4 --problem double-pendulum
arg cmd-arg --stepper-arg --stepper-cmd cat --stepper-arg x --expected-order 2
arg q0-length --q0 "${L[@]}" --expected-order 4 --q0 1,2,3
arg order-range --expected-order "${L[@]}" --expected-order 21
arg exits --stepper-cmd --stepper-cmd 'exit 3' --expected-order 2
arg garbage --stepper-cmd --stepper-cmd "python3 $PY garbage pendulum" --problem pendulum \
  --expected-order 2
arg silent --stepper-cmd --stepper-cmd 'sleep 5' --stepper-timeout 0.3 --expected-order 2
arg both-systems --hamiltonian "${L[@]}" --expected-order 4 --problem kepler \
  --hamiltonian 'p^2/2'

# Two runs write the same bytes (report and JSON), through either route.
for r in lib cmd; do
  if [ $r = lib ]; then a=("${L[@]}" --expected-order 4)
  else a=(--stepper-cmd "python3 $PY sv pendulum" --problem pendulum --expected-order 2 --steps 2048); fi
  "$V" verify "${a[@]}" --json-out "$tmp/a.json" >"$tmp/a.out" 2>&1
  "$V" verify "${a[@]}" --json-out "$tmp/b.json" >"$tmp/b.out" 2>&1
  if cmp -s "$tmp/a.json" "$tmp/b.json" && cmp -s "$tmp/a.out" "$tmp/b.out"; then ok
  else bad "reproducible ($r)"; fi
done

echo "verify_stepper: $pass passed, $fail failed"
[ "$fail" = 0 ]
