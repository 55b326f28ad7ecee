#!/usr/bin/env python3
"""Every printed formula accounted for: one table per paper, written during the book build.

Usage: formulas.py CLAIMS_JSON DISPLAYS_JSON GEN_DIR

DISPLAYS_JSON is `vibook displays --inline --json`: every display of the three papers as vibook
finds it in their text, with its number, place and LaTeX. CLAIMS_JSON is this build's ledger
(`vibook claims`), whose claims carry the comparisons their checks made: a display quoted
verbatim from the paper, read by vibook's LaTeX reader, compared with vibook's side, and where
it differs, the correction found.

The table has one row per numbered display and per display of a worked example (no ranges),
and a row for every other display or inline formula that a check compared. A row's outcome
comes from the ledger only:

  agrees         every comparison of that display, read from its quoted LaTeX, agrees; the
                 checks and claims are named;
  erratum        a comparison found it wrong and the erratum gives the corrected LaTeX;
  does not hold  wrong, and no small edit corrects it (the erratum gives our formula, verified
                 another way), or no correction was found (the search is described);
  not read       the reader could not parse it (the message and the LaTeX are shown).

A row with no comparison takes its outcome from the annotations below, typed once: "used"
(a definition the library takes as printed, with where), "none" (not compared, and why), or
"measured" (the display is not read as a formula, but a claim measures what it states), or
"erratum" (an erratum measured numerically, not read: the reason is given). An annotation on
a display that a check compared is an error (the comparison decides), unless it comes from a
range. The build fails when a numbered or example display has neither a comparison nor an
annotation, when an annotation names a display the paper does not have, when an erratum of
the ledger appears in no row, and when a row would say "agrees" without a comparison.

It writes GEN_DIR/formulas-S.html, formulas-V.html, formulas-SS.html and
formulas-summary.html.
"""
import html
import json
import os
import re
import sys

import bookfiles

# --- annotations: rows without a comparison ------------------------------------------------
# Keys are display ids ("(14)", "L276") or ranges "(2)–(5)" over the numbered displays in the
# paper's order.
S = {
    "(1)": ("none", "the space of admissible curves: a definition, nothing to evaluate"),
    "(2)–(5)": ("none", "the continuous extended action and its variation, the derivation of "
                        "(6)–(7); vibook starts from the discrete action (9)"),
    "(6)–(7)": ("none", "the continuous extended Euler–Lagrange equations; vibook integrates "
                        "their discretization, whose equations (11)–(12) are compared"),
    "(8)": ("none", "a definition: discrete curves with increasing times"),
    "(9)": ("used", "the discrete action Σ L_d: (11) and (12) are compared with its "
                    "derivatives (mechanics/extended.hpp)"),
    "(10)": ("none", "the variation of (9) written out; its coefficients are (11) and (12), "
                     "which are compared"),
    "(19)–(20)": ("none", "the Poincaré-transformed Hamiltonian and its equations; AVI "
                          "integrates them by (21)–(23)"),
    "(21)–(23)": ("measured", "S-F1", "AVI's implicit midpoint step in the transformed time, "
                                      "written by hand in avi/avi.hpp (not read from the "
                                      "display); AVI1 and AVI2 are run in Figs. 1–3"),
    "(28)": ("none", "an identity: the energy as a telescoping sum"),
    "(29)": ("measured", "S-EQ29", "the bound on the accumulated energy error, measured over "
                                   "10⁶ steps"),
    "(30)": ("none", "an estimate with assumed numbers; S-EQ29 measures the bound (29) itself"),
    "(31)": ("measured", "S-L1", "the transformed Lagrangian, written in check-s-l1 (not read "
                                 "from the display); its instance (56) is compared"),
    "(32)–(33)": ("none", "the continuous Euler–Lagrange equations of (31); their discrete "
                          "form is measured through Lemma 1 (S-L1)"),
    "(34)–(37)": ("measured", "S-L1", "the discrete action of (31), L̄_d and its discrete "
                                      "Euler–Lagrange equations, written in check-s-l1 and "
                                      "measured through Lemma 1"),
    "(38)": ("none", "a definition: the discrete action in Vermeeren's scaling"),
    "(42)–(45)": ("none", "the general construction of the modified equation (discrete "
                          "Euler–Lagrange operators, ψ, the meshed Lagrangian); the engine "
                          "builds it (modified/engine.hpp) and its instance (56)–(66) is "
                          "compared"),
    "(47)–(55)": ("none", "the general construction continued (the modified Lagrangian and "
                          "its equations); its instance (56)–(66) is compared"),
}

