#!/usr/bin/env python3
"""Seeded random arguments for `vibook run`, `vibook modified` and `vibook verify` (the argument
parser, the strict number and list parsers, the --alpha rational parser, the expression
parser of --ld and --potential, fed mutated expressions, and the other routes of verify:
--method, --tableau, --composition, --splitting, and black-box steppers that crash, hang, flood or do not
load, with --report and --json-out), run for a bounded number of cases and time. Every case must end with exit status 0, 2, 3 or 4, or 5 for a verify whose verdict
failed (never a signal, an
uncaught exception's 1, or a hang), with exactly one stderr line when it fails, and must leave
nothing in its directory but the file it was asked to write (or FILE.partial after status 3).

Usage: fuzz_args.py VIBOOK [--seed N] [--cases N] [--seconds S] [--stepper-lib FILE]
The seed is printed, so that a failing case can be replayed.
"""
import argparse
import os
import random
import subprocess
import sys
import tempfile
import time

GARBAGE = ["", " ", "abc", "nan", "inf", "-inf", "1e400", "-1e400", "0x10", "1e", "--", "-",
           "1,,0", ",", "1,", ",1", "1;0", "١", "é", "1/0", "1/2x", "0/0", "+", "++1",
           "9" * 40, "1" * 400, "%s%n", "$(true)", "1e-400"]
NUMBERS = ["0", "1", "0.5", "-1", "2", "10", "0.01", "0.1", "1e-3", "1e300", "1e-18", "-0.1",
           "0.99", "0.9", "1e155", "5", "3"]
LISTS = ["1,0", "0,1", "0.4,0", "0,2", "1", "1,2,3", "1e300,0", "0,0", "nan,1", "1,0.5"]


def pick(r, *pools):
    # Mostly a valid value, so that the cases reach the runs, not only the first check.
    pool = pools[0] if r.random() < 0.75 else r.choice(pools)
    return r.choice(pool)


LDS = ["h*((q1-q0)^2/(2*h^2) - (V(q0)+4*V((q0+q1)/2)+V(q1))/6)",
       "(q1-q0)^2/(2*h) - h*(V(q0)+V(q1))/2", "(q1-q0)^2/(2*h) - h*V((q0+q1)/2)",
       "(q1-q0)^2/(2*h) - h*V(q1)"]
POTENTIALS = ["x^2/2+y^2/2+x^2*y-y^3/3", "x^2/2", "-cos(x)", "-1/sqrt(x^2+y^2)",
              "x^4/4+y^2/2+z^2/2", "exp(x)-x"]
ALPHABET = "q01h()+-*/^V.xyz 23sincoexplgrt,"


def mutate(r, text):
    # Delete, insert or replace a few characters: most mutants are syntax or type errors.
    t = list(text)
    for _ in range(r.choice([0, 1, 1, 2, 3])):
        i = r.randrange(len(t) + 1)
        op = r.choice("dir")
        if op == "d" and i < len(t):
            del t[i]
        elif op == "i":
            t.insert(i, r.choice(ALPHABET))
        elif i < len(t):
            t[i] = r.choice(ALPHABET)
    return "".join(t)


FUNCS = ["sin", "cos", "exp", "log", "sqrt", "V", "tanh", "abs"]


def nested(r, depth):
    # A random scalar expression in q0, q1, h: nested functions, powers, V and grad(V) terms.
    if depth == 0 or r.random() < 0.2:
        return r.choice(["q0[1]", "q1[1]", "h", "(q1-q0)^2", "q0^2", "2", "1/3", "0.5",
                         "V(q0)", "V((q0+q1)/2)", "grad(V)(q0)*(q1-q0)"])
    k = r.random()
    if k < 0.45:
        f = r.choice(FUNCS)
        inner = nested(r, depth - 1)
        return f"V([{inner}, {inner}, {inner}])" if f == "V" and r.random() < 0.3 else f"{f}({inner})"
    if k < 0.75:
        return f"({nested(r, depth - 1)}){r.choice('+-*/')}({nested(r, depth - 1)})"
    return f"({nested(r, depth - 1)})^{r.choice(['2', '3', '-1', '1/2', '-3/2', '32', '33', '0'])}"


