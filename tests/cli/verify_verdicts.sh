#!/usr/bin/env bash
# `vibook verify` never certifies a wrong method (#24). Each row is a discrete Lagrangian whose
# right answer was worked out by hand: the wrong ones must fail the verdict that should fail,
# with its one-line reason; the right ones (orders 1, 2 and 4, one of them with --h-list
# reaching the round-off plateau) must pass. Each row checks the exit status, lines of the
# text report and the JSON verdict. Usage: verify_verdicts.sh path/to/vibook
set -u
V=$1
export VERIFY_PHASES=1
# shellcheck source=verify_case.sh
source "$(dirname "$0")/verify_case.sh"

SIMPSON='h*((q1-q0)^2/(2*h^2) - (V(q0)+4*V((q0+q1)/2)+V(q1))/6)'
HH='x^2/2+y^2/2+x^2*y-y^3/3'
HHARGS=(--potential "$HH" --q0 0,0.1 --p0 0.35,0 --steps 20000)

# --- wrong discrete Lagrangians: the verdict that should fail does ----------------------------
# Kinetic term doubled (mass 2): inconsistent with the intended L, so no order against the
# reference of L, and an energy of ½|p|² + V far from conserved.
# Its variational order is 0: L_d − L_d^E starts at h^1 with the extra kinetic energy.
case_ "kinetic doubled" 5 "consistency,order,energy,variational order" \
  "consistency .*NO, the kinetic part \(terms in v\) is v1\^2\+v2\^2, expected 1/2\*v1\^2\+1/2\*v2\^2" \
  "order .*: NO" "energy .*: bounded, not O\(h\^p\) \(no trend" \
  "variational order  *0: L_d - L_d\^E = h\^1 \(1/2\*v1\^2\+1/2\*v2\^2\) \+ O\(h\^2\); expected 2: NO; measured -?0\.0[0-9]*: agrees" \
  "verdict  *FAIL \(consistency, order, energy, variational order\)" -- \
  --ld 'h*((q1-q0)^2/h^2 - (V(q0)+4*V((q0+q1)/2)+V(q1))/6)' "${HHARGS[@]}"
# The potential's sign reversed on the pendulum.
case_ "potential sign" 5 "consistency,order,energy,variational order" \
  "consistency .*NO, the part without v \(minus the potential\) is -cos\(x\), expected cos\(x\)" \
  "order .*: NO" "energy .*: bounded, not O\(h\^p\)" -- \
  --ld 'h*((q1-q0)^2/(2*h^2) + (V(q0)+V(q1))/2)' --potential='-cos(x)' --q0 1 --p0 0.5 --steps 4096
# A position-dependent mass typed while the default ½|v|² − V is intended: inconsistent.
PDM='h*( (1+((q0+q1)/2)^2)*((q1-q0)/h)^2/2 - (V(q0)+V(q1))/2 )'
case_ "mass not intended" 5 "consistency,order,energy,variational order" \
  "consistency .*NO, the kinetic part" "variational order  *0: " -- \
  --ld "$PDM" --potential 'x^2/2+y^2/2' --q0 0.3,0.1 --p0 0.2,0.1 --steps 4096
# A first-order method claimed to be second order: the order fails, and so does the energy,
# whose error shrinks like h^1, not h^2, and the variational order (1: the h^2 term of
# L_d − L_d^E does not vanish).
SE='h*( ((q1-q0)/h)^2/2 - V(q1) )'
case_ "order claimed too high" 5 "order,energy,variational order" \
  "order  *1\.0[0-9]* .*expected 2 .*: NO" "energy .*bounded, not O\(h\^p\)" \
  "variational order  *1: L_d - L_d\^E = h\^2 \(.*\); expected 2: NO; measured 1\.0[0-9]*: agrees" -- \
  --ld "$SE" --potential='-cos(x)' --q0 1 --p0 0.5 --h 0.005 --steps 20000
# Simpson's rule on the linear interpolant (the README's example) claimed to be fourth order, as
# Simpson's rule alone would suggest: the linear path limits it to order 2, measured and
# variational (its energy error then shrinks like h^2, not the claimed h^4).
case_ "Simpson claimed order 4" 5 "order,energy,variational order" \
  "order  *(1\.99|2\.00)[0-9]* .*expected 4 .*: NO" \
  "variational order  *2: L_d - L_d\^E = h\^3 \(.*\) \+ O\(h\^4\); expected 4: NO; measured (1\.99|2\.00)[0-9]*: agrees" -- \
  --ld "$SIMPSON" "${HHARGS[@]}" --expected-order 4
