#!/usr/bin/env python3
"""Shen & Sun 2025, (4.4a)-(4.4b): the third and fourth derivatives along the modified equation,
checked in SymPy with undefined functions, outside vibook's engine and its formula reader.

Along a solution of x'' = F(x, v, h) = f(x) + h f1(x, v) + h^2 f2(x, v), v = x', the derivatives
are total derivatives: x''' = D F and x'''' = D^2 F with D g = g_x v + g_v F. The paper prints

  (4.4a)  x''' = F_v x' + F_v F = f_x v + h(f1_x v + f1_v f) + h^2(f2_x x' + f1_v f1) + ...
  (4.4b)  x'''' = F_xx<x',x'> + 2 F_xv<F,x'> + F_x F + F_vv<F,x'> + F_v F_x x' + F_v F_v F
                = f_xx<x',x'> + f_x f + h(f1_xx<x',x'> + 2 f1_xv<f,x'> + f1_x f + f_x f1
                  + f1_vv<f,f> + f1_v f_x v) + ...

Each line is written here by hand from the paper, with f, f1, f2 undefined functions of
(x1..xN) and (x1..xN, v1..vN), and compared with D F or D^2 F: the lines in F exactly, the
expanded lines through the power of h they show. A mixed derivative takes its arguments in the
order of its subscripts: g_xv<a, b> = sum_jk d2g/dx_j dv_k a_j b_k. Expected, in N = 1, 2, 3:

  (4.4a) first line: wrong as printed; right with F_x x' for F_v x' (every N).
  (4.4a) second line: wrong as printed; right with f2_v f added at h^2 (every N).
  (4.4b) first line: wrong as printed (every N); right with F_vv<F,F> and 2 F_xv<x',F>; with
         F_vv<F,F> alone, right in N = 1 only.
  (4.4b) second line: right as printed in N = 1 only; right with 2 f1_xv<x',f> (every N).

Usage: ss_eq44_sympy.py   (exit 0 when every expectation above holds)
"""
import sys

import sympy as sp


def setting(n):
    X = sp.symbols(f"x1:{n + 1}")
    V = sp.symbols(f"v1:{n + 1}")
    h = sp.Symbol("h")
    f = [sp.Function(f"f_{i}")(*X) for i in range(n)]
    f1 = [sp.Function(f"g_{i}")(*X, *V) for i in range(n)]
    f2 = [sp.Function(f"k_{i}")(*X, *V) for i in range(n)]
    F = [f[i] + h * f1[i] + h**2 * f2[i] for i in range(n)]

    def D(g):  # total derivative along x'' = F
        return [sp.expand(sum(gi.diff(X[j]) * V[j] + gi.diff(V[j]) * F[j] for j in range(n)))
                for gi in g]

    def jac(g, Y, u):  # g_Y u (a matrix times a vector)
        return [sum(g[i].diff(Y[j]) * u[j] for j in range(n)) for i in range(n)]

    def second(g, Y, Z, a, b):  # g_YZ<a, b>, a in the Y slot and b in the Z slot
        return [sum(g[i].diff(Y[j], Z[k]) * a[j] * b[k] for j in range(n) for k in range(n))
                for i in range(n)]

    return X, V, h, f, f1, f2, F, D, jac, second


def add(*vs):
    return [sp.expand(sum(c)) for c in zip(*vs)]


def scale(c, v):
    return [c * x for x in v]


def same(a, b, h, through=None):
    for ai, bi in zip(a, b):
        d = sp.expand(ai - bi)
        if through is not None:
            d = sum(d.coeff(h, k) * h**k for k in range(through + 1))
        if sp.simplify(d) != 0:
            return False
    return True


def main():
    failures = []

    def expect(name, got, want):
        print(f"{name}: {'agrees' if got else 'differs'} (expected {'agrees' if want else 'differs'})")
        if got != want:
            failures.append(name)

    for n in (1, 2, 3):
        X, V, h, f, f1, f2, F, D, jac, second = setting(n)
        x3 = D(F)
        x4 = D(x3)
        # (4.4a), first line
        printed = add(jac(F, V, V), jac(F, V, F))
        corrected = add(jac(F, X, V), jac(F, V, F))
        expect(f"N={n} (4.4a) line 1 as printed", same(printed, x3, h), False)
        expect(f"N={n} (4.4a) line 1 corrected", same(corrected, x3, h), True)
        # (4.4a), second line, through h^2
        base = add(jac(f, X, V), scale(h, add(jac(f1, X, V), jac(f1, V, f))),
                   scale(h**2, add(jac(f2, X, V), jac(f1, V, f1))))
        expect(f"N={n} (4.4a) line 2 as printed", same(base, x3, h, 2), False)
        expect(f"N={n} (4.4a) line 2 corrected",
               same(add(base, scale(h**2, jac(f2, V, f))), x3, h, 2), True)

        # (4.4b), first line
        def line1(xv_args, vv_args):
            return add(second(F, X, X, V, V), scale(2, second(F, X, V, *xv_args)),
                       jac(F, X, F), second(F, V, V, *vv_args), jac(F, V, jac(F, X, V)),
                       jac(F, V, jac(F, V, F)))
        expect(f"N={n} (4.4b) line 1 as printed", same(line1((F, V), (F, V)), x4, h), False)
        expect(f"N={n} (4.4b) line 1 with F_vv<F,F> only",
               same(line1((F, V), (F, F)), x4, h), n == 1)
        expect(f"N={n} (4.4b) line 1 corrected", same(line1((V, F), (F, F)), x4, h), True)

        # (4.4b), second line, through h
        def line2(xv_args):
            return add(second(f, X, X, V, V), jac(f, X, f),
                       scale(h, add(second(f1, X, X, V, V), scale(2, second(f1, X, V, *xv_args)),
                                    jac(f1, X, f), jac(f, X, f1), second(f1, V, V, f, f),
                                    jac(f1, V, jac(f, X, V)))))
        expect(f"N={n} (4.4b) line 2 as printed", same(line2((f, V)), x4, h, 1), n == 1)
        expect(f"N={n} (4.4b) line 2 corrected", same(line2((V, f)), x4, h, 1), True)
    if failures:
        print("FAILED:", ", ".join(failures))
        return 1
    print("(4.4a)-(4.4b): every expectation holds")
    return 0


if __name__ == "__main__":
    sys.exit(main())
