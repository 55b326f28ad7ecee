#!/usr/bin/env python3
"""Turn a Google Benchmark JSON file into the book's HTML table (median of the repetitions,
ratios against the hand-written loop of the same run)."""
import json
import sys

# --sympy FILE: SymPy's times for the engine's cost table (sympy_lmod.py --table).
sympy = {}
if "--sympy" in sys.argv:
    i = sys.argv.index("--sympy")
    for line in open(sys.argv[i + 1], encoding="utf-8"):
        f = line.split()
        if len(f) == 3:
            sympy[(int(f[0]), int(f[1]))] = float(f[2])
        elif len(f) == 4 and f[2] == ">":
            sympy[(int(f[0]), int(f[1]))] = ("timeout", float(f[3]))
    del sys.argv[i:i + 2]

data = json.load(open(sys.argv[1]))
med, its, wp = {}, {}, {}
for b in data["benchmarks"]:
    if b.get("aggregate_name") != "median":
        continue
    run = b["run_name"].replace("BM_", "").split("/iterations:")[0]
    if run.startswith("wp_"):  # work-precision: method/j -> (seconds per run, angle error)
        method, j = run[3:].split("/")
        scale = {"ns": 1e-9, "us": 1e-6, "ms": 1e-3, "s": 1.0}[b.get("time_unit", "ns")]
        wp.setdefault(method, []).append((int(j), b["real_time"] * scale, b["angle_error"],
                                          b["steps"]))
        continue
    if run.startswith(("engine_", "ldisc_", "verify_")):  # seconds: engine, whole commands
        scale = {"ns": 1e-9, "us": 1e-6, "ms": 1e-3, "s": 1.0}[b.get("time_unit", "ns")]
        med[run] = b["real_time"] * scale
        continue
    name = run.split("/")[0]
    med[name] = b["ns_per_step"]
    its[name] = b.get("iterations_per_step", 0.0)
hand = med.get("hand_loop")
ctx = data.get("context", {})
print("<table class=\"vibook-bench\">")
print("<tr><th>Störmer–Verlet on Kepler</th><th>ns per step (median)</th><th>ratio to hand loop</th></tr>")
for name in ("hand_loop", "vibook", "odeint"):
    if name in med:
        ratio = med[name] / hand if hand else float("nan")
        print(f"<tr><td>{name}</td><td>{med[name]:.2f}</td><td>{ratio:.3f}</td></tr>")
print("</table>")
def verdict(ok):
    return "<b>met</b>" if ok else "<b>not met</b>"
if hand and "vibook" in med and "odeint" in med:
    r_hand = med["vibook"] / hand
    r_odeint = med["vibook"] / med["odeint"]
    print("<p>Targets, evaluated on this run: vibook within 1.1&times; the hand loop &mdash; "
          f"{verdict(r_hand <= 1.1)} (ratio {r_hand:.3f}); vibook faster than Odeint &mdash; "
          f"{verdict(r_odeint < 1.0)} (vibook/Odeint {r_odeint:.3f}).</p>")
print(f"<p>Measured on {ctx.get('num_cpus', '?')} CPU(s) at {ctx.get('mhz_per_cpu', '?')} MHz, "
      f"{ctx.get('date', '')}; median of 5 repetitions.</p>")

# Adaptive methods, Kepler e = 0.7, h0 = 1e-3, 300 steps from perihelion. The table is also
# written alone to the third argument, when given, for the EpAVI chapter.
sv = med.get("sv_e07")
ep = med.get("epavi_fast_double")
adaptive = []


def out(line):
    adaptive.append(line)


