#!/usr/bin/env python3
"""The errata sheets: one per paper, written during the book build from this build's ledger.

Usage: errata.py CLAIMS_JSON DISPLAYS_JSON PAPERS_DIR GEN_DIR MD_DIR

For an author, not for us: each misprint is keyed to what the paper itself shows (equation
number, section, the sentence that introduces the display), never to a position in our
transcription. One entry per erratum of the ledger (PAPER-ERR-*), in the order of the paper:

  where        the display's place in the paper's terms and the sentence before it;
  printed      the display as the paper prints it (the LaTeX the check quoted verbatim);
  corrected    the corrected display and the edit in words, or, where no small edit corrects
               it, the formula vibook derives and how that formula was verified independently;
               an erratum measured numerically (not read as a formula) gives the measurement;
  evidence     links to the erratum's row in the reproduction report and the display's row in
               the formula tables, and the check that measured it;
  consequence  the claims of the paper that rest on the display, with their status: whether
               the paper's result still holds once the display is corrected.

Writes GEN_DIR/errata-S.html, errata-V.html, errata-SS.html (included by book/errata-*.md) and
the same sheets as Markdown, MD_DIR/errata-S.md, ..., which the book build copies beside the
HTML for download. Nothing here is typed by hand: an erratum the
ledger does not have is not on a sheet, and one it has is on exactly one.
"""
import html
import json
import os
import re
import sys

import bookfiles
from formulas import math

PAPERS = [("S", "sharma2022-epavi.md",
           "H. Sharma, J. Borggaard, M. Patil and C. Woolsey, Performance assessment of "
           "energy-preserving, adaptive time-step variational integrators, arXiv:2108.05420 "
           "(version of 12 January 2022)"),
          ("V", "vermeeren2017-modified-equations.md",
           "M. Vermeeren, Modified equations for variational integrators, Numerische "
           "Mathematik (2017), arXiv:1505.05411"),
          ("SS", "shen-sun2025-splitting-vi.md",
           "Y. Shen and Y. Sun, Numerical analysis for a class of variational integrators, "
           "preprint of 10 June 2025, doi:10.20944/preprints202506.0678.v1 (equation numbers "
           "of the preprint)")]

STATUS_WORDS = {
    "erratum": "holds once the misprinted displays are corrected",
    "reproduced": "holds",
    "reproduced-with-caveat": "holds, with the caveat in its note",
    "not-reproduced": "does not hold as stated",
    "pending": "not measured in this build",
}


def sentence_before(lines, line_no, quote):
    """The sentence of the paper that introduces the display at LINE_NO (1-based): for a
    display of its own, the last sentence of the paragraph before it; for an inline formula,
    the sentence that contains it. Math stays in the paper's $...$."""
    i = line_no - 1
    if 0 <= i < len(lines) and quote and quote[:40] in lines[i] and not lines[i].startswith("$$"):
        text = lines[i]
        at = text.find(quote[:40])
        start = max(text.rfind(". ", 0, at), text.rfind(": ", 0, at))
        end = text.find(". ", at + len(quote))
        return text[start + 2 if start >= 0 else 0:end + 1 if end >= 0 else len(text)].strip()
    j = i - 1
    while j >= 0 and (not lines[j].strip() or lines[j].startswith("$$")):
        j -= 1
    if j < 0:
        return ""
    text = lines[j].strip()
    # the last sentence: after the last ". " that is not inside $...$
    cut = 0
    inside = False
    for k, ch in enumerate(text[:-1]):
        if ch == "$":
            inside = not inside
        elif ch == "." and text[k + 1] == " " and not inside and k < len(text) - 2:
            cut = k + 2
    return text[cut:]


def prose_html(text):
    """Paper prose with its $...$ math as MathJax inline math."""
    out = []
    for k, part in enumerate(re.split(r"\$([^$]+)\$", text)):
        out.append(f"\\({html.escape(part.strip())}\\)" if k % 2 else html.escape(part))
    return "".join(out)


def claim_link(cid):
    return f'<a href="report.html#claim-{html.escape(cid)}">{html.escape(cid)}</a>'


