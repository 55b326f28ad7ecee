#!/usr/bin/env python3
"""Every printed formula accounted for: one table per paper, written during the book build.

Usage: formulas.py CLAIMS_JSON GEN_DIR

Below, for each paper, is the list of its displayed equations (numbered ones, and the displays
of its worked examples), each with what it is, where vibook implements it, and how it is
compared. That list is ours, typed once, like the claims catalogue: it says *which* check
compares an equation. The *outcome* is not typed: it is read from this build's claims ledger
(CLAIMS_JSON, written by `vibook claims`):

  ("claim", ID[, VIA])       agrees / does not agree, as the claim's measured status says (VIA:
                             how the claim reaches this equation, when it does so indirectly);
  ("erratum", ID)            erratum, when the check confirmed that the print is wrong and
                             the correction right (status `erratum`);
  ("value", ID, NAME, BOUND) agrees when the measured value NAME of claim ID is at most BOUND;
  ("used", TEXT)             a definition the library uses as printed (nothing to derive);
  ("none", TEXT)             not compared, and why.

The script fails when a claim it names is missing from the ledger, or when an erratum of the
ledger appears in no row (every printed formula found wrong must be in its paper's table).
It writes GEN_DIR/formulas-S.html, formulas-V.html, formulas-SS.html and formulas-summary.html.
"""
import html
import json
import os
import sys

import bookfiles

EPS = 2.0 ** -52

S = [
    ("(1)", "§2.1", "admissible curves of the extended configuration space",
     ("none", "a definition of the space of curves; nothing to compute")),
    ("(2)–(5)", "§2.1", "extended action and its variation",
     ("none", "the derivation of (6)–(7); vibook starts from the discrete action (9)")),
    ("(6)–(7)", "§2.1", "extended Euler–Lagrange equations (motion and energy balance)",
     ("none", "the continuous equations are integrated only through their discretizations; "
              "their discrete forms (11)–(12) are checked")),
    ("(8)", "§2.2", "discrete curves with increasing times", ("none", "a definition")),
    ("(9)–(13)", "§2.2", "discrete action, its variation, the two-step equations, momentum",
     ("claim", "S-DEL")),
    ("(14)", "§2.2", "discrete energy E_k = D3 L_d", ("erratum", "S-ERR-14")),
    ("(15)–(18)", "§2.2", "time-marching form (mechanics/extended.hpp, epavi/mechanical.hpp)",
     ("claim", "S-DEL")),
    ("(19)–(20)", "§3.1", "Poincaré-transformed Hamiltonian and its equations",
     ("used", "avi/avi.hpp integrates them by (21)–(23)")),
    ("(21)–(23)", "§3.1", "AVI: implicit midpoint rule in the transformed time",
     ("none", "implemented as printed (avi/avi.hpp) and tested there (avi/avi_test.cpp); the "
              "paper gives no second form to compare with")),
    ("(24)", "§3.2", "Kepler Hamiltonian", ("used", "kepler/kepler.hpp")),
    ("(25)", "§3.2.1", "midpoint extended discrete Lagrangian",
     ("used", "mechanics/extended.hpp; everything derived from it is checked in (15)–(18), "
              "(39)–(41) and Lemma 1")),
    ("(26)–(27)", "§3.2.1", "monitor functions g1, g2", ("used", "avi/avi.hpp")),
    ("(28)", "§3.3", "energy as a telescoping sum", ("none", "an identity")),
    ("(29)", "§3.3", "bound on the accumulated energy error", ("claim", "S-EQ29")),
    ("(30)", "§3.3", "the paper's example: 10⁹ steps for 10⁻⁶",
     ("none", "an estimate with assumed numbers; S-EQ29 measures the bound (29) itself")),
    ("(31)", "§4.1", "time-transformed Lagrangian", ("claim", "S-L1")),
    ("(32)–(33)", "§4.1", "Euler–Lagrange equations of (31)",
     ("none", "continuous; their discrete form (36)–(37) is checked")),
    ("(34)–(37)", "§4.1", "discrete action, L̄_d and its discrete Euler–Lagrange equations "
                          "(Lemma 1)", ("claim", "S-L1")),
    ("(38)", "§4.2", "discrete action in Vermeeren's scaling", ("none", "a definition")),
    ("(39)–(40)", "§4.2", "Kepler midpoint momentum equations", ("erratum", "S-ERR-39")),
    ("(41)", "§4.2", "Kepler midpoint energy equation",
     ("value", "S-EQ39", "max_rel_dev_printed_41", 1e3 * EPS)),
    ("(42)–(44)", "§4.2", "discrete Euler–Lagrange operators ψ and the modified equation to "
                          "order r", ("none", "general definitions; the engine builds them "
                                              "(modified/engine.hpp) and they are compared in "
                                              "the example (56)–(66)")),
    ("(45)–(55)", "§4.3", "meshed and modified Lagrangians of the transformed integrator",
     ("claim", "S-EQ58", "through its instance (56)–(66)")),
    ("(56)–(59)", "§4.4", "example: L̄, L̄_disc, L̄_disc([q̄]) and L̄_mesh of a 1-DOF system",
     ("claim", "S-EQ58")),
    ("(60)", "§4.4", "example: modified Euler–Lagrange equation in q (h² term)",
     ("erratum", "S-ERR-60")),
    ("(61)", "§4.4", "example: modified energy equation", ("erratum", "S-ERR-61")),
    ("(62)", "§4.4", "example: (60) and (61) combined before solving for q''",
     ("none", "an intermediate step; its solved form (63) is compared")),
    ("(63)–(64)", "§4.4", "example: modified equation and modified Lagrangian",
     ("claim", "S-EQ58")),
    ("(65)", "§4.4", "example: Euler–Lagrange equation of L̄_mod,3 (last h² term)",
     ("erratum", "S-ERR-65")),
    ("(66)", "§4.4", "example: that equation solved for q''", ("claim", "S-EQ58")),
]