if sv and ep:
    out("<table class=\"vibook-bench\">")
    out("<tr><th>Kepler e = 0.7, h0 = 1e-3</th><th>ns per step (median)</th>"
        "<th>solver iterations per step</th><th>ratio to a Störmer–Verlet step</th>"
        "<th>ratio to double EpAVI (closed form)</th></tr>")
    labels = [("sv_e07", "Störmer–Verlet"), ("midpoint_e07", "implicit midpoint"),
              ("epavi_fast_double", "EpAVI closed form, double"),
              ("epavi_fast_long_double", "EpAVI closed form, long double"),
              ("epavi_fast_double_double", "EpAVI closed form, double-double"),
              ("epavi_fast_quad", "EpAVI closed form, quad"),
              ("epavi_double", "EpAVI generic, double"),
              ("epavi_long_double", "EpAVI generic, long double"),
              ("epavi_double_double", "EpAVI generic, double-double"),
              ("epavi_quad", "EpAVI generic, quad"),
              ("epavi_mpfr18", "EpAVI generic, MPFR 18 digits"),
              ("avi1", "AVI1"), ("avi2", "AVI2")]
    for name, label in labels:
        if name in med:
            out(f"<tr><td>{label}</td><td>{med[name]:.0f}</td><td>{its[name]:.2f}</td>"
                f"<td>{med[name] / sv:.1f}</td><td>{med[name] / ep:.2f}</td></tr>")
    out("</table>")
    nan = float("nan")
    dd = med.get("epavi_fast_double_double", nan)
    gen = med.get("epavi_double", nan)
    a1, a2 = med.get("avi1", nan), med.get("avi2", nan)
    out("<p>Targets, evaluated on this run: EpAVI (closed form) in double within 10&times; a "
        f"Störmer–Verlet step &mdash; {verdict(ep / sv <= 10)} (ratio {ep / sv:.1f}); AVI1 and "
        f"AVI2 within 5&times; &mdash; {verdict(a1 / sv <= 5 and a2 / sv <= 5)} (ratios "
        f"{a1 / sv:.1f}, {a2 / sv:.1f}); double-double EpAVI within 15&times; double EpAVI "
        f"&mdash; {verdict(dd / ep <= 15)} (ratio {dd / ep:.1f}). The closed form is "
        f"{gen / ep:.0f}&times; faster than the generic path in double. EpAVI's iterations are "
        "evaluations of the energy equation (16). On the generic path each comes with a Newton "
        "solve of the momentum equations (15) by nested AutoDiff; on the closed form, with "
        "the derivatives of (25) written out from the potential's gradient and Hessian, "
        "in double usually only the first does (after the Newton update of the step the "
        "position moves along its Taylor polynomial in the step), and that solve usually "
        "takes one force. AVI's are evaluations of the step's equation for the midpoint "
        "(a force and the monitor each), the midpoint rule's Newton iterations. mpfr18: one "
        "repetition of 300 steps (MPFR at 18 digits, the paper's VPA).</p>")

# A typed discrete Lagrangian (#28): stepped through the compiled tape and through nested
# AutoDiff, against the hand-written kernels of the same run.
mp, sv_k = med.get("midpoint_e07"), med.get("sv_e07")
typed = [(k, med[k]) for k in ("typed_midpoint_native", "typed_midpoint_tape",
                               "typed_midpoint_autodiff", "typed_trapezoid_native",
                               "typed_trapezoid_tape", "typed_trapezoid_autodiff") if k in med]