def verify_case(r):
    args = ["verify"]
    if r.random() < 0.25:
        # A consistent kinetic part plus a nested remainder: deep trees, every function, big powers.
        args += ["--ld", f"h*((q1-q0)^2/(2*h^2) - {nested(r, r.randint(1, 8))})"]
    elif r.random() < 0.97:
        args += ["--ld", mutate(r, r.choice(LDS)) if r.random() < 0.8 else r.choice(GARBAGE)]
    if r.random() < 0.97:
        args += ["--potential", mutate(r, r.choice(POTENTIALS)) if r.random() < 0.8 else r.choice(GARBAGE)]
    # Small studies only.
    args += ["--t-end", "0.5", "--h-list", "0.1,0.05,0.025", "--steps", "1024"]
    opts = {
        "--dim": [["1", "2", "3"], ["0", "4"], GARBAGE],
        "--q0": [LISTS, GARBAGE],
        "--p0": [LISTS, GARBAGE],
        "--h": [["0.05", "0.1"], NUMBERS, GARBAGE],
        "--modified-order": [["0", "1", "2"], ["-1", "7"], GARBAGE],
        "--format": [["text", "latex"], ["python"], GARBAGE],
        "--expected-order": [["1", "2"], NUMBERS, GARBAGE],
        "--json-out": [["out.json"], ["", ".", "nodir/x.json"]],
        "--report": [["rep"], ["", ".", "nodir/rep", "rep/"]],
        "--max-seconds": [["30", "2"], ["0", "-1", "1e9"], GARBAGE],
        "--adaptive": [["epavi"], GARBAGE],
        "--adaptive-steps": [["256", "300"], ["0", "10", "1e9"], GARBAGE],
    }
    for name in r.sample(sorted(opts), r.choice([0, 1, 1, 2, 3])):
        args += [name, pick(r, *opts[name])]
    if "--adaptive" in args and "--adaptive-steps" not in args:
        args += ["--adaptive-steps", "256"]  # small runs only
    if r.random() < 0.1:
        # a composition of the typed L_d (the --ld route's expressions, another route)
        args += ["--composition", "ld", "--coefficients",
                 pick(r, ["yoshida4", "ruth3", "1/2*,1/2"], GARBAGE)]
    if "--max-seconds" not in args:
        args += ["--max-seconds", "40"]  # every case answers (status 3 past it), never hangs
    return args


TABLEAUS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "examples",
                        "tableaus")
STEPPER_LIB = None  # --stepper-lib FILE: Boost.Odeint's steppers behind the C ABI
STEPPER_CMDS = ["cat", "true", "sleep 100", "yes '0.1 0.1'", "sh -c 'kill -SEGV $$'",
                "python3 -c 'import os; os.abort()'", "printf 'ready\\n'", "echo error nope",
                "head -c 3000000 /dev/zero"]
STEPPER_ARGS = ["mclachlan4/kepler", "symplectic_euler/pendulum", "explicit_euler/pendulum",
                "velocity_verlet/kepler", "rk4/kepler", "nosuch/kepler", "mclachlan4", ""]