V = [
    ("(1)–(3)", "§2", "action, its variation, Euler–Lagrange equation",
     ("used", "mechanics/del_solver.hpp works with the discrete forms")),
    ("(4)", "§2", "discrete Euler–Lagrange equations", ("claim", "V-EX1")),
    ("(5)", "§2", "discrete Legendre maps", ("erratum", "V-ERR-5")),
    ("Example 1 (a)–(d)", "§2", "midpoint, Störmer–Verlet and the two symplectic Euler "
                                "discrete Lagrangians, and the methods they generate",
     ("claim", "V-EX1")),
    ("(6)", "§2", "Hamilton's equations", ("none", "standard; vibook works on the Lagrangian side")),
    ("Proposition 1", "§2", "the discrete Euler–Lagrange expression is consistent",
     ("claim", "V-P1")),
    ("(7)", "§3.1", "modified equation of a one-step method (first-order equations)",
     ("none", "vibook treats second-order equations (8)–(10) only")),
    ("(8)–(10)", "§3.2", "expansion of the difference equation, the substitution of "
                         "higher derivatives, the form of the modified equation",
     ("claim", "V-EX2", "through Example 2 and the examples of §5")),
    ("Example 2", "§3.2", "Störmer–Verlet modified equation to h²", ("claim", "V-EX2")),
    ("Example 3", "§3.2", "harmonic oscillator: −x − h²x/12 − h⁴x/90, period 6 at h = 1, "
                          "the arcsin² form", ("claim", "V-EX3")),
    ("(11)–(12)", "§4.1", "natural boundary conditions of a meshed variational problem",
     ("none", "theory; no formula to evaluate")),
    ("(13)", "§4.2", "L_disc([x], h)", ("claim", "V-SV2", "for Störmer–Verlet, to h⁴ with V-SV4")),
    ("Lemma 6, Definition 6", "§4.2", "midpoint-sum-to-integral coefficients "
                                      "(2^{1−2i} − 1)B_{2i}/(2i)!", ("claim", "V-L6")),
    ("(14)–(15), (18)–(20)", "§4.3–4.4", "properties of admissible families; steps of the "
                                         "proof of Theorem 16",
     ("none", "hypotheses and proof steps; the theorem's conclusion is measured (V-T16)")),
    ("(16)–(17), Theorem 16", "§4.4", "k-critical families: defect O(h^{k+1})",
     ("claim", "V-T16")),
    ("(21)", "§5.1.1", "Störmer–Verlet L_mesh to h²", ("claim", "V-SV2")),
    ("(22)–(23)", "§5.1.1", "Störmer–Verlet modified equation and L_mod,3", ("claim", "V-SV2")),
    ("§5.1.2, h⁴ terms", "§5.1.2", "fourth-order L_disc, L_mesh, modified equation",
     ("claim", "V-SV4")),
    ("§5.1.2, L_mod,5", "§5.1.2", "the h⁴ term of L_mod,5", ("erratum", "V-ERR-SV4")),
    ("Example 4", "§5.1.1", "Kepler: L_mod,3, the modified equation, the precession",
     ("claim", "V-EX4")),
    ("(24)–(25)", "§5.2", "symplectic Euler L_mod,2 and H_mod,2", ("claim", "V-SE")),
    ("Example 5", "§5.2", "anisotropic oscillator: first-order modified equation",
     ("claim", "V-EX5")),
]