# Störmer–Verlet at ωh = 1.98: stable, and its 98 % energy error is bounded and shrinks like
# h^2 from h to h/2. Size is no criterion (chapter, "The criteria of every route"): a correct
# method at a large step passes (the edge; the wrong inputs above fail on the scaling).
case_ "energy at a large step" 0 "" \
  "energy .*h = 1.98.*: bounded \(no trend .*relative error 9.80e-01, shrinking like h\^2.00" -- \
  --ld 'h*(((q1-q0)/h)^2/2 - (V(q0)+V(q1))/2)' --potential 'x^2/2' --q0 1 --p0 0 --h 1.98
# Symplectic Euler declared symmetric: its symmetry and reversibility become part of the
# verdict, and both fail (defects growing like h^2).
case_ "not symmetric" 5 "symmetry,reversibility" "symmetric .*: NO$" "time-reversible .*: NO$" \
  "grows at least like h\^[12]\.[0-9]+" -- \
  --ld "$SE" --potential='-cos(x)' --q0 1 --p0 0.5 --expected-order 1 --h 0.005 --steps 20000 \
  --symmetric

# --- right ones pass -------------------------------------------------------------------------
# Order 2, Simpson on Hénon–Heiles (the README's example), symmetric.
case_ "order 2" 0 "" "order  *(1\.99|2\.00)[0-9]* .*: yes" "symplectic .*: yes" \
  "time-reversible .*: yes$" "energy .*: bounded" "verdict  *PASS" -- \
  --ld "$SIMPSON" "${HHARGS[@]}" --symmetric
# Order 1: symplectic Euler, and its modified Hamiltonian's h^1 term +p sin(x)/2 (for this
# variant, q1 = q0 + h p0, p1 = p0 − h V'(q1); checked by hand against a numerical run).
case_ "order 1" 0 "" "order  *(0\.99|1\.0)[0-9]* .*: yes" "time-reversible .*: NO \(reported only" \
  "variational order  *1: .*expected 1: yes" \
  "H_1 = 1/2\*p1\*sin\(x1\)" "verdict  *PASS" -- \
  --ld "$SE" --potential='-cos(x)' --q0 1 --p0 0.5 --expected-order 1 --h 0.005 --steps 20000
# Order 4 (a modified-potential Störmer–Verlet, the components and grad(V) of the language),
# with --h-list reaching the round-off plateau: the plateau is left out of the fit.
L4='h*( ((q1-q0)/h)^2/2*(1 + h^2/12*(cos(q0[1])+cos(q1[1]))) - (V(q0)+V(q1))/2 - h^2/48*(grad(V)(q0)^2 + grad(V)(q1)^2) )'
case_ "order 4" 0 "" "order  *(3\.9|4\.0)[0-9]* over .*: yes" "points .*--h-list" \
  "variational order  *4: L_d - L_d\^E = h\^5 \(.*\) \+ O\(h\^6\); expected 4: yes; measured (3\.9|4\.0)[0-9]*: agrees" \
  "verdict  *PASS \(consistency, order, symplecticity, energy, variational order\)" -- \
  --ld "$L4" --potential='-cos(x)' --q0 1 --p0 0.5 --expected-order 4 --steps 20000 \
  --h-list 0.2,0.1,0.05,0.025,0.0125,0.00625,0.003125,0.0015625,0.00078125,0.000390625
# Position-dependent mass, the Lagrangian it was meant for: energy is its Legendre transform.
case_ "mass intended" 0 "" "consistency .*: yes" "energy .*Legendre transform of L: bounded" -- \
  --ld "$PDM" --lagrangian '(1+q^2)*v^2/2 - V(q)' --potential 'x^2/2+y^2/2' --q0 0.3,0.1 \
  --p0 0.2,0.1 --steps 20000
# The implicit midpoint rule conserves a quadratic energy to round-off: on the harmonic
# oscillator and on a stiff one (ω = 100, ωh = 5 at the energy test's step), the verdict is
# "conserved to round-off", not a drift of 1e-13.
MID='h*(((q1-q0)/h)^2/2 - V((q0+q1)/2))'
case_ "midpoint harmonic" 0 "" "energy .*: conserved to round-off" -- \
  --ld "$MID" --potential 'x^2/2' --q0 1 --p0 0
