#!/usr/bin/env python3
"""A one-step method in Python, verified by `vibook verify --stepper-cmd` (line protocol 1).

Usage: stepper.py METHOD SYSTEM
  METHOD  sv         Stormer-Verlet (kick-drift-kick), order 2
          yoshida4   the triple jump of Stormer-Verlet, order 4
          ruth3      Ruth's third-order method as a composition of symplectic Euler (drift, then
                     kick) and its adjoint, stages 7/24*, 3/8, 3/8*, -25/24, 1* (* the adjoint)
          ruth3_swapped  deliberately wrong: each (adjoint, base) pair of those stages applied
                     in the other order, 3/8, 7/24*, -25/24, 3/8*, 0, 1* (documented 3, order 2)
          euler      deliberately wrong: explicit Euler, order 1 and not symplectic
          garbage    deliberately wrong: answers text that is not a state
          refuse     answers 'error' for steps larger than 0.01
  SYSTEM  pendulum (1 dof) or kepler (2 dof)

Each request is 'H N q_1 .. q_d p_1 .. p_d'; the answer is the state after N steps of size H.
"""
import math
import sys


def force(system, q):
    if system == "pendulum":
        return [-math.sin(q[0])]
    r2 = q[0] * q[0] + q[1] * q[1]
    ir3 = 1.0 / (r2 * math.sqrt(r2))
    return [-q[0] * ir3, -q[1] * ir3]


def sv(system, h, q, p):
    f = force(system, q)
    p = [pi + 0.5 * h * fi for pi, fi in zip(p, f)]
    q = [qi + h * pi for qi, pi in zip(q, p)]
    f = force(system, q)
    p = [pi + 0.5 * h * fi for pi, fi in zip(p, f)]
    return q, p


def se(system, h, q, p):  # drift, then kick
    q = [qi + h * pi for qi, pi in zip(q, p)]
    f = force(system, q)
    return q, [pi + h * fi for pi, fi in zip(p, f)]


def se_adjoint(system, h, q, p):  # kick, then drift
    f = force(system, q)
    p = [pi + h * fi for pi, fi in zip(p, f)]
    return [qi + h * pi for qi, pi in zip(q, p)], p


C = 2 ** (1 / 3)
W1 = 1 / (2 - C)
W0 = -C / (2 - C)


def yoshida4(system, h, q, p):
    for w in (W1, W0, W1):
        q, p = sv(system, w * h, q, p)
    return q, p


RUTH3 = [(7 / 24, True), (3 / 8, False), (3 / 8, True), (-25 / 24, False), (1.0, True)]
RUTH3_SWAPPED = [(3 / 8, False), (7 / 24, True), (-25 / 24, False), (3 / 8, True), (0.0, False),
                 (1.0, True)]


def stages(table):
    def step(system, h, q, p):
        for c, adjoint in table:
            q, p = (se_adjoint if adjoint else se)(system, c * h, q, p)
        return q, p
    return step


def euler(system, h, q, p):
    f = force(system, q)
    return [qi + h * pi for qi, pi in zip(q, p)], [pi + h * fi for pi, fi in zip(p, f)]


def main():
    method, system = sys.argv[1], sys.argv[2]
    step = {"sv": sv, "yoshida4": yoshida4, "ruth3": stages(RUTH3),
            "ruth3_swapped": stages(RUTH3_SWAPPED), "euler": euler, "refuse": sv,
            "garbage": sv}[method]
    for line in sys.stdin:
        x = [float(t) for t in line.split()]
        h, n = x[0], int(x[1])
        d = (len(x) - 2) // 2
        q, p = x[2:2 + d], x[2 + d:]
        if method == "garbage":
            print("the state is", q, flush=True)
            continue
        if method == "refuse" and h > 0.01:
            print(f"error: step {h} larger than 0.01", flush=True)
            continue
        for _ in range(n):
            q, p = step(system, h, q, p)
        print(" ".join(repr(v) for v in q + p), flush=True)


if __name__ == "__main__":
    main()