SS = [
    ("(2.1)", "§2", "second-order system d/dt(M ẋ) = f", ("used", "mechanics/helmholtz.hpp")),
    ("(2.2a)–(2.2c), Theorem 2", "§2", "Helmholtz conditions", ("claim", "SS-T2")),
    ("(2.3)–(2.4)", "§2", "steps of the proof of Theorem 2", ("none", "proof steps")),
    ("(2.5a)–(2.5c), Theorem 3", "§2", "conditions for a Lorentz-type force", ("claim", "SS-T2")),
    ("(2.6a)–(2.6b), Theorem 4", "§2", "conditions for constant M", ("claim", "SS-T2")),
    ("(2.7)", "§2", "relativistic system: variational", ("claim", "SS-T2")),
    ("Lagrangian of (2.7)", "§2", "−c²γ⁻¹ + φ as printed", ("erratum", "SS-ERR-2.7")),
    ("Propositions 2, 4", "§2", "Kepler invariants H, m, A and their Noether characteristics",
     ("claim", "SS-P4")),
    ("N[x], proof of Proposition 4", "§2", "the operator N[x]", ("erratum", "SS-ERR-P4")),
    ("(3.1)–(3.2)", "§3", "discrete action, discrete Euler–Lagrange equations, ẍ = −∇φ",
     ("used", "mechanics/del_solver.hpp")),
    ("(3.3)–(3.6), Theorem 6", "§3", "L^1st, its Legendre maps and the explicit update",
     ("claim", "SS-T6")),
    ("(3.7)–(3.11), Theorem 7", "§3", "L^2nd, its equations and Legendre maps",
     ("claim", "SS-T7")),
    ("(3.12)–(3.13)", "§3", "Kepler problem and its Lagrangian", ("used", "kepler/kepler.hpp")),
    ("(3.14)–(3.15)", "§3", "example: VI-1 and VI-2 written out for Kepler",
     ("none", "the Kepler instances of (3.6) and (3.11): the code implements the general forms, "
              "which SS-T6 and SS-T7 check, and the printed instances are not evaluated on their "
              "own")),
    ("(3.16)–(3.18)", "§3", "relativistic system in proper time, its Lagrangian, the "
                            "K-symplectic form", ("used", "relativistic/relativistic.hpp")),
    ("(3.19)", "§3", "K-symplectic composition", ("erratum", "SS-ERR-3.19")),
    ("(3.20)", "§3", "relativistic variational integrator (its two-step t-equation)",
     ("erratum", "SS-ERR-T8")),
    ("(3.21)–(3.22), Theorem 8", "§3", "(3.20) equals the composition", ("claim", "SS-T8")),
    ("φ of §3 and Fig. 7", "§3, §5", "the sign of the Coulomb potential",
     ("erratum", "SS-ERR-PHI")),
    ("(4.1)–(4.4)", "§4", "modified equation of a two-step method: expansion and the "
                          "substitution of higher derivatives",
     ("none", "the construction Vermeeren's (8)–(10) give; checked there (V-EX2) and in its "
              "instances below")),
    ("(4.5a)–(4.5c)", "§4", "Nyström methods", ("used", "the four tableaux of SS-T10")),
    ("(4.6)", "§4", "two-step form of a Nyström method", ("erratum", "SS-ERR-4.6")),
    ("(4.7)–(4.8)", "§4", "steps of the proof of Theorem 10",
     ("none", "proof steps; the theorem's result is compared")),
    ("Theorem 10", "§4", "coefficients f^[1], f^[2] of the Nyström modified equation",
     ("claim", "SS-T10")),
    ("(4.9)–(4.10)", "§4", "modified Lagrangian: definition", ("none", "a definition")),
    ("(4.11)–(4.12)", "§4", "meshed Lagrangian with the coefficients (2^{1−2k} − 1)B_{2k}/(2k)!",
     ("claim", "V-L6", "the coefficients of Vermeeren's Lemma 6")),
    ("(4.13)", "§4", "Störmer–Verlet discrete Lagrangian", ("used", "integrators/kernels.hpp")),
    ("(4.14)–(4.15)", "§4", "Störmer–Verlet L_mod and modified equation",
     ("none", "not compared as printed here: they are Vermeeren's (23) and (22) in other "
              "symbols, which V-SV2 compares")),
    ("(4.16)–(4.17), Theorem 11", "§4", "symplectic Euler L^symE and its modified Lagrangian",
     ("claim", "SS-T11")),
    ("(4.18)", "§4", "proof of Theorem 11: h² term of the meshed Lagrangian",
     ("erratum", "SS-ERR-4.18")),
    ("(4.19)", "§4", "the h³ term of the meshed Lagrangian vanishes", ("claim", "SS-T11")),
    ("(4.20)", "§4", "example: pendulum, H_mod,1", ("claim", "SS-F1")),
    ("(4.21)", "§4", "VI-1: modified Lagrangian to h²",
     ("value", "SS-T12", "terms_differing", 0.0)),
    ("(4.22)", "§4", "VI-1: modified equation (h¹ term)", ("erratum", "SS-ERR-4.22")),
    ("(4.23)–(4.24)", "§4", "VI-2: modified Lagrangian and modified equation",
     ("erratum", "SS-ERR-4.24")),
    ("(4.25)", "§4", "VI-2: L_mod before ẍ is eliminated",
     ("none", "the intermediate form of (4.23), which is compared")),
    ("(4.26)–(4.27), Theorem 13", "§4", "one-period change of the LRL vector", ("claim", "SS-T13")),
    ("(4.28)", "§4", "step of the proof of Theorem 13", ("none", "a proof step")),
    ("(4.29)–(4.30), Theorems 14–16", "§4", "LRL changes of Störmer–Verlet, symplectic Euler "
                                            "and VI-1", ("claim", "SS-T13")),
    ("Appendix A", "App. A", "central differences: the arcsin² series, its coefficients and "
                             "radius of convergence", ("claim", "SS-AA")),
    ("Appendix A, last line", "App. A", "the convergence bound", ("erratum", "SS-ERR-A")),
]

