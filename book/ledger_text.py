#!/usr/bin/env python3
"""Numbers and verdicts in the chapters' prose, read from this build's claims ledger.

A chapter writes `[[S-F2:avi2_max_step_over_h0:.1f]]` where its text quotes a measured value,
`[[S-F2:status]]`, `[[S-F2:cause:TEXT]]` or `[[S-F2:headline:TEXT]]` where it says what held or
failed (TEXT, when given, stands where the claim has no cause or headline: it is reproduced),
and `[[S-ERR-39:corrected]]` for the LaTeX of an erratum's correction as the check found it.
This script replaces them, so that a sentence cannot contradict the table below it.

  ledger_text.py FILE              Doxygen input filter (Doxyfile FILTER_PATTERNS *.md): FILE
                                   with every placeholder replaced, to standard output; the
                                   ledger is $VIBOOK_BOOK_OUT/claims.json.
  ledger_text.py --check CLAIMS_JSON FILE...
                                   the book build's check, before Doxygen: every placeholder
                                   of every FILE names a claim and a value of the ledger
                                   (exit 1 with the list otherwise).
"""
import html
import json
import os
import re
import sys

PLACEHOLDER = re.compile(r"\[\[([A-Z]+-[A-Za-z0-9.\-]+):([^\]:]+)(?::([^\]]*))?\]\]")


def load(path):
    with open(path, encoding="utf-8") as f:
        return {c["id"]: c for c in json.load(f)["claims"]}


def value_of(claims, cid, name, spec):
    """The text for one placeholder, or raise KeyError naming what is missing."""
    if cid not in claims:
        raise KeyError(f"no claim {cid} in the ledger")
    c = claims[cid]
    if name in ("status", "cause", "headline"):
        text = c.get(name, "") or (spec or "")
        if not text:
            raise KeyError(f"claim {cid} has no {name}")
        # inline TeX of a headline (a correction's term) in Doxygen's delimiters
        return html.escape(text, quote=False).replace("\\(", "\\f$").replace("\\)", "\\f$")
    if name == "corrected":
        for x in c.get("comparisons", []):
            if x.get("corrected"):
                tex = re.sub(r"\\quad\s*\([0-9.a-z]+\)\s*$", "", x["corrected"].strip())
                return tex.rstrip(" ,.")
        raise KeyError(f"claim {cid} has no corrected display")
    if name not in c["values"]:
        raise KeyError(f"claim {cid} has no value {name}")
    v = c["values"][name]
    if v is None:
        raise KeyError(f"claim {cid}: value {name} is not a number")
    return format(v, spec or ".3g")


def substitute(text, claims):
    return PLACEHOLDER.sub(lambda m: value_of(claims, m.group(1), m.group(2), m.group(3)), text)


def main():
    if len(sys.argv) >= 3 and sys.argv[1] == "--check":
        claims = load(sys.argv[2])
        problems = []
        for path in sys.argv[3:]:
            with open(path, encoding="utf-8") as f:
                for n, line in enumerate(f, 1):
                    for m in PLACEHOLDER.finditer(line):
                        try:
                            value_of(claims, m.group(1), m.group(2), m.group(3))
                        except (KeyError, ValueError) as e:
                            problems.append(f"{path}:{n}: {m.group(0)}: {e}")
        if problems:
            sys.exit("ledger_text.py:\n  " + "\n  ".join(problems))
        return
    path = sys.argv[1]
    with open(path, encoding="utf-8") as f:
        text = f.read()
    if PLACEHOLDER.search(text):
        claims = load(os.path.join(os.environ["VIBOOK_BOOK_OUT"], "claims.json"))
        text = substitute(text, claims)
    sys.stdout.write(text)


if __name__ == "__main__":
    main()