def map_case(r):
    # The other routes of verify (a method, a tableau, a composition, a black box), each with
    # its report and JSON asked for now and then: small studies only.
    args = ["verify"]
    k = r.random()
    if k < 0.3:
        args += ["--method", pick(r, ["gauss:1", "gauss:2", "lobatto:2", "lobatto:3"],
                                  ["gauss:0", "gauss:99", "nosuch", "gauss:", "sv"], GARBAGE)]
    elif k < 0.5:
        names = sorted(os.listdir(TABLEAUS)) if os.path.isdir(TABLEAUS) else []
        pool = [os.path.join(TABLEAUS, n) for n in names if n.endswith(".json")]
        args += ["--tableau", pick(r, pool or ["x.json"], ["/dev/null", "/dev/zero", ".", ""],
                                   GARBAGE)]
    elif k < 0.62:
        args += ["--composition", pick(r, ["sv", "se"], ["ld", "nosuch"], GARBAGE),
                 "--coefficients", pick(r, ["yoshida4", "ruth3", "1,1", "1/2,1/2"], GARBAGE)]
    elif k < 0.7:
        args += ["--splitting", pick(r, ["leapfrog", "forest-ruth", "sbab-2",
                                         "drift:1/2,kick:1,drift:1/2", "drift:1,kick:1",
                                         "kick:1/2-sqrt(3)/6,drift:1,kick:1/2+sqrt(3)/6"],
                                     ["nosuch", "drift:1/0", "kick:sqrt(-2)", "drift:(1",
                                      "drift:1e999,kick:1", "drift:1,kick:1,",
                                      "drift:" + "(" * 100 + "1" + ")" * 100 + ",kick:1"],
                                     GARBAGE)]
    elif k < 0.85 or STEPPER_LIB is None:
        args += ["--stepper-cmd", r.choice(STEPPER_CMDS), "--stepper-timeout", "2"]
    else:
        args += ["--stepper-lib", pick(r, [STEPPER_LIB], ["/dev/null", "/etc/passwd", "."]),
                 "--stepper-arg", r.choice(STEPPER_ARGS), "--stepper-timeout", "5"]
    if r.random() < 0.9:
        args += ["--problem", pick(r, ["pendulum", "kepler", "henon-heiles"], ["", "nosuch"])]
    args += ["--h-list", "0.1,0.05,0.025", "--steps", "1024"]
    if "--stepper-cmd" in args or "--stepper-lib" in args:
        # a black box's order is said, not derived (mostly a valid one)
        args += ["--expected-order", pick(r, ["1", "2", "4"], NUMBERS, GARBAGE)]
    opts = {
        "--json-out": [["out.json"], ["", ".", "nodir/x.json"]],
        "--report": [["rep"], ["", ".", "nodir/rep", "rep/"]],
        "--h": [["0.05", "0.1"], NUMBERS, GARBAGE],
        "--q0": [LISTS, GARBAGE],
        "--p0": [LISTS, GARBAGE],
    }
    if "--expected-order" not in args:
        opts["--expected-order"] = [["1", "2", "4"], NUMBERS, GARBAGE]
    for name in r.sample(sorted(opts), r.choice([0, 1, 2, 2, 3])):
        args += [name, pick(r, *opts[name])]
    args += ["--max-seconds", "40"]
    return args


