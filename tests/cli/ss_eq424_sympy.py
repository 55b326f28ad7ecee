#!/usr/bin/env python3
"""Shen & Sun 2025, Theorem 12: is the printed (4.24) the Euler–Lagrange equation of the
printed (4.23)? An independent check in SymPy, outside vibook's engine.

The proof says "with the modified Lagrangian (4.23), the direct calculation provides the
modified equation (4.24)". Both displays are wrong for VI-2 (SS-ERR-4.23, SS-ERR-4.24); this
decides whether (4.24)'s error is its own or inherited from (4.23). The Lagrangian (4.23) is
taken as printed, its Euler–Lagrange equation d/dt ∂L/∂ẋ − ∂L/∂x = 0 solved for ẍ through h²
(ẍ = −∇φ substituted in the h² terms), and compared with the printed (4.24), A₁ and A₂ as
printed after it, exactly in rational arithmetic: for random quartic pieces φ^[1], φ^[2] in two
degrees of freedom (the paper's setting), at random rational states. A copy of (4.24) with one
coefficient changed (12 φ^[1]_xx ∇φ read as 13) must be told apart, so that the check can fail.
Usage: ss_eq424_sympy.py   (exit 0 when (4.24) is the equation of (4.23) and the wrong copy is not)
"""
import random
import sys

import sympy as sp

x1, x2, v1, v2, a1, a2, h = sp.symbols("x1 x2 v1 v2 a1 a2 h")
X, V, A = [x1, x2], [v1, v2], [a1, a2]
d = sp.diff


def quartic(rng):
    return sum(sp.Rational(rng.randint(-9, 9), rng.randint(1, 5)) * x1**i * x2**j
               for i in range(5) for j in range(5) if i + j <= 4)


def hess(f):
    return [[d(f, a, b) for b in X] for a in X]


def quad(f):  # f_xx<v, v>
    H = hess(f)
    return sum(H[i][j] * V[i] * V[j] for i in range(2) for j in range(2))


def cubic(f):  # f_xxx<v, v>, a vector
    return [sum(d(f, X[i], X[j], X[k]) * V[j] * V[k] for j in range(2) for k in range(2))
            for i in range(2)]


def hess_times(f, w):  # f_xx w
    H = hess(f)
    return [H[i][0] * w[0] + H[i][1] * w[1] for i in range(2)]


def defect(p1, p2, point, coefficient=12):
    """EL(printed (4.23)) − printed (4.24) at POINT: [h⁰ coefficient, h² coefficient] per
    component."""
    phi = p1 + p2
    g = [d(phi, x1), d(phi, x2)]
    # (4.23) as printed
    L = (sp.Rational(1, 2) * (v1**2 + v2**2) - phi + h**2 / 96 * (
        7 * (g[0]**2 + g[1]**2) - 12 * d(phi, x2) * d(p1, x2) - 8 * quad(phi) + 12 * quad(p1)
        - 12 * d(p1, x1, 2) * v1**2))

    def ddt(f):
        return sum(d(f, X[i]) * V[i] + d(f, V[i]) * A[i] for i in range(2))

    el = [ddt(d(L, V[i])) - d(L, X[i]) for i in range(2)]
    el = [sp.expand(e.subs(point)) for e in el]
    sol = sp.solve(el, A, dict=True)[0]
    gp = [gi.subs(point) for gi in g]
    acc = [sp.expand(sp.series(sol[a], h, 0, 4).removeO().subs({a1: -gp[0], a2: -gp[1]}))
           for a in A]
    # (4.24) as printed, with A_1, A_2 as printed after it
    A1 = (6 * d(p1, x1, 3) * v1**2 + 12 * d(p1, x1, x1, x2) * v1 * v2
          - 12 * d(p1, x1, 2) * d(phi, x1) - 6 * d(p1, x1, x2) * d(phi, x2)
          - 6 * d(phi, x1, x2) * d(p1, x2))
    A2 = (-6 * d(p1, x1, x1, x2) * v1**2 - 6 * d(p1, x2, 2) * d(phi, x2)
          - 6 * d(phi, x2, 2) * d(p1, x2))
    c3, c31, hg, hg1 = cubic(phi), cubic(p1), hess_times(phi, g), hess_times(p1, g)
    printed = [-g[i] + h**2 / 48 * (4 * c3[i] - hg[i] - 6 * c31[i] + coefficient * hg1[i]
                                    + [A1, A2][i]) for i in range(2)]
    out = []
    for i in range(2):
        diff = sp.expand(acc[i] - printed[i].subs(point))
        out += [diff.coeff(h, 0), diff.coeff(h, 2)]
    return out


def main():
    rng = random.Random(20251128)
    ok = True
    for trial in range(3):
        p1, p2 = quartic(rng), quartic(rng)
        point = {s: sp.Rational(rng.randint(-20, 20), rng.randint(7, 23)) for s in (x1, x2, v1, v2)}
        dev = defect(p1, p2, point)
        same = all(c == 0 for c in dev)
        print(f"trial {trial + 1}: EL(printed (4.23)) - printed (4.24), coefficients of h^0, h^2 "
              f"per component: {dev}: {'identical' if same else 'DIFFERENT'}")
        ok &= same
        wrong = defect(p1, p2, point, coefficient=13)
        told = any(c != 0 for c in wrong)
        print(f"trial {trial + 1}: the copy with 13 for 12: {'told apart' if told else 'NOT told apart'}")
        ok &= told
    print("ss_eq424_sympy: (4.24) is " + ("" if ok else "NOT ") +
          "the Euler-Lagrange equation of (4.23) as printed")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
