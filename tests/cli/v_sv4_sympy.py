#!/usr/bin/env python3
"""Vermeeren 2017, §5.1.2: the h^4 term of Stormer-Verlet's modified equation in one and two
degrees of freedom. An independent check in SymPy, outside vibook's engine and formula reader.

The recurrence x(t+h) - 2x(t) + x(t-h) = -h^2 U'(x(t)) expanded in h along a solution of the
modified equation x'' = F = F0 + h^2 F2 + h^4 F4 gives x'' + h^2/12 x'''' + h^4/360 x^(6) + O(h^6)
= -U', so F0 = -U', F2 = -[x'''']_0 / 12, F4 = -[x'''']_2 / 12 - [x^(6)]_0 / 360, with
x'''' = D^2 F and x^(6) = D^4 F the total derivatives along x'' = F (D g = g_x x' + g_x' F).
U is an undefined function of (x1..xN). The paper prints, for x in R^N (its Remark reads the
derivatives of U as tensors),

  F4 = (20 U3(U2 x', x') - 8 U2(U2 U1) + 18 U4(U1, x', x') - 9 U3(U1, U1) - 3 U5(x', x', x', x')) / 720

with Uk the k-th derivative tensor. Expected: F2 as printed in (22) in N = 1, 2; F4 as printed in
N = 1 but not in N = 2; F4 with 20 U3(U2 x', x') split as 12 U3(U2 x', x') + 8 U2 U3(x', x') in
both.
Usage: v_sv4_sympy.py   (exit 0 when every expectation holds)
"""
import itertools
import sys

import sympy as sp


def check(n):
    X = sp.symbols(f"x1:{n + 1}")
    V = sp.symbols(f"v1:{n + 1}")
    h = sp.Symbol("h")
    U = sp.Function("U")(*X)

    def T(k, *args):  # U^(k) applied to k - 1 vectors: a vector (the free index first)
        out = []
        for i in range(n):
            s = 0
            for idx in itertools.product(range(n), repeat=len(args)):
                term = sp.diff(U, X[i], *[X[j] for j in idx])
                for a, j in zip(args, idx):
                    term *= a[j]
                s += term
            out.append(s)
        return out

    def D(g, F):
        return [sp.expand(sum(gi.diff(X[j]) * V[j] + gi.diff(V[j]) * F[j] for j in range(n)))
                for gi in g]

    F0 = [-c for c in T(1)]
    x4_0 = D(D(F0, F0), F0)
    F2 = [-c / 12 for c in x4_0]
    F = [F0[i] + h**2 * F2[i] for i in range(n)]
    x4 = D(D(F, F), F)
    x6 = D(D(D(D(F0, F0), F0), F0), F0)
    F4 = [sp.expand(-x4[i].coeff(h, 2) / 12 - x6[i] / 360) for i in range(n)]

    U1 = T(1)
    U2v = T(2, V)              # U'' x'
    U2U1 = T(2, U1)            # U'' U'
    U2U2U1 = T(2, U2U1)        # U''(U'' U')
    printed2 = [sp.expand((T(3, V, V)[i] - U2U1[i]) / 12) for i in range(n)]
    a = T(3, U2v, V)           # U3(U'' x', x')
    b = T(2, T(3, V, V))       # U'' U3(x', x')
    rest = [-8 * U2U2U1[i] + 18 * T(4, U1, V, V)[i] - 9 * T(3, U1, U1)[i] - 3 * T(5, V, V, V, V)[i]
            for i in range(n)]
    printed4 = [sp.expand((20 * a[i] + rest[i]) / 720) for i in range(n)]
    split4 = [sp.expand((12 * a[i] + 8 * b[i] + rest[i]) / 720) for i in range(n)]
    same = lambda p, q: all(sp.expand(p[i] - q[i]) == 0 for i in range(n))
    return same(printed2, F2), same(printed4, F4), same(split4, F4)


def main():
    ok = True
    for n in (1, 2):
        f2, printed, split = check(n)
        for name, got, want in (("h^2 term (22) as printed", f2, True),
                                ("h^4 term as printed", printed, n == 1),
                                ("h^4 term, 20 U3(U2 x', x') split as 12 + 8 U2 U3(x', x')", split, True)):
            print(f"N={n} {name}: {'agrees' if got else 'differs'} "
                  f"(expected {'agrees' if want else 'differs'})")
            ok = ok and got == want
    print("Vermeeren §5.1.2's h^4 modified equation holds in one dimension only: "
          + ("yes" if ok else "NO"))
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
