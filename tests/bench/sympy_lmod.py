#!/usr/bin/env python3
"""The modified Lagrangian of Störmer–Verlet for a generic potential, derived with SymPy.

An independent derivation of what `vibook modified --method sv --potential generic --what
lagrangian` derives (Vermeeren 2017 §4), written for two uses:

* the benchmarks page (#28): SymPy's time for the same derivation, beside the engine's
  (`bench_table.py` reads the lines this script prints with --time);
* a check of the engine by other means (`--compare FILE`: the engine's `--format python`
  output must equal this derivation term by term).

The route differs from the engine's on purpose. Everything is a polynomial over QQ in h,
the velocities v_i and the derivatives U_alpha of the potential at x (SymPy's sparse
polynomial ring, truncated in h after every product). No jet symbols are used: the curve is
a solution of the modified equation xddot = F(x, xdot, h), so every higher derivative of x is
a total derivative along F, D(v_i) = F_i and D(U_alpha) = sum_i U_alpha,i v_i.

1. F from the discrete Euler–Lagrange equation of Störmer–Verlet,
   x(t+h) - 2x(t) + x(t-h) = -h^2 grad U(x(t)), whose Taylor expansion is
   sum_{m even >= 2} 2 h^m / m! x^(m) = -h^2 grad U; solved by the fixed point
   F = -grad U - sum_{m >= 4 even} 2 h^(m-2) / m! D^(m-2) F, two orders of h a sweep.
2. L_disc = |x(t+h/2) - x(t-h/2)|^2 / (2h^2) - (U(x(t-h/2)) + U(x(t+h/2)))/2 along the curve
   (Vermeeren (13), the papers' scaling L_disc ~ L), the Taylor coefficients of x(t +- h/2)
   being v, F, D F, ...
3. L_mod,K = sum_i (2^(1-2i) - 1) B_2i / (2i)! h^(2i) D^(2i) L_disc (Lemma 6: the meshed
   Lagrangian), evaluated along the curve and truncated after h^K (Definition 8).

usage: sympy_lmod.py DIM ORDER [--time] [--compare FILE]
       sympy_lmod.py --table OUT [--timeout SECONDS]
  --time          print "sympy_lmod DIM ORDER SECONDS" (wall seconds of the derivation, in
                  the process, after SymPy is imported: as the engine's benchmark times it)
  --compare FILE  FILE is the engine's `--format python` output for the same DIM and ORDER:
                  exit 0 when the two are equal, 1 (with the difference) when not
  --table OUT     time every entry of the benchmarks page's cost table (1 and 2 degrees of
                  freedom to h^10, 3 to h^8), each in its own process stopped after SECONDS
                  (default 120), and write "DIM ORDER SECONDS" or "DIM ORDER > SECONDS" lines
                  to OUT (written under a temporary name, then renamed)
"""
import itertools
import os
import subprocess
import sys
import time
from math import factorial

from sympy import QQ, Rational, bernoulli, expand
from sympy.polys.rings import ring