case_ "midpoint stiff" 0 "" "energy .*h = 0.05.*: conserved to round-off" -- \
  --ld "$MID" --potential '5000*x^2' --q0 0.1 --p0 0 --h-list 0.002,0.001,0.0005 --t-end 1
# ...with a --h-list that does not resolve ω, the order fails with the hint...
case_ "midpoint stiff, unresolved" 5 "order" "order .*: NO" "^ +\(ω = 100 at q0: ωh runs from 20" -- \
  --ld "$MID" --potential '5000*x^2' --q0 0.1 --p0 0 --steps 4096 \
  --h-list 0.2,0.1,0.05,0.025,0.0125
# ...and the walk of step sizes of every route goes on to where ωh is small: order 2.
case_ "midpoint stiff, the walk" 0 "" "order  *(1\.99|2\.00)[0-9]* over .*: yes" -- \
  --ld "$MID" --potential '5000*x^2' --q0 0.1 --p0 0 --steps 4096

# --- --adaptive epavi: the typed L_d as Sharma et al.'s energy-preserving adaptive integrator ----
# Simpson on Hénon–Heiles: every step exists, the steps adapt, the intended energy is bounded.
case_ "adaptive: Simpson" 0 "" \
  "adaptive \(EpAVI\) +2000 of 2000 steps from h0 = 0.05" "^ +H = \|p\|\^2/2 \+ V\(q\): bounded" \
  "verdict  *PASS \(consistency, order, symplecticity, energy, variational order, adaptive\)" -- \
  --ld "$SIMPSON" "${HHARGS[@]}" --adaptive epavi --adaptive-steps 2000
python3 - "$tmp/v.json" <<'PY' && ok || bad "adaptive: Simpson JSON"
import json, sys
a = json.load(open(sys.argv[1]))["adaptive"]
assert a["steps_taken"] == 2000 and a["passed"] and a["verdict"] == "bounded", a
assert 0 < a["dt_min"] < a["dt_max"] and a["discrete_energy_drift"] < 1e-12, a
PY
# The kinetic term doubled keeps its own discrete energy; the intended one it does not.
case_ "adaptive: kinetic doubled" 5 "consistency,order,energy,variational order,adaptive" \
  "adaptive \(EpAVI\) +2000 of 2000 steps" "^ +H = \|p\|\^2/2 \+ V\(q\): bounded, not O\(h\^p\)" -- \
  --ld 'h*((q1-q0)^2/h^2 - (V(q0)+4*V((q0+q1)/2)+V(q1))/6)' "${HHARGS[@]}" --adaptive epavi \
  --adaptive-steps 2000 --modified-order 0
# The midpoint rule, i.e. EpAVI itself, on a Kepler orbit of eccentricity 0.8 from h0 = 1e-3:
# no admissible step on the way out from perihelion (the EpAVI chapter's finding); the scan
# finds no sign change, so the verdict fails (5), not the solver (3).
case_ "adaptive: no admissible step" 5 "adaptive" \
  "NO ADMISSIBLE STEP at step [0-9]+, t = 0\.[0-9]+: .* has no sign change" -- \
  --ld "$MID" --potential='-1/sqrt(x^2+y^2)' --q0 0.2,0 --p0 0,3 --h 0.001 --t-end 1 \
  --h-list 0.01,0.005,0.0025,0.00125 --steps 4096 --adaptive epavi
python3 - "$tmp/v.json" <<'PY' && ok || bad "adaptive: no admissible step JSON"
import json, sys
a = json.load(open(sys.argv[1]))["adaptive"]
n = a["no_admissible_step"]
assert a["verdict"] == "no admissible step" and not a["passed"], a
assert n["sign_changes"] == 0 and n["scan_points"] > 100 and n["min_abs_residual"] > 0, n
assert a["steps_taken"] == n["step"] - 1, a
PY
# Bad arguments: named, exit 2, before any work.
arg "adaptive: unknown" --adaptive --ld "$MID" --potential 'x^2/2' --adaptive avi
arg "adaptive: steps alone" --adaptive-steps --ld "$MID" --potential 'x^2/2' --adaptive-steps 500
arg "adaptive: too few steps" --adaptive-steps --ld "$MID" --potential 'x^2/2' --adaptive epavi \
  --adaptive-steps 10
arg "adaptive: composition" --adaptive --composition sv --coefficients yoshida4 --adaptive epavi

