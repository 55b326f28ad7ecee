#!/usr/bin/env python3
"""The Galerkin methods' table of the verify chapter, generated: `vibook verify --method M
--problem P` for every catalogue method on the three nonlinear test problems, one row per
method, every number read from the command's JSON; then Gauss 4 on Kepler over a hand-chosen
list of step sizes, with the local slopes between neighbours (where the order-8 methods meet
their round-off floor). Verdicts are printed as measured: a failed order is shown, not hidden.

usage: method_table.py VIBOOK OUT_HTML
"""
import html
import json
import math
import os
import subprocess
import sys
import tempfile
from concurrent.futures import ThreadPoolExecutor

VIBOOK, OUT = sys.argv[1], sys.argv[2]
METHODS = ["gauss:1", "gauss:2", "gauss:3", "gauss:4",
           "lobatto:2", "lobatto:3", "lobatto:4", "lobatto:5"]
PROBLEMS = ["kepler", "henon-heiles", "pendulum"]
WALK = "0.2,0.16,0.125,0.1,0.08,0.0625,0.05,0.04,0.03125,0.025,0.02"


def run(args, tmp, name):
    out = os.path.join(tmp, name + ".json")
    cmd = [VIBOOK, "verify"] + args + ["--json-out", out]
    p = subprocess.run(cmd, capture_output=True, text=True)
    if p.returncode not in (0, 5):
        sys.exit(f"method_table: {' '.join(cmd)} exited {p.returncode}: {p.stderr}")
    with open(out) as f:
        return json.load(f)


with tempfile.TemporaryDirectory() as tmp:
    jobs = [(m, pr) for m in METHODS for pr in PROBLEMS]
    with ThreadPoolExecutor(max_workers=2) as pool:
        results = dict(zip(jobs, pool.map(
            lambda j: run(["--method", j[0], "--problem", j[1]], tmp,
                          j[0].replace(":", "-") + "-" + j[1]), jobs)))
    walk = run(["--method", "gauss:4", "--problem", "kepler", "--h-list", WALK], tmp, "walk")

rows = []
for m in METHODS:
    first = results[(m, PROBLEMS[0])]
    cells = [f"<td><code>{m}</code></td>",
             f"<td>{first['method']['documented_order']}</td>"]
    for pr in PROBLEMS:
        j = results[(m, pr)]
        fitted = j["order"]["fitted"]
        ok = j["order"]["passed"]
        cells.append("<td>{}{}</td>".format("—" if fitted is None else f"{fitted:.2f}",
                                            "" if ok else " (fails)"))
    sym = max(results[(m, pr)]["symplecticity"]["defect"] for pr in PROBLEMS)
    rev = max(results[(m, pr)]["reversibility"]["defect"] for pr in PROBLEMS)
    passed = [pr for pr in PROBLEMS if results[(m, pr)]["verdict"]["passed"]]
    cells += [f"<td>{sym:.1e}</td>", f"<td>{rev:.1e}</td>",
              "<td>{}</td>".format(html.escape(results[(m, 'kepler')]["energy"]["verdict"])),
              "<td>{}</td>".format("all three" if len(passed) == 3 else
                                   html.escape(", ".join(passed) or "none"))]
    rows.append("<tr>" + "".join(cells) + "</tr>")

h, e = walk["order"]["h"], walk["order"]["error"]
slopes = []
for i in range(1, len(h)):
    s = math.log(e[i - 1] / e[i]) / math.log(h[i - 1] / h[i]) if e[i] > 0 and e[i - 1] > 0 else None
    slopes.append(f"h = {h[i]:g}: error {e[i]:.1e}, slope {s:.2f}" if s is not None else
                  f"h = {h[i]:g}: error {e[i]:.1e}")

head = ("<tr><th>method</th><th>documented order</th><th>order, Kepler</th>"
        "<th>order, Hénon–Heiles</th><th>order, pendulum</th><th>symplectic defect (largest)</th>"
        "<th>reversibility defect (largest)</th><th>energy (Kepler)</th><th>verdict passes on</th>"
        "</tr>")
tmp_out = OUT + ".tmp"
with open(tmp_out, "w") as f:
    f.write('<table class="doxtable">\n' + head + "\n" + "\n".join(rows) + "\n</table>\n"
            "<p>Gauss 4 on Kepler over the step sizes " + html.escape(WALK) +
            ": the error at T = 5 and the local slope from the size before.</p>\n<ul>\n" +
            "".join(f"<li>{html.escape(x)}</li>\n" for x in slopes) + "</ul>\n")
os.replace(tmp_out, OUT)