PAPERS = [("S", "Sharma et al. 2022", S), ("V", "Vermeeren 2017", V),
          ("SS", "Shen &amp; Sun 2025", SS)]


def outcome(how, claims):
    """(css class, text) of one row's outcome, from this build's ledger."""
    kind = how[0]
    if kind == "used":
        return "used", "used as printed (" + html.escape(how[1]) + ")"
    if kind == "none":
        return "none", "not compared: " + html.escape(how[1])
    cid = how[1]
    if cid not in claims:
        raise KeyError(f"claim {cid} is not in the ledger")
    c = claims[cid]
    link = f'<a href="report.html#claim-{html.escape(cid)}">{html.escape(cid)}</a>'
    status = c["status"]
    if kind == "erratum":
        if status == "erratum":
            return "erratum", f"erratum: the print is wrong, the correction verified ({link})"
        return "disagrees", f"erratum not confirmed: {html.escape(status)} ({link})"
    if kind == "value":
        name, bound = how[2], how[3]
        v = c["values"].get(name)
        if v is None:
            raise KeyError(f"claim {cid} has no value {name}")
        if v <= bound:
            return "agrees", f"agrees: {html.escape(name)} = {v:.3g} ≤ {bound:.3g} ({link})"
        return "disagrees", f"does not agree: {html.escape(name)} = {v:.3g} > {bound:.3g} ({link})"
    via = f"; {html.escape(how[2])}" if len(how) > 2 else ""
    if status in ("reproduced", "reproduced-with-caveat"):
        return "agrees", f"agrees ({link}, {html.escape(status)}{via})"
    if status == "pending":
        return "none", f"not compared yet ({link} pending)"
    return "disagrees", f"does not agree ({link}, {html.escape(status)})"


def main():
    claims_json, gen = sys.argv[1], sys.argv[2]
    with open(claims_json, encoding="utf-8") as f:
        claims = {c["id"]: c for c in json.load(f)["claims"]}
    named = set()
    counts = {}
    for key, name, rows in PAPERS:
        out = ['<table class="vibook-formulas">\n<tr><th>Equation</th><th>Where</th>'
               '<th>What it is</th><th>Outcome</th></tr>\n']
        for label, where, what, how in rows:
            if how[0] in ("claim", "erratum", "value"):
                named.add(how[1])
            css, text = outcome(how, claims)
            counts[(key, css)] = counts.get((key, css), 0) + 1
            out.append(f'<tr class="formula-{css}"><td>{html.escape(label)}</td>'
                       f'<td>{html.escape(where)}</td><td>{html.escape(what)}</td>'
                       f'<td>{text}</td></tr>\n')
        out.append("</table>\n")
        bookfiles.write_text(os.path.join(gen, f"formulas-{key}.html"), "".join(out))
    missing = sorted(i for i, c in claims.items() if "-ERR-" in i and i not in named)
    if missing:
        sys.exit(f"formulas.py: errata of the ledger in no formula table: {', '.join(missing)}")
    kinds = [("agrees", "agrees"), ("erratum", "erratum"), ("disagrees", "does not agree"),
             ("used", "used as printed"), ("none", "not compared")]
    summary = ['<table class="vibook-summary">\n<tr><th>paper</th>']
    summary += [f"<th>{t}</th>" for _, t in kinds] + ["</tr>\n"]
    for key, name, _ in PAPERS:
        summary.append(f"<tr><td>{name}</td>")
        summary += [f'<td class="formula-{k}">{counts.get((key, k), 0)}</td>' for k, _ in kinds]
        summary.append("</tr>\n")
    summary.append("</table>\n")
    bookfiles.write_text(os.path.join(gen, "formulas-summary.html"), "".join(summary))
    print(f"formulas: {sum(len(r) for _, _, r in PAPERS)} rows, outcomes from {claims_json}")


if __name__ == "__main__":
    main()