if typed and mp and sv_k:
    print("<table class=\"vibook-bench\">")
    print("<tr><th>typed --ld on Kepler e = 0.7, h = 1e-3</th><th>ns per step (median)</th>"
        "<th>Newton iterations per step</th><th>ratio to its hand-written kernel</th></tr>")
    labels = {"typed_midpoint_native": ("midpoint, compiled tape as native code", mp),
              "typed_trapezoid_native": ("trapezoidal, compiled tape as native code", sv_k),
              "typed_midpoint_tape": ("midpoint, compiled tape, interpreted", mp),
              "typed_midpoint_autodiff": ("midpoint, nested AutoDiff (--reference)", mp),
              "typed_trapezoid_tape": ("trapezoidal, compiled tape, interpreted", sv_k),
              "typed_trapezoid_autodiff": ("trapezoidal, nested AutoDiff (--reference)", sv_k)}
    for key, value in typed:
        label, kernel = labels[key]
        print(f"<tr><td>{label}</td><td>{value:.0f}</td><td>{its[key]:.2f}</td>"
            f"<td>{value / kernel:.1f}</td></tr>")
    print("</table>")
    parts = []
    best = {m: med.get(f"typed_{m}_native", med.get(f"typed_{m}_tape"))
            for m in ("midpoint", "trapezoid")}
    how = {m: "native code" if f"typed_{m}_native" in med else "interpreted tape"
           for m in ("midpoint", "trapezoid")}
    if best["midpoint"]:
        r = best["midpoint"] / mp
        parts.append(f"typed implicit midpoint within 3&times; the hand-written midpoint kernel "
                     f"&mdash; {verdict(r <= 3)} (ratio {r:.1f}, {how['midpoint']})")
        t8 = best["midpoint"] * 1e-9 * 1e8
        parts.append(f"10<sup>8</sup> steps of the typed midpoint rule in under two minutes "
                     f"&mdash; {verdict(t8 < 120)} ({t8:.0f} s at this run's time per step, "
                     "the integrator alone)")
    if best["trapezoid"]:
        r = best["trapezoid"] / sv_k
        parts.append(f"typed trapezoidal rule within 5&times; the Störmer–Verlet kernel "
                     f"&mdash; {verdict(r <= 5)} (ratio {r:.1f}, {how['trapezoid']}; the kernel "
                     "is explicit, the typed rule is solved by Newton's method)")
    for m in ("midpoint", "trapezoid"):
        a, b, c = (med.get(f"typed_{m}_{k}") for k in ("autodiff", "tape", "native"))
        if a and b:
            parts.append(f"{m}: the interpreted tape is {a / b:.1f}&times; faster than nested "
                         "AutoDiff" + (f", native code {a / c:.1f}&times;" if c else ""))
    vprk = [(k, med[k]) for k in ("vprk_lobatto3_tableau", "vprk_lobatto3_galerkin") if k in med]
    if vprk and best["midpoint"]:
        print("<table class=\"vibook-bench\">")
        print("<tr><th>3-stage Lobatto IIIA&ndash;IIIB on Kepler e = 0.7, h = 1e-3</th>"
            "<th>ns per step (median)</th><th>Newton iterations per step</th>"
            "<th>ratio to the typed midpoint rule</th></tr>")
        vlabels = {"vprk_lobatto3_tableau": "from its tableau (--tableau; Newton on the stages)",
                   "vprk_lobatto3_galerkin": "Galerkin integrator (--method lobatto:3; nested "
                                             "AutoDiff of L)"}
        for key, value in vprk:
            print(f"<tr><td>{vlabels[key]}</td><td>{value:.0f}</td><td>{its[key]:.2f}</td>"
                f"<td>{value / best['midpoint']:.1f}</td></tr>")
        print("</table>")
        fastest = min(value for _, value in vprk)
        r = fastest / best["midpoint"]
        parts.append(f"3-stage Lobatto VPRK within 5&times; the typed midpoint rule "
                     f"&mdash; {verdict(r <= 5)} (ratio {r:.1f}, the faster of the two rows "
                     "above; both are compiled for the problem, neither is typed as text)")
    readme = med.get("verify_readme_example")
    if readme is not None:
        parts.append("<code>vibook verify</code> on the README's example (the Simpson rule "
                     "typed for H&eacute;non&ndash;Heiles: consistency, orders, defects, the "
                     "10<sup>5</sup>-step energy test, the modified equation to h&sup2;) within "
                     f"2 s wall &mdash; {verdict(readme <= 2)} ({readme:.2f} s, the command as "
                     "the README prints it, process start included)")
    print("<p>Targets of the compiled discrete Lagrangian (#28), evaluated on this run: " +
        "; ".join(parts) + ".</p>")

# A library stepper behind vibook's host process (#50): per step, one request a step and one
# request a run, against the library called in this process.
box = {k: med[k] for k in ("black_box_inprocess", "black_box_host_step", "black_box_host_every")
       if k in med}
if "black_box_inprocess" in box:
    base = box["black_box_inprocess"]
    labels = {"black_box_inprocess": "called in this process (the limit)",
              "black_box_host_step": "in vibook's host process, one request a step",
              "black_box_host_every": "in vibook's host process, one request a run (every state)"}
    print("<table class=\"vibook-bench\">")
    print("<tr><th>--stepper-lib: Odeint's McLachlan 4 on Kepler</th><th>ns per step (median, "
          "wall)</th><th>ratio to the call in this process</th></tr>")
    for k, v in box.items():
        print(f"<tr><td>{labels[k]}</td><td>{v:.0f}</td><td>{v / base:.1f}</td></tr>")
    print("</table>")
    if "black_box_host_every" in box and "black_box_host_step" in box:
        print("<p>The energy phase's run of 10<sup>5</sup> steps, at these rates: "
              f"{box['black_box_host_every'] * 1e-4:.2g} s with one request a run (how "
              f"<code>vibook verify --stepper-lib</code> takes it), "
              f"{box['black_box_host_step'] * 1e-4:.2g} s with one request a step. The library "
              "runs in a child process so that a crash in it is a status, not the end of vibook "
              "(chapter \"Verify your own integrator\").</p>")

