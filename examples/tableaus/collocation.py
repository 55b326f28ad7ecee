#!/usr/bin/env python3
"""Write collocation tableaus to 45 significant digits (the tableau files of this folder that
are not typed by hand): Gauss with s = 4, 5, 6 stages (order 2s, symplectic and symmetric)
Lobatto IIIA with 4 stages (order 6, symmetric, NOT symplectic: a wrong input for the
symplecticity verdict), and Gauss 6 with one entry off in its eleventh digit (a wrong input for
the order verdict).

A collocation method with nodes c_1 < ... < c_s has a_ij = int_0^{c_i} l_j(t) dt and
b_j = int_0^1 l_j(t) dt, l_j the Lagrange polynomials of the nodes (Hairer, Lubich & Wanner,
Geometric Numerical Integration, 2006, Sec. II.1.3). Gauss's nodes are the zeros of the
shifted Legendre polynomial P_s(2t - 1); Lobatto's are 0, 1 and the zeros of P'_{s-1}(2t - 1).
mpmath (Debian python3-mpmath, a dependency of python3-sympy) at 80 digits.

Usage: collocation.py [DIR]   (default: this folder)
"""
import json
import os
import sys

import mpmath as mp

mp.mp.dps = 80


def lagrange_integrals(c):
    s = len(c)

    def coefficients(j):  # of l_j, lowest power first
        p, den = [mp.mpf(1)], mp.mpf(1)
        for m in range(s):
            if m != j:
                q = [mp.mpf(0)] * (len(p) + 1)
                for k, a in enumerate(p):
                    q[k + 1] += a
                    q[k] -= a * c[m]
                p, den = q, den * (c[j] - c[m])
        return [a / den for a in p]

    ls = [coefficients(j) for j in range(s)]
    integral = lambda p, x: sum(a * x ** (k + 1) / (k + 1) for k, a in enumerate(p))
    a = [[integral(ls[j], c[i]) for j in range(s)] for i in range(s)]
    b = [integral(ls[j], 1) for j in range(s)]
    return a, b


def text(x):
    return mp.nstr(x, 45)


def write(path, name, source, c, order, symmetric):
    a, b = lagrange_integrals(c)
    doc = {"name": name, "source": source, "order": order, "symmetric": symmetric,
           "c": [text(x) for x in c], "a": [[text(x) for x in r] for r in a],
           "b": [text(x) for x in b]}
    with open(path, "w") as f:
        json.dump(doc, f, indent=1)
        f.write("\n")


def legendre_zeros(n):  # of P_n on [-1, 1]
    return sorted(mp.polyroots(mp.taylor(lambda t: mp.legendre(n, t), 0, n)[::-1],
                               maxsteps=400, extraprec=400))


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.abspath(__file__))
    hlw = "Hairer, Lubich & Wanner, Geometric Numerical Integration (2006), Sec. II.1.3"
    for s in (4, 5, 6):
        c = [(1 + x) / 2 for x in legendre_zeros(s)]
        write(os.path.join(out, f"gauss{s}.json"), f"Gauss collocation, {s} stages",
              f"{hlw}: nodes the zeros of P_{s}(2t - 1); entries to 45 digits by "
              "examples/tableaus/collocation.py", c, 2 * s, True)
    # Gauss 6 with one entry off in its eleventh digit: the row sum no longer gives c_3, and
    # the method drops to order 1 (visible in double-double, where the error term of 1e-11
    # is not hidden by round-off); the symplecticity conditions fail by 2e-12.
    with open(os.path.join(out, "gauss6.json")) as f:
        doc = json.load(f)
    doc["a"][2][3] = text(mp.mpf(doc["a"][2][3]) + mp.mpf("1e-11"))
    doc["name"] = "Gauss collocation, 6 stages, a_34 off in its eleventh digit"
    doc["source"] = ("gauss6.json with a_34 + 1e-11: a wrong input for the order verdict in "
                     "double-double (examples/tableaus/collocation.py)")
    with open(os.path.join(out, "wrong-gauss6-typo.json"), "w") as f:
        json.dump(doc, f, indent=1)
        f.write("\n")
    # Gauss 3 as a Runge-Kutta-Nystrom tableau: for q'' = f(q) the collocation method's stages
    # are Q = q0 + c h p0 + h^2 A A f(Q), so abar = A^2, bbar = b^T A = b_j (1 - c_j) and the
    # velocities' weights are b (HLW Sec. II.2.3, IV.2.2). Symplectic, symmetric, order 6.
    c = [(1 + x) / 2 for x in legendre_zeros(3)]
    a, b = lagrange_integrals(c)
    abar = [[sum(a[i][k] * a[k][j] for k in range(3)) for j in range(3)] for i in range(3)]
    bbar = [sum(b[i] * a[i][j] for i in range(3)) for j in range(3)]
    doc = {"name": "Gauss collocation, 3 stages, as a Runge-Kutta-Nystrom method",
           "source": f"{hlw}: abar = A^2, bbar = b^T A; entries to 45 digits by "
           "examples/tableaus/collocation.py", "order": 6, "symmetric": True,
           "c": [text(x) for x in c], "abar": [[text(x) for x in r] for r in abar],
           "bbar": [text(x) for x in bbar], "b": [text(x) for x in b]}
    with open(os.path.join(out, "gauss3-rkn.json"), "w") as f:
        json.dump(doc, f, indent=1)
        f.write("\n")
    c = [mp.mpf(0), (5 - mp.sqrt(5)) / 10, (5 + mp.sqrt(5)) / 10, mp.mpf(1)]
    write(os.path.join(out, "wrong-lobatto4-iiia-only.json"),
          "Lobatto IIIA, 4 stages (not symplectic)",
          f"{hlw}: nodes 0, (5 -+ sqrt 5)/10, 1; order 6 and symmetric, but not symplectic "
          "(no IIIB partner): a wrong input for the symplecticity verdict", c, 6, True)


if __name__ == "__main__":
    main()