V = {
    "(1)–(3)": ("none", "the continuous action, its variation and Euler–Lagrange equation: "
                        "standard, nothing to evaluate"),
    "(6)": ("none", "Hamilton's equations: standard; vibook works on the Lagrangian side"),
    "(7)": ("none", "the modified equation of a first-order system; vibook treats second-order "
                    "equations (8)–(10)"),
    "(8)–(10)": ("none", "the construction of the modified equation that the engine implements "
                         "(modified/engine.hpp); its results are compared in Example 2 and §5"),
    "L276": ("none", "the form of the answer (f₀ + h²f₂); its coefficients are compared in the "
                     "next displays"),
    "L284": ("none", "an intermediate expansion in a general f(x, ẋ), written with "
                     "f_{0,xv}(f₀, v), a notation the reader does not take; the result (22) is "
                     "compared"),
    "L314": ("none", "the intermediate expansion of Example 3; its solution −x − h²x/12 − "
                     "h⁴x/90 (the displays after it) is compared"),
    "(11)–(12)": ("none", "natural boundary conditions of a meshed variational problem: "
                          "theory, nothing to evaluate"),
    "(13)": ("used", "the definition of L_disc([x], h) the engine implements "
                     "(modified/engine.hpp); its Störmer–Verlet instance L805 is compared"),
    "(14)–(15)": ("none", "properties of admissible families in the proof of Theorem 16"),
    "(16)–(17)": ("measured", "V-T16", "the defect of k-critical families, measured as an "
                                       "order along truncated modified solutions"),
    "(18)–(20)": ("none", "steps of the proof of Theorem 16; its conclusion is measured "
                          "(V-T16)"),
}

SS = {
    "(2.1)": ("used", "the second-order system of the Helmholtz conditions "
                      "(mechanics/helmholtz.hpp)"),
    "(2.2a)–(2.2c)": ("measured", "SS-T2", "the Helmholtz conditions, written in "
                                           "mechanics/helmholtz.hpp (not read from the "
                                           "display) and evaluated on Kepler, (2.7), a Lorentz "
                                           "force and a damped oscillator"),
    "(2.3)–(2.4)": ("none", "steps of the proof of Theorem 2"),
    "(2.5a)–(2.6b)": ("measured", "SS-T2", "the conditions of Theorems 3–4, written in "
                                           "mechanics/helmholtz.hpp and evaluated there"),
    "(3.1)": ("none", "a definition: the discrete action in the paper's scaling h Σ 𝕃"),
    "(3.2)": ("none", "the Newtonian equation ẍ = −∇φ: the problem the methods of §3 solve"),
    "(3.3)–(3.6b)": ("measured", "SS-T6", "L^1st, its Legendre maps and the explicit update, "
                                          "written in integrators/splitting.hpp (not read "
                                          "from the displays): the generic solver on L^1st "
                                          "equals the composition to round-off"),
    "(3.7)–(3.11)": ("measured", "SS-T7", "L^2nd, its equations and Legendre maps, written in "
                                          "integrators/splitting.hpp: the generic solver on "
                                          "L^2nd equals the symmetric composition"),
    "(3.12)": ("none", "the Kepler problem ẍ = −x/|x|³; its Lagrangian (3.13) is compared"),
    "(3.14)–(3.15)": ("none", "VI-1 and VI-2 written out for Kepler: the code implements the "
                              "general forms (3.6) and (3.11), measured by SS-T6 and SS-T7; "
                              "these instances are not read"),
    "(3.16)": ("used", "the relativistic system in proper time "
                       "(relativistic/relativistic.hpp)"),
    "(3.17)": ("used", "the Lagrangian L = ½ẋᵀMẋ + A·ẋ: its M and A define the notation "
                       "with which (3.20) is read"),
    "(3.18)": ("used", "the K-symplectic form, whose subflows relativistic.hpp implements"),
    "(3.19)": ("erratum", "SS-ERR-3.19", "a composition of flows, which the reader does not "
                                         "evaluate: measured on the composition as we "
                                         "transcribe it"),
    "(3.21)": ("none", "the transformation in the proof of Theorem 8; its result (3.22) is "
                       "measured"),
    "(3.22)": ("measured", "SS-T8", "the explicit form of (3.20), written in relativistic.hpp "
                                    "(Vi322; not read from the display): equal to the generic "
                                    "solver on (3.20) and to the composition to round-off"),
    "(4.1)": ("none", "a definition: the second-order system of §4"),
    "(4.2)–(4.3)": ("none", "the modified equation of a two-step method: the construction "
                            "Vermeeren's (8)–(10) give, which the engine implements; its "
                            "instances in §4 are compared, and so are the derivatives "
                            "(4.4a)–(4.4b) built from it"),
    "(4.5a)–(4.5c)": ("used", "Nyström methods: the four tableaux of Theorem 10's comparison "
                              "(modified/engine.hpp)"),
    "(4.7)": ("none", "a step of the proof of Theorem 10 (the internal stages); the result "
                      "(4.8a)–(4.8b) is compared"),
    "(4.9)–(4.12)": ("none", "the definition of the modified Lagrangian, as in Vermeeren §4 "
                             "(the engine implements it); its instances (4.14)–(4.25) are "
                             "compared"),
    "(4.26)–(4.27)": ("measured", "SS-T13", "Theorem 13's one-period LRL changes, predicted "
                                            "from the modified Lagrangians and measured "
                                            "(check-ss-t13); Theorem 16's Δ|A| and Δω (L662, "
                                            "L666) are compared with them, each with the "
                                            "formula its label names"),
    "(4.28)": ("none", "a step of the proof of Theorem 13"),
    "(A1)–(A4)": ("none", "the differential equation of arcsin² and its series ansatz in "
                          "Appendix A; the coefficients a_{2k} (L768) and (A5) are compared"),
}