if adaptive:
    print("\n".join(adaptive))
if len(sys.argv) > 3:
    with open(sys.argv[3], "w") as f:
        f.write("\n".join(adaptive) + "\n" if adaptive else
                "<p><em>The benchmarks of the adaptive methods are not in this run.</em></p>\n")

# The modified-equation engine: derivation times (seconds, median).
eng = {k: v for k, v in med.items() if k.startswith(("engine_", "ldisc_"))}
if eng:
    print("<table class=\"vibook-bench\">")
    print("<tr><th>modified-equation engine</th><th>time (median)</th></tr>")
    labels = [("engine_sv_generic/4", "L_mod to h⁴, Störmer–Verlet, generic 1-DOF U"),
              ("engine_sv_generic/6", "L_mod to h⁶, Störmer–Verlet, generic 1-DOF U"),
              ("engine_sv_generic/8", "L_mod to h⁸, Störmer–Verlet, generic 1-DOF U"),
              ("engine_sv_kepler/4", "L_mod to h⁴, Störmer–Verlet, Kepler 2-D"),
              ("ldisc_engine/4", "L_disc([x], h) to h⁴, engine"),
              ("ldisc_ginac_series/4", "L_disc([x], h) to h⁴, GiNaC series() (one iteration per repetition)"),
              ("ldisc_engine/6", "L_disc([x], h) to h⁶, engine"),
              ("ldisc_ginac_series/6", "L_disc([x], h) to h⁶, GiNaC series() (one iteration per repetition)"),
              ("engine_varorder_gauss4_pendulum", "variational order of gauss:4 on the pendulum, derived (rule cut to 30 digits, through h⁹)"),
              ("engine_varorder_yoshida6_henon_heiles", "variational order of Yoshida-6 on Hénon–Heiles, derived (coefficients cut to 30 digits, through h⁷)")]
    for key, label in labels:
        if key in eng:
            print(f"<tr><td>{label}</td><td>{eng[key]:.4g} s</td></tr>")
    print("</table>")
    g8, k4 = eng.get("engine_sv_generic/8"), eng.get("engine_sv_kepler/4")
    parts = []
    if g8 is not None:
        parts.append(f"generic 1-DOF to h⁸ within 10 s &mdash; {verdict(g8 <= 10)} ({g8:.3g} s)")
    if k4 is not None:
        parts.append(f"Kepler 2-D to h⁴ within 5 s &mdash; {verdict(k4 <= 5)} ({k4:.3g} s)")
    g4 = eng.get("engine_varorder_gauss4_pendulum")
    if g4 is not None:
        parts.append(f"gauss:4 on the pendulum derived within 10 s &mdash; {verdict(g4 <= 10)} "
                     f"({g4:.3g} s)")
    y6 = eng.get("engine_varorder_yoshida6_henon_heiles")
    if y6 is not None:
        parts.append(f"Yoshida-6 derived within 10 s &mdash; {verdict(y6 <= 10)} ({y6:.3g} s on "
                     "Hénon–Heiles; on Kepler, the target's problem, not timed: it has not "
                     "finished within 11 CPU-minutes)")
    for k in (4, 6):
        e, g = eng.get(f"ldisc_engine/{k}"), eng.get(f"ldisc_ginac_series/{k}")
        if e and g:
            parts.append(f"L_disc to h^{k}: GiNaC series() / engine = {g / e:.1f}")
    print("<p>Targets, evaluated on this run: " + "; ".join(parts) + ".</p>")

# The engine's cost with dimension and order (#28): L_mod,K of Störmer–Verlet, generic U.
cost = {}
for k, v in eng.items():
    if k.startswith("engine_cost/"):
        _, d, o = k.split("/")
        cost[(int(d), int(o))] = v
