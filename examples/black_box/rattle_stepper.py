#!/usr/bin/env python3
"""RATTLE for the spherical pendulum, a constrained system verified by `vibook verify
--stepper-cmd` with typed constraints:

    vibook verify --stepper-cmd 'python3 rattle_stepper.py rattle' --potential z \
      --constraint '(x^2+y^2+z^2-1)/2' --q0 0.8414709848078965,0,-0.5403023058681398 \
      --p0 0,0.8,0 --expected-order 2 --symmetric

Usage: rattle_stepper.py METHOD
  METHOD  rattle  RATTLE (HLW VII.1.4) for H = |p|^2/2 + q3 on |q| = 1: the position
                  constraint's multiplier in closed form (the smaller root of a quadratic), the
                  new momentum projected onto the hidden constraint q.p = 0; order 2, symmetric,
                  symplectic on the constraint manifold
          shake   deliberately wrong: the same positions, the momentum left unprojected (it
                  leaves the hidden constraint by O(h) a step)

Each request is 'H N q1 q2 q3 p1 p2 p3' (line protocol 1); the answer is the state after N steps.
"""
import math
import sys


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def step(h, q, p, project):
    # the kick of V = q3 (grad V = e3) and the free flight, before the constraint force
    a = [q[0] + h * p[0], q[1] + h * p[1], q[2] + h * (p[2] - 0.5 * h)]
    # q1 = a - m q with |q1| = 1 (m = h^2 lambda / 2): the smaller root of
    # |q|^2 m^2 - 2 (a.q) m + |a|^2 - 1 = 0
    qq, aq = dot(q, q), dot(a, q)
    disc = aq * aq - qq * (dot(a, a) - 1)
    if disc < 0:
        raise ValueError("no position on the sphere")
    m = (aq - math.sqrt(disc)) / qq
    q1 = [a[i] - m * q[i] for i in range(3)]
    v = [(q1[i] - q[i]) / h for i in range(3)]
    v[2] -= 0.5 * h
    if project:  # onto the hidden constraint q1.p1 = 0
        c = dot(q1, v) / dot(q1, q1)
        v = [v[i] - c * q1[i] for i in range(3)]
    return q1, v


def main():
    method = sys.argv[1] if len(sys.argv) > 1 else ""
    if method not in ("rattle", "shake"):
        print(f"error unknown method: {method} (rattle or shake)", flush=True)
        return
    for line in sys.stdin:
        x = [float(v) for v in line.split()]
        h, n = x[0], int(x[1])
        q, p = x[2:5], x[5:8]
        try:
            for _ in range(n):
                q, p = step(h, q, p, method == "rattle")
        except ValueError as e:
            print(f"error {e}", flush=True)
            continue
        print(" ".join(repr(v) for v in q + p), flush=True)


if __name__ == "__main__":
    main()
