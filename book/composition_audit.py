#!/usr/bin/env python3
"""The composition audit of the verify chapter, generated: every catalogue composition and
three deliberately wrong ones run through `vibook verify --composition` on two nonlinear
problems (Kepler, eccentricity 0.5, and Hénon–Heiles), one table row each, every number read
from the command's JSON. A catalogue row must pass and a wrong one must fail (exit 5): otherwise
this script fails the book build, since an audit that cannot flag a known defect, or flags a
correct method, certifies nothing.

usage: composition_audit.py VIBOOK OUT_HTML
"""
import html
import json
import os
import subprocess
import sys
import tempfile

VIBOOK, OUT = sys.argv[1], sys.argv[2]

# (label, base, coefficients, extra arguments, must pass)
ROWS = [
    ("yoshida4", "sv", "yoshida4", [], True),
    ("suzuki4", "sv", "suzuki4", [], True),
    ("yoshida6", "sv", "yoshida6", [], True),
    ("yoshida6 on the midpoint rule", "midpoint", "yoshida6", [], True),
    ("yoshida8", "sv", "yoshida8", [], True),
    ("mclachlan8", "sv", "mclachlan8", [], True),
    ("kahanli6", "sv", "kahanli6", [], True),
    ("kahanli8", "sv", "kahanli8", [], True),
    ("ruth3", "se", "ruth3", [], True),
    ("wrong: yoshida6 with w1 off by 1e-11 (w0 recomputed, still consistent)", "sv",
     "0.784513610477560,0.235573213359357,-1.17767998416887,1.315186320663906,"
     "-1.17767998416887,0.235573213359357,0.784513610477560", ["--expected-order", "6"], False),
    ("wrong: ruth3 with each (adjoint, base) pair applied in the other order", "se",
     "3/8,7/24*,-25/24,3/8*,0,1*", ["--expected-order", "3"], False),
    ("wrong: the triple jump (yoshida4) on a first-order base", "se", "yoshida4",
     ["--expected-order", "4"], False),
]
PROBLEMS = ["kepler", "henon-heiles"]


def run(base, coefficients, extra, problem, tmp):
    out = os.path.join(tmp, "r.json")
    cmd = [VIBOOK, "verify", "--composition", base, "--coefficients", coefficients,
           "--problem", problem, "--json-out", out] + extra
    p = subprocess.run(cmd, capture_output=True, text=True)
    if p.returncode not in (0, 5):
        sys.exit(f"composition_audit: {' '.join(cmd)} exited {p.returncode}: {p.stderr}")
    with open(out) as f:
        return p.returncode, json.load(f)


def sci(x):
    return "—" if x is None else f"{x:.1e}"


def cell(s):
    return f"<td>{s}</td>"


rows_html = []
problems_broken = []
sources = []
with tempfile.TemporaryDirectory() as tmp:
    for label, base, coefficients, extra, must_pass in ROWS:
        results = {pr: run(base, coefficients, extra, pr, tmp) for pr in PROBLEMS}
        j = results[PROBLEMS[0]][1]
        oc = j["order_conditions"]
        comp = j["composition"]
        res = oc["residual_by_weight"]
        k = oc["order"]
        if k < len(res):
            conditions = f"{k} (weight {k + 1}: {res[k]:.1e})"
        else:
            conditions = f"≥ {k}"
        newton = comp.get("newton")
        published = "—"
        if newton:
            published = (f"{max(newton['published_residual_by_weight']):.1e} (Newton moves "
                         f"them by {newton['max_change_from_published']:.1e})")
        measured = []
        for pr in PROBLEMS:
            o = results[pr][1].get("order", {})
            f = o.get("fitted")
            measured.append("—" if f is None else f"{f:.2f}")
        failed = {pr: results[pr][1]["verdict"]["failed"] for pr in PROBLEMS}
        passed_all = all(results[pr][0] == 0 for pr in PROBLEMS)
        flagged_all = all(results[pr][0] == 5 for pr in PROBLEMS)
        def parts(pr):
            return ", ".join(failed[pr])
        same = len({parts(pr) for pr in PROBLEMS}) == 1
        flags = (parts(PROBLEMS[0]) + " (both problems)" if same else
                 "; ".join(f"{pr}: {parts(pr)}" for pr in PROBLEMS if failed[pr]))
        if must_pass and not passed_all:
            verdict = "FAILS: " + flags
            problems_broken.append(f"{label}: {verdict}")
        elif must_pass:
            verdict = "agrees with its source"
        elif flagged_all:
            verdict = "flagged: " + flags
        else:
            verdict = "NOT FLAGGED"
            problems_broken.append(f"{label}: a deliberately wrong composition passed")
        sym = j.get("symplecticity", {})
        en = j.get("energy", {})
        if comp["source"] != "typed" and comp["source"] not in [x[1] for x in sources]:
            sources.append((coefficients, comp["source"], comp["derivation"]))
        rows_html.append(
            "<tr>" + cell(f"{html.escape(label)}<br><small>{len(comp['stages'])} stages of "
                          f"{base}</small>") +
            cell(f"{oc['expected']:g}<br><small>{html.escape(oc['expected_from'])}</small>") +
            cell(conditions) + cell(published) + "".join(cell(m) for m in measured) +
            cell(sci(sym.get("defect"))) + cell("yes" if comp["symmetric"] else "no") +
            cell(html.escape(en.get("verdict", "—"))) + cell(html.escape(verdict)) + "</tr>")

head = ("<tr><th>composition</th><th>expected order</th><th>order by the conditions</th>"
        "<th>published digits</th><th>order, Kepler</th><th>order, Hénon–Heiles</th>"
        "<th>symplectic defect</th><th>symmetric</th><th>energy (Kepler)</th><th>audit</th></tr>")
tmp_out = OUT + ".tmp"
with open(tmp_out, "w") as f:
    f.write("<style>table.vibook-audit { font-size: 80%; table-layout: fixed; width: 100%; }\n"
            "table.vibook-audit td { overflow-wrap: anywhere; vertical-align: top; }</style>\n"
            '<table class="doxtable vibook-audit">\n<colgroup>' +
            "".join(f'<col style="width: {w}%">' for w in (20, 8, 11, 12, 7, 8, 8, 7, 9, 10)) +
            "</colgroup>\n" + head + "\n" + "\n".join(rows_html) +
            "\n</table>\n<p>Where the coefficients come from:</p>\n<ul>\n" +
            "".join(f"<li><b>{html.escape(n)}</b>: {html.escape(src)}; {html.escape(der)}.</li>\n"
                    for n, src, der in sources) + "</ul>\n")
os.replace(tmp_out, OUT)
if problems_broken:
    sys.exit("composition_audit: the audit is wrong about a known case:\n  " +
             "\n  ".join(problems_broken))