# --- nothing lost ------------------------------------------------------------------------------
# The symbolic engine fails on an L_d with powers of h below h^1 (|v|^4/h^3-type kinetic term):
# the numerical verdicts are still printed and written, the failure named.
case_ "symbolic failure" 5 "consistency,order,energy" "reference .*GBS" "symplectic .*defect" \
  "modified equation  *FAILED \(error\): the expansion of h\^-1 L_d" -- \
  --ld '(q1-q0)^4/h^3 - h*(V(q0)+V(q1))/2' --potential 'x^2/2+x^4/4' --q0 0.5 --p0 0.3 --steps 2048
python3 - "$tmp/v.json" <<'PY' && ok || bad "symbolic failure: JSON keeps the numerics"
import json, sys
j = json.load(open(sys.argv[1]))
assert j["order"]["h"] and j["symplecticity"]["defect"] >= 0 and j["energy"]["verdict"], j
ph = {p["phase"]: p for p in j["phases"]}
assert ph["modified"]["status"] == "failed" and "h^-1 L_d" in ph["modified"]["reason"], ph
PY
# A step that fails names the phase, step, time and state (exit 3), and past ωh = 2 says so.
"$V" verify --ld 'h*(((q1-q0)/h)^2/2 - (V(q0)+V(q1))/2)' --potential 'sqrt(x)' --q0 1 --p0 0.1 \
  --steps 2048 >"$tmp/out" 2>"$tmp/err"
[ $? = 3 ] && grep -Eq "energy  *FAILED \(numerical\): energy run, h = 0.05: step [0-9]+ at t = [0-9.]+ from q = \(" "$tmp/out" &&
  [ "$(wc -l <"$tmp/err")" = 1 ] && grep -q "^vibook: error: verify: reference: " "$tmp/err" && ok || bad "step failure: $(cat "$tmp/out") $(cat "$tmp/err")"

# The three ways of stepping the typed method give one verdict: native code from the tape (its
# own cache directory here; a cache that cannot be created is refused with one line and the
# object compiled in a private temporary directory), the interpreted tape (VIBOOK_NATIVE=0),
# and nested AutoDiff (--reference). The native and interpreted tapes
# give the same numbers to the bit, so their reports differ in the evaluation line only.
simpson=(--ld 'h*((q1-q0)^2/(2*h^2) - (V(q0)+4*V((q0+q1)/2)+V(q1))/6)'
  --potential 'x^2/2+y^2/2+x^2*y-y^3/3' --q0 0,0.1 --p0 0.35,0 --steps 4096)
VIBOOK_CACHE_DIR="$tmp/cache" "$V" verify "${simpson[@]}" >"$tmp/native" 2>&1
s1=$?
VIBOOK_NATIVE=0 "$V" verify "${simpson[@]}" >"$tmp/interp" 2>&1
s2=$?
VIBOOK_CACHE_DIR=/proc/vibook-no-cache "$V" verify "${simpson[@]}" >"$tmp/nocache" 2>"$tmp/nocache.err"
s3=$?
"$V" verify "${simpson[@]}" --reference >"$tmp/ref" 2>&1
s4=$?
if [ "$s1$s2$s3$s4" = 0000 ] && grep -q "^evaluation  *compiled tape, run as native code" "$tmp/native" &&
  grep -q "^evaluation  *compiled tape, interpreted (no native code: VIBOOK_NATIVE=0)" "$tmp/interp" &&
  grep -q "^evaluation  *compiled tape, run as native code" "$tmp/nocache" &&
  grep -q "^vibook: the tape cache is not used: cannot create /proc/vibook-no-cache; compiling in a private temporary directory$" "$tmp/nocache.err" &&
  grep -q "^evaluation  *nested forward AutoDiff" "$tmp/ref" &&
  diff <(grep -v "^evaluation" "$tmp/native") <(grep -v "^evaluation" "$tmp/interp") >/dev/null &&
  diff <(grep -v "^evaluation" "$tmp/native") <(grep -v "^evaluation" "$tmp/nocache") >/dev/null &&
  grep -q "^verdict  *PASS" "$tmp/ref" && ls "$tmp/cache/tapes/"*.so >/dev/null 2>&1; then ok; else
  bad "native / interpreted / reference: $s1$s2$s3$s4 $(cat "$tmp/native" "$tmp/interp" "$tmp/nocache" | grep -E "evaluation|verdict")"
fi

echo "verify verdicts: $pass passed, $fail failed"
[ "$fail" = 0 ]