PAPERS = [("S", "Sharma et al. 2022", S), ("V", "Vermeeren 2017", V),
          ("SS", "Shen &amp; Sun 2025", SS)]

KINDS = [("agrees", "agrees"), ("erratum", "erratum"), ("does-not-hold", "does not hold"),
         ("unreadable", "not read"), ("used", "used as printed"),
         ("measured", "measured, not read"), ("none", "not compared")]


def expand(key, numbered):
    """The display ids an annotation key names: one id, or a range over numbered displays."""
    if "–" not in key:
        return [key], False
    a, b = key.split("–")
    if a not in numbered or b not in numbered:
        raise KeyError(f"annotation range {key}: no display {a if a not in numbered else b}")
    i, j = numbered.index(a), numbered.index(b)
    if j < i:
        raise KeyError(f"annotation range {key} is reversed")
    return numbered[i:j + 1], True


def claim_link(cid):
    c = html.escape(cid)
    return f'<a href="report.html#claim-{c}">{c}</a>'


def math(latex):
    """The formula in a box of its own that scrolls sideways when it is wide. Inline math in
    display style: the book numbers every display (mathjax-config.js), and these are the
    papers' formulas, not the book's. For rendering only, a \\tag{X} is written (X), a
    line break outside an environment is put in one, and in a display of several rows or with
    unbalanced delimiters \\left/\\right become fixed sizes (\\Bigl/\\Bigr): the papers break
    a \\left( ... \\right) over the rows of an aligned display, or close one \\left| twice,
    which TeX (and MathJax) cannot typeset. The text compared is the paper's."""
    if not latex:
        return ""
    tex = re.sub(r"\\tag\{([^}]*)\}", r"\\quad (\1)", latex)
    if "\\\\" in tex or len(re.findall(r"\\left(?![a-zA-Z])", tex)) != len(
            re.findall(r"\\right(?![a-zA-Z])", tex)):
        tex = re.sub(r"\\(left|right)\s*\.", "", tex)
        tex = re.sub(r"\\left(?![a-zA-Z])\s*", r"\\Bigl", tex)
        tex = re.sub(r"\\right(?![a-zA-Z])\s*", r"\\Bigr", tex)
    if ("\\\\" in tex or "&" in tex) and "\\begin" not in tex:
        tex = "\\begin{aligned}" + tex + "\\end{aligned}"
    return '<div class="formula-scroll">\\(\\displaystyle ' + html.escape(tex) + "\\)</div>"