def run_case(r):
    if r.random() < 0.15:
        return verify_case(r)
    if r.random() < 0.1:
        return map_case(r)
    if r.random() < 0.7:
        args = ["run"]
        if r.random() < 0.95:
            args += ["--problem", r.choice(["kepler"] * 10 + ["harmonic", "pendulum",
                                            "relativistic-kepler"] * 2 + ["foo", ""])]
        if r.random() < 0.95:
            args += ["--method", r.choice(["sv", "se", "midpoint", "del-generic", "epavi", "avi1"] * 3
                                          + ["se-adjoint", "avi2", "vi", "k-symplectic", "vi1",
                                             "vi2", "vi2-adjoint", "rk4", ""])]
        # Small runs only: the step and the end time come from bounded pools most of the time.
        opts = {
            "--h": [["0.05", "0.1", "0.5"], NUMBERS, GARBAGE],
            "--t-end": [["1", "2", "0.5"], NUMBERS, GARBAGE],
            "--periods": [["0.5", "1"], NUMBERS, GARBAGE],
            "--e": [["0", "0.5", "0.7"], NUMBERS, GARBAGE],
            "--q0": [LISTS, GARBAGE],
            "--p0": [LISTS, GARBAGE],
            "--h0": [["0.01", "0.05"], NUMBERS, GARBAGE],
            "--precision": [["double", "long-double", "double-double", "quad", "mpfr"], GARBAGE],
            "--digits": [["18", "25"], ["0", "-1", "100001"], GARBAGE],
            "--tol": [["1e-10", "1e-6"], NUMBERS, GARBAGE],
            "--energy-target": [["previous", "initial"], GARBAGE],
            "--alpha": [["0.3", "0.5"], NUMBERS, GARBAGE],
            "--c": [["5", "10"], NUMBERS, GARBAGE],
            "--tau-end": [["1", "2"], NUMBERS, GARBAGE],
            "--every": [["1", "10", "100"], ["0", "-1", "1.5"], GARBAGE],
            "--discrete-lagrangian": [["midpoint", "sv", "se", "se-adjoint"], GARBAGE],
        }
        for name in r.sample(sorted(opts), r.choice([0, 1, 1, 2, 2, 3, 5])):
            args += [name, pick(r, *opts[name])]
        if r.random() < 0.95:
            args += ["--csv", r.choice(["out.csv"] * 6 + ["-", "", ".", "nodir/x.csv"])]
    else:
        args = ["modified"]
        if r.random() < 0.95:
            args += ["--method", r.choice(["sv", "se", "se-adjoint", "midpoint", "vi1",
                                           "vi1-adjoint", "vi2", "rk4", ""])]
        opts = {
            "--potential": [["generic", "kepler", "pendulum", "harmonic"], GARBAGE],
            "--dim": [["1", "2", "3"], ["0", "4", "-1", "03", "+2", " 2", "0x2", "2.0"], GARBAGE],
            "--what": [["equation", "lagrangian", "hamiltonian", "meshed", "disc"], GARBAGE],
            "--format": [["text", "latex", "python"], GARBAGE],
            "--alpha": [["1/2", "0.3", "1/3", "0", "1", "2.5e-1"], GARBAGE, NUMBERS],
            "--max-seconds": [["30", "1"], ["0", "-1", "1e9", "1e-400"], GARBAGE],
        }
        if r.random() < 0.9:
            args += ["--order", pick(r, ["0", "1", "2", "4"],
                                     ["-1", "11", "1.5", "010", "011", "0x2", " 2", "+2", "",
                                      "2 ", "08", "1e1", "99999999999999999999"], GARBAGE)]
        for name in r.sample(sorted(opts), r.choice([0, 1, 2, 2, 3])):
            args += [name, pick(r, *opts[name])]
        if r.random() < 0.3:
            args.append("--cross-check")
        if r.random() < 0.2:
            args.append("--progress")
        if "--max-seconds" not in args:
            args += ["--max-seconds", "40"]  # a large --dim/--order answers with status 3
    if r.random() < 0.05:
        args.insert(r.randint(1, len(args)), r.choice(["--nosuch", "-x", "--h=", "--"]))
    return args


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("vibook")
    ap.add_argument("--seed", type=int, default=int(os.environ.get("VIBOOK_FUZZ_SEED", "20261122")))
    ap.add_argument("--cases", type=int, default=int(os.environ.get("VIBOOK_FUZZ_CASES", "400")))
    ap.add_argument("--seconds", type=float, default=float(os.environ.get("VIBOOK_FUZZ_SECONDS", "120")))
    ap.add_argument("--stepper-lib", help="a library behind the stepper ABI, for the black-box cases")
    a = ap.parse_args()
    global STEPPER_LIB
    STEPPER_LIB = a.stepper_lib
    vibook = os.path.realpath(a.vibook)
    r = random.Random(a.seed)
    print(f"fuzz: seed {a.seed}, at most {a.cases} cases in {a.seconds:.0f} s")
    start = time.monotonic()
    done = failed = 0
    statuses = {}
    while done < a.cases and time.monotonic() - start < a.seconds:
        args = run_case(r)
        with tempfile.TemporaryDirectory() as d:
            try:
                p = subprocess.run([vibook] + args, cwd=d, capture_output=True, timeout=60,
                                   stdin=subprocess.DEVNULL)
            except subprocess.TimeoutExpired:
                failed += 1
                print(f"FAIL (no answer in 60 s): vibook {' '.join(repr(x) for x in args)}")
                done += 1
                continue
            left = sorted(os.listdir(d))
            outputs = [args[args.index(o) + 1].rstrip("/") for o in ("--csv", "--json-out", "--report")
                       if o in args[:-1]]
            allowed = set()
            for out in outputs:
                # verify writes its JSON and report whatever happened (nothing lost)
                done_ok = p.returncode in (0, 5) or (p.returncode == 3 and args[0] == "verify")
                if done_ok and out and "/" not in out:
                    allowed.add(out)
                if p.returncode == 3 and out and "/" not in out:
                    allowed.add(out + ".partial")
            err = p.stderr.decode("utf-8", "replace").splitlines()
            problem = None
            if p.returncode not in (0, 2, 3, 4) and not (p.returncode == 5 and args[0] == "verify"):
                problem = f"exit status {p.returncode}"
            elif p.returncode != 0 and len(err) != 1:
                problem = f"{len(err)} stderr lines"
            elif p.returncode != 0 and not err[0].startswith("vibook: "):
                problem = "stderr line without the 'vibook: ' prefix"
            elif set(left) - allowed:
                problem = f"left {sorted(set(left) - allowed)}"
            statuses[p.returncode] = statuses.get(p.returncode, 0) + 1
            if problem:
                failed += 1
                print(f"FAIL ({problem}): vibook {' '.join(repr(x) for x in args)}")
                for line in err[:5]:
                    print("   ", line)
        done += 1
    summary = ", ".join(f"status {k}: {v}" for k, v in sorted(statuses.items()))
    print(f"fuzz: {done} cases in {time.monotonic() - start:.0f} s ({summary})")
    print(f"{done - failed} passed, {failed} failed")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