def main():
    claims_json, displays_json, papers_dir, gen, md_dir = sys.argv[1:6]
    with open(claims_json, encoding="utf-8") as f:
        claims = {c["id"]: c for c in json.load(f)["claims"]}
    with open(displays_json, encoding="utf-8") as f:
        displays = {(d["paper"], d["id"]): d for d in json.load(f)}
    os.makedirs(md_dir, exist_ok=True)
    used_by = {}
    for cid, c in claims.items():
        for e in c.get("errata", []):
            used_by.setdefault(e, []).append(cid)
    problems = []
    summary = []
    for key, filename, citation in PAPERS:
        with open(os.path.join(papers_dir, filename), encoding="utf-8") as f:
            lines = f.read().split("\n")
        entries = []
        for cid, c in claims.items():
            if c.get("paper") != key or "-ERR-" not in cid:
                continue
            slips = [x for x in c.get("comparisons", [])
                     if x["outcome"] != "agrees" and x.get("role") != "cross-check"]
            first_line = min((displays[(key, x["display"])]["line"] for x in slips
                              if (key, x["display"]) in displays), default=None)
            if first_line is None:
                m = re.search(r"\(([\w.]+)\)", c.get("where", ""))
                d = displays.get((key, f"({m.group(1)})")) if m else None
                first_line = d["line"] if d else len(lines)
            entries.append((first_line, cid, c, slips))
        entries.sort(key=lambda e: (e[0], e[1]))
        out_html, out_md = [], []
        n_slips = sum(max(1, len(s)) for _, _, _, s in entries)
        out_html.append(f"<p class=\"errata-cite\">{html.escape(citation)}.</p>\n"
                        f"<p>{len(entries)} errata, {n_slips} printed displays or statements "
                        f"affected. Plain text of this sheet: "
                        f"<a href=\"errata-{key}.md\">errata-{key}.md</a>.</p>\n")
        out_md.append(f"# Errata: {citation}\n\nWritten by vibook's book build from its "
                      f"ledger (claims.json); {len(entries)} errata.\n")
        for _, cid, c, slips in entries:
            out_html.append(f'<div class="erratum" id="erratum-{html.escape(cid)}">\n'
                            f"<h3>{html.escape(cid)}: {html.escape(c['title'])}</h3>\n<dl>\n")
            out_md.append(f"\n## {cid}: {c['title']}\n")
            out_html.append(f"<dt>Where</dt><dd>{html.escape(c.get('where', ''))}</dd>\n")
            out_md.append(f"\n- Where: {c.get('where', '')}\n")
            if not slips:
                out_html.append("<dt>Finding</dt><dd>" + html.escape(c["note"]) + "</dd>\n")
                out_md.append(f"- Finding (measured, not read as a formula): {c['note']}\n")
            for n, x in enumerate(slips, 1):
                d = displays.get((key, x["display"]))
                before = sentence_before(lines, d["line"], x["quote"]) if d else ""
                head = f" (slip {n} of {len(slips)})" if len(slips) > 1 else ""
                label = x["label"] + (f", {x['part']}" if x["part"] else "")
                out_html.append(f"<dt>Display{head}</dt><dd>{html.escape(label)}")
                out_md.append(f"- Display{head}: {label}\n")
                if before:
                    out_html.append(f"<br><span class=\"errata-context\">after the sentence "
                                    f"“{prose_html(before)}”</span>")
                    out_md.append(f"  - after the sentence: “{before}”\n")
                out_html.append("</dd>\n")
                out_html.append(f"<dt>Printed</dt><dd>{math(x['quote'])}</dd>\n")
                out_md.append(f"  - printed: $${x['quote']}$$\n")
                if x["corrected"]:
                    out_html.append(f"<dt>Corrected</dt><dd>{math(x['corrected'])}"
                                    f"<p>The edit: {edit_html(x['edit'])}.</p></dd>\n")
                    out_md.append(f"  - corrected: $${x['corrected']}$$\n"
                                  f"  - the edit: {x['edit']}\n")
                else:
                    how = (f"verified independently: {x['verified']}" if x["verified"]
                           else f"no correction was found ({x['search']})")
                    out_html.append(f"<dt>Corrected</dt><dd>No small edit corrects it. The "
                                    f"formula vibook derives, {html.escape(how)}:"
                                    f"{math(x['ours'])}</dd>\n")
                    out_md.append(f"  - no small edit corrects it; the formula vibook "
                                  f"derives ({how}): $${x['ours']}$$\n")
                if x["detail"]:
                    out_html.append(f"<dt>Difference</dt><dd>{edit_html(x['detail'])}</dd>\n")
                    out_md.append(f"  - difference: {x['detail']}\n")
                out_html.append(f"<dt>Compared with</dt><dd>{html.escape(x['against'])}, "
                                f"{html.escape(x['through'])} (check "
                                f"<code>{html.escape(x['check'])}</code>)</dd>\n")
                out_md.append(f"  - compared with: {x['against']}, {x['through']} "
                              f"(check {x['check']})\n")
            links = [claim_link(cid) + " in the reproduction report"]
            for x in slips:
                anchor = f"formulas.html#formula-{key}-{html.escape(x['display'])}"
                if (key, x["display"]) in displays:
                    links.append(f'<a href="{anchor}">its row</a> in the formula tables')
                    break
            out_html.append(f"<dt>Evidence</dt><dd>{'; '.join(links)}; measured by "
                            f"<code>{html.escape(c['source'])}</code></dd>\n")
            out_md.append(f"- Evidence: claim {cid} of claims.json, measured by "
                          f"{c['source']}\n")
            users = used_by.get(cid, [])
            if not users:
                problems.append(f"{cid}: no claim of the ledger lists it among its errata")
            conseq = []
            for u in users:
                s = claims[u]["status"]
                conseq.append(f"{claim_link(u)} ({html.escape(claims[u]['title'])}): "
                              f"{html.escape(s)}, {STATUS_WORDS.get(s, s)}")
                out_md.append(f"- Rests on it: {u} ({claims[u]['title']}): {s}, "
                              f"{STATUS_WORDS.get(s, s)}\n")
            out_html.append("<dt>The paper's result</dt><dd>" + "<br>".join(conseq) +
                            "</dd>\n</dl>\n</div>\n")
        summary.append((key, len(entries), n_slips))
        bookfiles.write_text(os.path.join(gen, f"errata-{key}.html"), "".join(out_html))
        bookfiles.write_text(os.path.join(md_dir, f"errata-{key}.md"), "".join(out_md))
    listed = sum(n for _, n, _ in summary)
    total = sum(1 for cid in claims if "-ERR-" in cid)
    if listed != total:
        problems.append(f"{total} errata in the ledger, {listed} on the sheets")
    if problems:
        sys.exit("errata.py:\n  " + "\n  ".join(problems))
    print("errata: " + ", ".join(f"{k} {n} ({s} displays)" for k, n, s in summary))


def edit_html(text):
    """An edit in words: prose with \\( ... \\) math kept for MathJax, the rest escaped."""
    return html.escape(text)


if __name__ == "__main__":
    main()
