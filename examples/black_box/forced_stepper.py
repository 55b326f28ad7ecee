#!/usr/bin/env python3
"""A one-step method for a time-dependent system, verified by `vibook verify --stepper-cmd
--stepper-protocol 2` (line protocol 2: the request carries the start time).

Usage: forced_stepper.py METHOD SYSTEM
  METHOD  sv           Stormer-Verlet for H = p^2/2 + V(q, t), time as a drifting variable: half
                       a kick with the force at t, a drift of h (which also advances the time),
                       half a kick with the force at t + h; order 2
          sv_stale     deliberately wrong: the same, but the second half kick still uses the
                       force at the step's start time t (the time advanced with coefficient 0
                       by the drift). On an autonomous system it is Stormer-Verlet; on a forced
                       one it is of order 1
  SYSTEM  forced-pendulum   H = p^2/2 - cos(q) - q cos(t)/2
          pendulum          H = p^2/2 - cos(q) (autonomous: the time is ignored)

Each request is 'T H N q p'; the answer is the state after N steps of size H from time T.
"""
import math
import sys


def force(system, q, t):
    f = -math.sin(q)
    if system == "forced-pendulum":
        f += 0.5 * math.cos(t)
    return f


def sv(system, t, h, q, p, stale):
    p += 0.5 * h * force(system, q, t)
    q += h * p
    p += 0.5 * h * force(system, q, t if stale else t + h)
    return q, p


def main():
    method, system = sys.argv[1], sys.argv[2]
    if method not in ("sv", "sv_stale") or system not in ("forced-pendulum", "pendulum"):
        print(f"error unknown method or system: {method} {system}", flush=True)
        return
    for line in sys.stdin:
        x = [float(v) for v in line.split()]
        t, h, n = x[0], x[1], int(x[2])
        q, p = x[3], x[4]
        for k in range(n):
            q, p = sv(system, t + k * h, h, q, p, method == "sv_stale")
        print(f"{q!r} {p!r}", flush=True)


if __name__ == "__main__":
    main()