def derive(dim, K):
    """L_mod,K as an element of a sparse polynomial ring over QQ, and the ring's symbols."""
    top = K + 2  # the highest order of a derivative of U that the truncated series reach
    alphas = [a for n in range(top + 1)
              for a in itertools.combinations_with_replacement(range(1, dim + 1), n)]
    u_names = ["U" if not a else "U_" + "".join(str(i) for i in a) for a in alphas]
    v_names = [f"v{i}" for i in range(1, dim + 1)]
    R, *gens = ring(["h"] + v_names + u_names, QQ)
    h, v, U = gens[0], gens[1:1 + dim], dict(zip(alphas, gens[1 + dim:]))

    def cut(p, cap=K):  # drop the powers of h above cap
        return R({m: c for m, c in p.items() if m[0] <= cap})

    def by_h(p):  # p as {j: the coefficient of h^j}, each still carrying its h^j
        parts = {}
        for m, c in p.items():
            parts.setdefault(m[0], {})[m] = c
        return {j: R(d) for j, d in parts.items()}

    def mul(p, q, cap=K):  # p q to h^cap, without forming the higher products
        ps, qs = by_h(p), by_h(q)
        out = R.zero
        for j, a in ps.items():
            for k, b in qs.items():
                if j + k <= cap:
                    out += a * b
        return out

    def u(alpha):
        a = tuple(sorted(alpha))
        if a not in U:
            raise RuntimeError(f"U_{a} is beyond the ring's derivatives (order {top})")
        return U[a]

    # The total derivative along xddot = F: D(h) = 0, D(v_i) = F_i, D(U_a) = sum_i U_a,i v_i.
    dU = {a: sum((u(a + (i,)) * v[i - 1] for i in range(1, dim + 1)), R.zero)
          for a in alphas if len(a) < top}

    def D(p, F, cap):  # to h^cap: a quantity multiplied by h^(K - cap) later
        p = cut(p, cap)
        out = R.zero
        present = set()
        for m in p.keys():
            present.update(j for j, e in enumerate(m) if e)
        for j in sorted(present):
            if j == 0:
                continue
            dp = p.diff(gens[j])
            if j <= dim:
                out += mul(dp, F[j - 1], cap)
            else:
                a = alphas[j - 1 - dim]
                if a not in dU:
                    raise RuntimeError(f"D(U_{a}) needs derivatives beyond order {top}")
                out += mul(dp, dU[a], cap)
        return out

    grad = [u((i,)) for i in range(1, dim + 1)]
    # 1. The modified equation, by fixed-point sweeps: F is right to h^0 at the start, and a
    # sweep from an F right to h^(c-2) makes it right to h^c.
    F = [-g for g in grad]
    for sweep in range(1, K // 2 + 1):
        c = min(K, 2 * sweep)
        new = [-g for g in grad]
        DF = list(F)  # D^(m-2) F, m = 2, 3, ...
        for m in range(3, c + 3):
            DF = [D(x, F, c - (m - 2)) for x in DF]
            if m % 2 == 0:
                coeff = QQ(2, factorial(m))
                new = [n - cut(coeff * h ** (m - 2) * x, c) for n, x in zip(new, DF)]
        F = new
    # The derivatives of x along the curve: X[1] = v, X[2] = F, X[m] = D X[m-1].
    X = {1: list(v), 2: F}
    for m in range(3, K + 2):  # X[m] is multiplied by h^(m-1) or more
        X[m] = [D(c, F, K - (m - 1)) for c in X[m - 1]]
    # 2. L_disc along the curve.
    half = QQ(1, 2)
    delta = {s: [sum((cut(QQ(s) ** m * half ** m / factorial(m) * h ** m * X[m][i])
                      for m in range(1, K + 2)), R.zero) for i in range(dim)]
             for s in (1, -1)}
    chord = [sum((cut(half ** (m - 1) / factorial(m) * h ** (m - 1) * X[m][i])
                  for m in range(1, K + 2, 2)), R.zero) for i in range(dim)]
    kinetic = half * sum((mul(c, c) for c in chord), R.zero)
    potential = R.zero
    for s in (1, -1):  # U(x + delta) = sum over multisets of indices of U_a prod delta_i^k / k!
        powers = [[R.one] for _ in range(dim)]
        for i in range(dim):
            for k in range(1, K + 1):
                powers[i].append(mul(powers[i][-1], delta[s][i]))
        for a in alphas:
            if len(a) > K:
                continue
            term = R(QQ(1))
            for i in range(1, dim + 1):
                k = a.count(i)
                if k:
                    term = mul(term, QQ(1, factorial(k)) * powers[i - 1][k])
            potential += mul(U[a], term)
    L_disc = kinetic - half * potential
    # 3. The meshed Lagrangian along the curve, truncated: L_mod,K.
    L = R.zero
    Dk = L_disc
    for i in range(0, K // 2 + 1):
        if i > 0:
            Dk = D(D(Dk, F, K - 2 * i + 1), F, K - 2 * i)
        c = (Rational(2) ** (1 - 2 * i) - 1) * bernoulli(2 * i) / factorial(2 * i)
        L += cut(QQ(c.p, c.q) * h ** (2 * i) * Dk)
    return L


def table(out, timeout):
    lines = []
    for dim, orders in ((1, (2, 4, 6, 8, 10)), (2, (2, 4, 6, 8, 10)), (3, (2, 4, 6, 8))):
        for K in orders:
            try:
                r = subprocess.run([sys.executable, __file__, str(dim), str(K), "--time"],
                                   capture_output=True, text=True, timeout=timeout, check=True)
                lines.append(f"{dim} {K} {r.stdout.split()[-1]}")
            except subprocess.TimeoutExpired:
                lines.append(f"{dim} {K} > {timeout:g}")
    tmp = out + ".tmp"
    with open(tmp, "w", encoding="utf-8") as f:
        f.write("\n".join(lines) + "\n")
    os.replace(tmp, out)
    return 0


def main(argv):
    if "--table" in argv:
        timeout = float(argv[argv.index("--timeout") + 1]) if "--timeout" in argv else 120.0
        return table(argv[argv.index("--table") + 1], timeout)
    args = [a for a in argv if not a.startswith("--")]
    if len(args) < 2:
        print(__doc__, file=sys.stderr)
        return 2
    dim, K = int(args[0]), int(args[1])
    if not 1 <= dim <= 3 or not 0 <= K <= 10:
        print("sympy_lmod.py: DIM must be 1 to 3 and ORDER 0 to 10", file=sys.stderr)
        return 2
    start = time.perf_counter()
    L = derive(dim, K)
    seconds = time.perf_counter() - start
    if "--time" in argv:
        print(f"sympy_lmod {dim} {K} {seconds:.6g}")
    if "--compare" in argv:
        path = argv[argv.index("--compare") + 1]
        space = {}
        sys.setrecursionlimit(100000)  # a long sum on one line nests deeply in the parser
        with open(path, encoding="utf-8") as f:
            exec(f.read(), space)  # the engine's --format python output: defines L
        difference = expand(space["L"] - L.as_expr())
        if difference != 0:
            print(f"sympy_lmod.py: the engine's L_mod differs from SymPy's by {difference}",
                  file=sys.stderr)
            return 1
        print(f"sympy_lmod.py: dim {dim}, h^{K}: the engine's L_mod equals SymPy's "
              f"({len(L.terms())} terms)")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
