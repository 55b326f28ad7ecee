#!/usr/bin/env python3
"""The field audit as the book's ledger records it (chapter "Verify your own integrator", "The
audit"): every published composition and odeint stepper the audit measures passes, and every
deliberately wrong one is flagged, which the ledger records as `reproduced`; a row that holds a
Boost header's Doxygen brief to the stepper's measured order (4 on both problems) is
`reproduced` exactly when the brief says 4, and otherwise blames the documentation.

The rows are read from the claims.json the book build wrote (./build.sh test builds the book
first), not measured a second time: the checks field-audit and field-audit-odeint run once per
build, in the book. Usage: field_audit_ledger.py BUILD/book/claims.json

--selftest: the same judgement on copies of that ledger with one row broken in each way it
can be (a row not reproduced, an order missing, a brief's status that disagrees with its
stated order, a row absent): each must fail.
"""
import copy
import json
import math
import sys

SOURCES = ("field-audit", "field-audit-odeint")


def problems(claims):
    """What is wrong with the audit's rows of a ledger: a list of lines, empty when nothing."""
    rows = [c for c in claims if c.get("source") in SOURCES]
    out = []
    for source in SOURCES:
        if not any(c["source"] == source for c in rows):
            out.append(f"no row of the check {source} in the ledger")
    for c in rows:
        cid, status, values = c["id"], c["status"], c.get("values", {})
        if c.get("paper") != "A" or not cid.startswith("A-"):
            out.append(f"{cid}: not a row of the audit (paper {c.get('paper')})")
        if cid.endswith("-BRIEF"):
            stated = values.get("expected_order")
            if not isinstance(stated, (int, float)) or stated < 1:
                out.append(f"{cid}: no order read from the Doxygen brief")
                continue
            for p in ("kepler", "henon-heiles"):
                o = values.get(f"order_{p}")
                if not isinstance(o, (int, float)) or abs(o - 4) >= 0.2:
                    out.append(f"{cid}: measured order on {p} is {o}, not 4")
            want = "reproduced" if abs(stated - 4) < 0.2 else "not-reproduced"
            if status != want:
                out.append(f"{cid}: status {status}, but the brief states {stated}: want {want}")
            if status == "not-reproduced" and not c.get("headline", "").startswith(
                    "the order stated in the Doxygen brief of odeint's "):
                out.append(f"{cid}: the headline does not blame the documentation")
            continue
        if status != "reproduced":
            out.append(f"{cid}: {status}: {c.get('headline', c.get('note', ''))[:300]}")
        for p in ("kepler", "henon-heiles"):
            o = values.get(f"order_{p}")
            if not isinstance(o, (int, float)) or not math.isfinite(o):
                out.append(f"{cid}: no measured order on {p}")
    return out


def main():
    args = [a for a in sys.argv[1:] if a != "--selftest"]
    if len(args) != 1:
        sys.exit("usage: field_audit_ledger.py [--selftest] BUILD/book/claims.json")
    try:
        claims = json.load(open(args[0]))["claims"]
    except OSError as e:
        sys.exit(f"no ledger {args[0]} ({e.strerror}): build the book first (./build.sh test does)")
    found = problems(claims)
    rows = [c for c in claims if c.get("source") in SOURCES]
    for line in found:
        print("FAIL:", line)
    print(f"field audit in the ledger: {len(rows)} rows, {len(found)} problems")
    if "--selftest" not in sys.argv[1:]:
        sys.exit(1 if found else 0)
    # Each break must be found.
    def broken(edit):
        c = copy.deepcopy(claims)
        edit([r for r in c if r.get("source") in SOURCES])
        return c
    plain = next(r["id"] for r in rows if not r["id"].endswith("-BRIEF"))
    brief = next(r["id"] for r in rows if r["id"].endswith("-BRIEF"))

    def set_status(rs, cid, s):
        next(r for r in rs if r["id"] == cid)["status"] = s

    def drop_order(rs):
        next(r for r in rs if r["id"] == plain)["values"].pop("order_kepler", None)

    def flip_brief(rs):
        r = next(r for r in rs if r["id"] == brief)
        r["status"] = "reproduced" if r["status"] == "not-reproduced" else "not-reproduced"

    cases = {
        "a row not reproduced": lambda rs: set_status(rs, plain, "not-reproduced"),
        "an order missing": drop_order,
        "a brief's status against its order": flip_brief,
        "the odeint rows absent": lambda rs: [r.update(source="other") for r in rs
                                              if r["source"] == "field-audit-odeint"],
    }
    missed = [name for name, edit in cases.items() if not problems(broken(edit))]
    for name in missed:
        print("FAIL: selftest: not caught:", name)
    print(f"field audit selftest: {len(cases) - len(missed)} of {len(cases)} breaks caught")
    sys.exit(1 if found or missed else 0)


if __name__ == "__main__":
    main()
