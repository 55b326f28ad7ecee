#!/usr/bin/env python3
"""Shen & Sun 2025, the proof of Theorem 16: which bracket belongs to which one-period change.
An independent check in SymPy, outside vibook's engine and formula reader.

Theorem 13 gives Delta|A| = -eps T [EL(Lbar) . v_A2] (4.26) and Delta omega = (eps T / e)
[EL(Lbar) . v_A1] (4.27). The proof of Theorem 16 writes (eps = h/2, EL(Lbar) = EL(G) with
G = 2 alpha phi_x2 x2')

  Delta|A|     = -hT/2  [EL(G) . v_A1] = -hT/2  [-12 alpha H x1 x2^2/|x|^5 + 12 alpha A2 x1 x2/|x|^5]
  Delta omega  =  hT/2e [EL(G) . v_A2] =  hT/2e [ 12 alpha H x1^2 x2/|x|^5 - 12 alpha A1 x1 x2/|x|^5]

This script checks, exactly and pointwise (before the period average), for Kepler's
phi = -1/|x|, H, A and v_A of Propositions 2 and 4, and EL(L) = d/dt dL/dx' - dL/dx:
  1. each bracket equals the product written beside it (the lines' own equalities hold);
  2. EL(G) . v_A1 and EL(G) . v_A2 differ, so the label decides: as printed, the bracket under
     Delta|A| is Theorem 13's bracket of Delta omega and the other way round.
Usage: ss_t16_labels_sympy.py   (exit 0 when both hold)
"""
import sys

import sympy as sp

x1, x2, v1, v2, a1, a2, alpha = sp.symbols("x1 x2 v1 v2 a1 a2 alpha")
X, V, A = [x1, x2], [v1, v2], [a1, a2]
r = sp.sqrt(x1**2 + x2**2)
phi = -1 / r


def total(e):  # d/dt on the free jets (x, x', x'')
    return sum(sp.diff(e, X[i]) * V[i] + sp.diff(e, V[i]) * A[i] for i in range(2))


def EL(L):
    return [sp.simplify(total(sp.diff(L, V[i])) - sp.diff(L, X[i])) for i in range(2)]


vv, xv = v1**2 + v2**2, x1 * v1 + x2 * v2
H = vv / 2 - 1 / r
A1 = x1 * vv - v1 * xv - x1 / r
A2 = x2 * vv - v2 * xv - x2 / r
vA1 = [-x2 * v2, 2 * x1 * v2 - v1 * x2]
vA2 = [2 * x2 * v1 - x1 * v2, -x1 * v1]

G = 2 * alpha * sp.diff(phi, x2) * v2
el = EL(G)
p1 = sp.simplify(el[0] * vA1[0] + el[1] * vA1[1])
p2 = sp.simplify(el[0] * vA2[0] + el[1] * vA2[1])
b1 = -12 * alpha * H * x1 * x2**2 / r**5 + 12 * alpha * A2 * x1 * x2 / r**5
b2 = 12 * alpha * H * x1**2 * x2 / r**5 - 12 * alpha * A1 * x1 * x2 / r**5

ok = True
for name, got in [("bracket under Delta|A| = EL(G).v_A1", sp.simplify(b1 - p1) == 0),
                  ("bracket under Delta omega = EL(G).v_A2", sp.simplify(b2 - p2) == 0),
                  ("EL(G).v_A1 differs from EL(G).v_A2", sp.simplify(p1 - p2) != 0)]:
    print(f"{name}: {'yes' if got else 'NO'}")
    ok = ok and got
if ok:
    print("Theorem 16's proof: each bracket is the product beside it, and the two products differ:"
          " Delta|A| (Theorem 13: v_A2) and Delta omega (v_A1) carry each other's brackets")
sys.exit(0 if ok else 1)
