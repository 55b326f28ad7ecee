#!/usr/bin/env python3
"""Sharma et al. 2022, the inline expansions before (58): an independent check in SymPy, outside
vibook's engine and formula reader.

The paper writes q_{k+-1}(a) = q(a) +- (Da/2) q'(a) + (Da^2/8) q''(a) +- (Da^3/24) q'''(a) + O(Da^4)
(and the same for t), expanding about the midpoint a of the step. This script checks:
  1. the Taylor series of q(a +- Da/2) has Da^3/48 q''' (the Da/2 and Da^2/8 terms as printed);
  2. (58)'s first form, (q_{k+1} - q_k)/Da = q' + Da^2/24 q''' + ..., follows from Da^3/48 and
     not from the printed Da^3/24 (which would give Da^2/12).
Usage: s_i401_sympy.py   (exit 0 when both hold)
"""
import sys

import sympy as sp

a, d = sp.symbols("a Delta_a")
q = sp.Function("q")
ok = True
for sign in (1, -1):
    series = sp.series(q(a + sign * d / 2), d, 0, 4).removeO().doit()
    coeffs = [sp.simplify(series.coeff(d, k) / sp.diff(q(a), a, k)) for k in range(4)]
    want = [1, sp.Rational(sign, 2), sp.Rational(1, 8), sp.Rational(sign, 48)]
    print(f"sign {sign:+d}: coefficients {coeffs} (expected {want})")
    ok = ok and coeffs == want
q3 = sp.Symbol("q3")
for third, expect in ((sp.Rational(1, 48), sp.Rational(1, 24)), (sp.Rational(1, 24), sp.Rational(1, 12))):
    # (q(a + Da/2) - q(a - Da/2))/Da with the given third-order coefficient: its Da^2 q''' term
    got = sp.expand((2 * third * d**3 * q3) / d).coeff(d, 2) / q3
    print(f"with Da^3*{third}: (q_(k+1) - q_k)/Da has Da^2 * {got} q''' (58 needs 1/24)")
    ok = ok and got == expect
print("the inline expansions need Da^3/48: " + ("yes" if ok else "NO"))
sys.exit(0 if ok else 1)