if cost:
    orders = sorted({o for _, o in cost})
    print("<table class=\"vibook-bench\">")
    print("<tr><th>L_mod to h^K, Störmer–Verlet, generic U</th>" +
          "".join(f"<th>K = {o}</th>" for o in orders) + "</tr>")
    for d in sorted({d for d, _ in cost}):
        cells = "".join(f"<td>{cost[(d, o)]:.3g} s</td>" if (d, o) in cost else "<td>&mdash;</td>"
                        for o in orders)
        print(f"<tr><td>{d} degree(s) of freedom</td>{cells}</tr>")
        if sympy:
            def sym(key):
                t = sympy.get(key)
                if t is None:
                    return "<td>&mdash;</td>"
                if isinstance(t, tuple):
                    return f"<td>&gt; {t[1]:g} s</td>"
                return f"<td>{t:.3g} s</td>"
            print(f"<tr><td>&nbsp;&nbsp;SymPy, same derivation</td>"
                  + "".join(sym((d, o)) for o in orders) + "</tr>")
    print("</table>")
    if sympy:
        both = [(k, cost[k], sympy[k]) for k in sorted(cost) if k in sympy]
        slower = [f"{d}-D to h^{o}" for (d, o), e, t in both
                  if not (e < (t[1] if isinstance(t, tuple) else t))]
        finished = [(k, e, t) for k, e, t in both if not isinstance(t, tuple)]
        ratios = sorted(t / e for _, e, t in finished if e > 0)
        print("<p>The SymPy rows time <code>tests/bench/sympy_lmod.py</code>, our own derivation "
              "of the same L_mod,K in SymPy's sparse polynomial rings over QQ (the modified "
              "equation from the discrete Euler&ndash;Lagrange equation, no jet symbols, "
              "truncated in h after every product), in its own process after SymPy is imported, "
              "each entry stopped after its time limit; the test <code>modified_sympy</code> "
              "checks that it and the engine give the same L_mod term by term. Target: the "
              "engine faster than SymPy at every entry &mdash; "
              f"{verdict(not slower and bool(both))}"
              + (f" (slower at {', '.join(slower)})" if slower else "")
              + (f"; SymPy/engine from {ratios[0]:.2g} to {ratios[-1]:.2g} where SymPy finished"
                 if ratios else "") + ".</p>")
    names = ["sv", "se", "se-adjoint", "midpoint", "vi1", "vi1-adjoint", "vi2"]
    per_method = {names[int(k.split("/")[1])]: v for k, v in eng.items()
                  if k.startswith("engine_method_3d/") and int(k.split("/")[1]) < len(names)}
    if per_method:
        print("<table class=\"vibook-bench\">")
        print("<tr><th>H_mod to h⁴ in 3-D (with the equation and L_mod)</th>" +
              "".join(f"<th>{m}</th>" for m in per_method) + "</tr>")
        print("<tr><td>time</td>" + "".join(f"<td>{v:.3g} s</td>" for v in per_method.values()) +
              "</tr>")
        print("</table>")
    targets = [((3, 6), 4.0), ((2, 10), 6.0), ((3, 8), 18.0)]
    parts = [f"{d}-D to h^{o} within {t:g} s &mdash; {verdict(cost[(d, o)] <= t)} "
             f"({cost[(d, o)]:.3g} s)" for (d, o), t in targets if (d, o) in cost]
    k8 = eng.get("engine_sv_kepler/8")
    if k8 is not None:
        parts.append(f"Kepler 2-D to h⁸ within 30 s &mdash; {verdict(k8 <= 30)} ({k8:.3g} s)")
    if per_method:
        worst = max(per_method, key=per_method.get)
        parts.append(f"every method to h⁴ in 3-D within 5 s &mdash; "
                     f"{verdict(per_method[worst] <= 5)} (slowest {worst}, "
                     f"{per_method[worst]:.3g} s)")
    print("<p>Targets of the engine's cost (#28), evaluated on this run: " + "; ".join(parts) +
          ". One iteration per repetition.</p>")

# Work-precision against wall-clock time (Shen & Sun methods): table, and the CSV of the diagram
# when a second argument names it.
if wp:
    print("<table class=\"vibook-bench\">")
    print("<tr><th>Kepler e = 0.6, 10 periods</th><th>steps</th><th>time per run (median)</th>"
          "<th>LRL-angle error</th></tr>")
    for method in ("se", "sv", "vi1", "vi2"):
        for j, sec, err, steps in sorted(wp.get(method, [])):
            print(f"<tr><td>{method}</td><td>{int(steps)}</td><td>{sec * 1e3:.3f} ms</td>"
                  f"<td>{err:.3g}</td></tr>")
    print("</table>")
    if len(sys.argv) > 2:
        with open(sys.argv[2], "w") as f:
            f.write("method,steps,seconds,angle_error\n")
            for method in ("se", "sv", "vi1", "vi2"):
                for j, sec, err, steps in sorted(wp.get(method, [])):
                    f.write(f"{method},{int(steps)},{sec:.9g},{err:.17g}\n")