def main():
    claims_json, displays_json, gen = sys.argv[1], sys.argv[2], sys.argv[3]
    with open(claims_json, encoding="utf-8") as f:
        claims = {c["id"]: c for c in json.load(f)["claims"]}
    with open(displays_json, encoding="utf-8") as f:
        displays = json.load(f)

    # Every comparison of the ledger, once, with the claim it belongs to and its erratum.
    erratum_of = {}
    for cid, c in claims.items():
        if "-ERR-" in cid:
            for x in c.get("comparisons", []):
                erratum_of[(x["paper"], x["display"], x["check"], x["part"])] = cid
    comps = {}
    seen = set()
    for cid, c in claims.items():
        if "-ERR-" in cid:
            continue
        for x in c.get("comparisons", []):
            key = (x["paper"], x["display"], x["check"], x["part"], x["quote"])
            if key in seen:
                continue
            seen.add(key)
            comps.setdefault((x["paper"], x["display"]), []).append((cid, x))
    # Errata whose comparisons no claim carries (none should; kept for safety).
    for cid, c in claims.items():
        if "-ERR-" in cid:
            for x in c.get("comparisons", []):
                key = (x["paper"], x["display"], x["check"], x["part"], x["quote"])
                if key not in seen:
                    seen.add(key)
                    comps.setdefault((x["paper"], x["display"]), []).append((cid, x))

    named_errata = set()
    counts = {}
    problems = []
    n_compared = n_unread = n_unread_errata = 0
    for key, name, notes in PAPERS:
        mine = [d for d in displays if d["paper"] == key]
        ids = [d["id"] for d in mine]
        numbered = [d["id"] for d in mine if d["number"]]
        annotation = {}
        for k, how in notes.items():
            try:
                targets, ranged = expand(k, numbered)
            except KeyError as e:
                problems.append(f"{key}: {e}")
                continue
            for t in targets:
                if t not in ids:
                    problems.append(f"{key}: annotation names {t}, which the paper does not have")
                annotation[t] = (how, ranged)
        out = ['<table class="vibook-formulas">\n<tr><th>Display</th><th>Where</th>'
               '<th>As printed</th><th>Outcome</th><th>Ours, or the correction</th></tr>\n']
        for d in mine:
            did = d["id"]
            cs = comps.get((key, did), [])
            row_wanted = (not d["inline"] and (d["number"] or d["context"].startswith("Example"))) or cs
            if not row_wanted:
                continue
            where = html.escape(d["section"] + (" · " + d["context"] if d["context"] else ""))
            # its place in the paper's terms; the section and context are the next column
            label = html.escape(d["place"] if not d["number"] else "(" + d["number"] + ")")
            if cs:
                if did in annotation and not annotation[did][1]:
                    problems.append(f"{key} {did}: annotated but compared by "
                                    f"{cs[0][1]['check']}: the comparison decides; remove the "
                                    f"annotation")
                css, text, ours = outcome_compared(cs, claims, erratum_of, named_errata)
                n_compared += 1
                n_unread += css == "unreadable"
            elif did in annotation:
                css, text, ours = outcome_annotated(annotation[did][0], claims, named_errata,
                                                    problems, key, did)
            else:
                problems.append(f"{key} {did}: neither compared nor annotated "
                                f"({d['latex'][:60]}…)")
                continue
            if css == "agrees" and not cs:
                problems.append(f"{key} {did}: 'agrees' without a comparison")
            counts[(key, css)] = counts.get((key, css), 0) + 1
            if not cs and css in ("erratum", "does-not-hold"):
                n_unread_errata += 1
            out.append(f'<tr class="formula-{css}" id="formula-{key}-{html.escape(did)}">'
                       f'<td>{label}</td><td>{where}</td><td>{math(d["latex"])}</td>'
                       f'<td>{text}</td><td>{ours}</td></tr>\n')
        out.append("</table>\n")
        bookfiles.write_text(os.path.join(gen, f"formulas-{key}.html"), "".join(out))
    unexplained = sorted(i for i, c in claims.items()
                         if "-ERR-" not in i and c["status"] in ("not-reproduced", "erratum")
                         and (not c.get("cause") or not c.get("headline")))
    if unexplained:
        problems.append("claims not reproduced (or only with misprints corrected) without a cause "
                        f"and a headline saying what failed: {', '.join(unexplained)}")
    missing = sorted(i for i in claims if "-ERR-" in i and i not in named_errata)
    if missing:
        problems.append(f"errata of the ledger in no formula row: {', '.join(missing)}")
    if problems:
        sys.exit("formulas.py:\n  " + "\n  ".join(problems))
    summary = ['<table class="vibook-summary">\n<tr><th>paper</th>']
    summary += [f"<th>{t}</th>" for _, t in KINDS] + ["</tr>\n"]
    for key, name, _ in PAPERS:
        summary.append(f"<tr><td>{name}</td>")
        summary += [f'<td class="formula-{k}">{counts.get((key, k), 0)}</td>' for k, _ in KINDS]
        summary.append("</tr>\n")
    summary.append("</table>\n")
    summary.append(f"<p>{n_compared} displays read from the papers and compared; "
                   f"{n_unread} of them the reader could not parse.")
    if n_unread_errata:
        summary.append(f" The erratum and does-not-hold columns also count {n_unread_errata} "
                       f"display{'s' if n_unread_errata > 1 else ''} found wrong by a measurement "
                       f"and not read as a formula (the row says which), so the first four "
                       f"columns sum to {n_compared + n_unread_errata}.")
    summary.append("</p>\n")
    bookfiles.write_text(os.path.join(gen, "formulas-summary.html"), "".join(summary))
    print(f"formulas: {n_compared} displays compared ({n_unread} not read), outcomes from "
          f"{claims_json}")


