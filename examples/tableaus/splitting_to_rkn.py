#!/usr/bin/env python3
"""Write a splitting method for H = |p|^2/2 + V(q) as a Runge-Kutta-Nystrom tableau file
(c, abar, bbar, b), exactly, with Python's fractions: one stage per kick, at the drift total
c_k before it; abar_kj = b_j (c_k - c_j) for the kicks j before k; bbar_j = b_j (1 - c_j)
(the drifts summing to 1). vibook does the same in C++ (as_rkn_tableau in
src/vibook/integrators/splitting_sequence.hpp); this script is an independent second
derivation, and writes the published RKN methods of this folder that are splittings:

- mclachlan-atela-5-rkn.json: McLachlan & Atela 1992, Nonlinearity 5, 541, the optimal
  fifth-order RKN method (six kicks, kick first), with the digits as codes that cite the paper
  reproduce them (Principia's McLachlanAtela1992Order5Optimal); symplectic, order 5.
- wrong-mclachlan-atela-5-three.json: the same with three kicks changed (a wrong input).

Usage: splitting_to_rkn.py [DIR]   (default: this folder)
"""
import json
import os
import sys
from fractions import Fraction as F


def rkn(flows):
    c, b, drift = [], [], F(0)
    for kind, x in flows:
        if kind == "drift":
            drift += x
        else:
            c.append(drift)
            b.append(x)
    assert drift == 1, "the drifts must sum to 1"
    n = len(b)
    abar = [[b[j] * (c[k] - c[j]) if j < k else F(0) for j in range(n)] for k in range(n)]
    bbar = [b[j] * (1 - c[j]) for j in range(n)]
    return c, abar, bbar, b


def text(x):
    return f"{x.numerator}/{x.denominator}" if x.denominator != 1 else str(x.numerator)


def write(path, name, source, order, flows):
    c, abar, bbar, b = rkn(flows)
    doc = {"name": name, "source": source, "order": order, "symmetric": False,
           "c": [text(x) for x in c], "abar": [[text(x) for x in r] for r in abar],
           "bbar": [text(x) for x in bbar], "b": [text(x) for x in b]}
    with open(path, "w") as f:
        json.dump(doc, f, indent=1)
        f.write("\n")


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.abspath(__file__))
    kicks = ["0.1193900292875672758", "0.6989273703824752308", "-0.1713123582716007754",
             "0.4012695022513534480", "0.0107050818482359840", "-0.0589796254980311632"]
    drifts = ["0.339839625839110000", "-0.088601336903027329", "0.5858564768259621188",
              "-0.603039356536491888", "0.3235807965546976394", "0.4423637942197494587"]
    flows = []
    for k, d in zip(kicks, drifts):
        flows += [("kick", F(k)), ("drift", F(d))]
    # the drifts as printed sum to 1 - 1e-19: the last one takes the rounding, so that the
    # tableau has the RKN form (q1 = q0 + h p0 + ...); the order conditions show how well the
    # digits satisfy them
    total = sum(x for kind, x in flows if kind == "drift")
    flows[-1] = ("drift", flows[-1][1] - (total - 1))
    src = ("McLachlan & Atela 1992, Nonlinearity 5, 541: the optimal fifth-order RKN splitting, six "
           "kicks, kick first, with the digits as codes that cite the paper reproduce them (the "
           "paper itself was not at hand); written as an RKN tableau by "
           "examples/tableaus/splitting_to_rkn.py")
    write(os.path.join(out, "mclachlan-atela-5-rkn.json"),
          "McLachlan-Atela optimal fifth-order RKN method (as a tableau)", src, 5, flows)
    wrong = list(flows)
    wrong[0] = ("kick", wrong[0][1] + F(2, 1000))   # b_1 + 2e-3
    wrong[2] = ("kick", wrong[2][1] - F(1, 1000))   # b_2 - 1e-3
    wrong[4] = ("kick", wrong[4][1] - F(1, 1000))   # b_3 - 1e-3 (the kicks' sum kept)
    write(os.path.join(out, "wrong-mclachlan-atela-5-three.json"),
          "McLachlan-Atela fifth-order RKN with coefficients changed (a wrong input)",
          "mclachlan-atela-5-rkn.json with three kicks changed, b_1 + 2e-3, b_2 - 1e-3 and "
          "b_3 - 1e-3 (their sum kept, so it stays consistent): a wrong input for the order "
          "conditions by Nystrom trees", 5, wrong)


if __name__ == "__main__":
    main()