def outcome_compared(cs, claims, erratum_of, named_errata):
    """(css, outcome HTML, ours HTML) of a display some check compared."""
    deciding = [(cid, x) for cid, x in cs if x.get("role") != "cross-check"] or cs
    parts = []
    ours = []
    worst = "agrees"
    order = ["agrees", "erratum", "does-not-hold", "unreadable"]
    for cid, x in deciding:
        check = html.escape(x["check"])
        part = html.escape(x["part"])
        if x["outcome"] == "agrees":
            parts.append(f"agrees: {part}, against {html.escape(x['against'])} "
                         f"{html.escape(x['through'])} ({check}, {claim_link(cid)})")
            ours.append(math(x["ours"]))
            continue
        if x["outcome"] == "unreadable":
            kind = "unreadable"
            parts.append(f"not compared: the reader cannot parse it ({html.escape(x['detail'])}; "
                         f"{check}, {claim_link(cid)})")
        else:
            eid = erratum_of.get((x["paper"], x["display"], x["check"], x["part"]))
            if eid:
                named_errata.add(eid)
            elink = claim_link(eid) if eid else "no erratum entry"
            if x["corrected"]:
                kind = "erratum"
                parts.append(f"erratum {elink}: {part} — {html.escape(x['edit'])}; the "
                             f"correction agrees with {html.escape(x['against'])} ({check}, "
                             f"{claim_link(cid)})")
                ours.append("corrected: " + math(x["corrected"]))
            else:
                kind = "does-not-hold"
                why = ("no small edit corrects it; ours, verified by " + html.escape(x["verified"])
                       if x["verified"] else html.escape(x["search"]))
                parts.append(f"does not hold {elink}: {part} — {html.escape(x['detail'])}; "
                             f"{why} ({check}, {claim_link(cid)})")
                ours.append("ours: " + math(x["ours"]))
        if order.index(kind) > order.index(worst):
            worst = kind
    for cid, x in cs:
        if x.get("role") == "cross-check":
            parts.append(f"cross-check ({html.escape(x['part'])}): {html.escape(x['outcome'])}")
    return worst, "<br>".join(parts), "<br>".join(o for o in ours if o)


def outcome_annotated(how, claims, named_errata, problems, key, did):
    kind = how[0]
    if kind == "used":
        return "used", "used as printed: " + html.escape(how[1]), ""
    if kind == "none":
        return "none", "not compared: " + html.escape(how[1]), ""
    cid = how[1]
    if cid not in claims:
        problems.append(f"{key} {did}: claim {cid} is not in the ledger")
        return "none", "", ""
    status = html.escape(claims[cid]["status"])
    if kind == "measured":
        return ("measured", f"not read as a formula; measured: {html.escape(how[2])} "
                            f"({claim_link(cid)}, {status})", "")
    if kind == "erratum":
        named_errata.add(cid)
        return ("erratum" if claims[cid]["status"] == "erratum" else "does-not-hold",
                f"erratum {claim_link(cid)} ({status}), not read: {html.escape(how[2])}", "")
    problems.append(f"{key} {did}: unknown annotation kind {kind}")
    return "none", "", ""


if __name__ == "__main__":
    main()
