#!/usr/bin/env python3
"""After Doxygen (book/build_book.cmake, step 4): a notice at the top of every book page that
shows something this build did not measure, so that a partial build never reads as final.

A build without the long studies and the benchmarks (`./build.sh test`, or `./build.sh book`
without them) leaves three kinds of placeholders in the pages:
  - a figure whose image is the build's "not run in this build" notice (an SVG the book build
    writes in place of a long study's or the benchmarks' plot);
  - a table that says "Not measured in this build" (the benchmark tables);
  - claim rows with the status pending (a long study's claims).
Each page that holds one gets, before its text, a box naming what is not measured and the
command that measures it. Pages without placeholders are left untouched. With every study run,
no page changes.
Usage: partial_notice.py BOOK_HTML_DIR"""
import glob
import html
import os
import re
import sys

import bookfiles

html_dir = sys.argv[1]

NOT_RUN = "not run in this build"


def placeholders(text):
    """What on this page is not measured: [(kind, name)]."""
    found = []
    for ref in re.findall(r'(?:data|src)="([\w.-]+\.svg)"', text):
        path = os.path.join(html_dir, ref)
        if os.path.exists(path):
            with open(path, encoding="utf-8", errors="replace") as f:
                if NOT_RUN in f.read():
                    found.append(("figure", ref[:-4]))
    n_tables = text.count("Not measured in this build")
    if n_tables:
        found.append(("table", f"{n_tables} benchmark table{'s' if n_tables > 1 else ''}"))
    pending = sorted(set(re.findall(
        r'<tr class="status-pending"[^>]*><td class="claim-id"><a href="(?:report\.html)?#claim-'
        r'([\w.-]+)"',
        text)))
    if pending:
        found.append(("claims", ", ".join(pending)))
    return found


changed = 0
for path in sorted(glob.glob(os.path.join(html_dir, "*.html"))):
    page = os.path.basename(path)
    if not page.startswith(("chapter-", "appendix-")) and page not in (
            "benchmarks.html", "report.html", "index.html"):
        continue
    with open(path, encoding="utf-8") as f:
        text = f.read()
    if 'class="vibook-partial"' in text:
        continue
    found = placeholders(text)
    if not found:
        continue
    parts = []
    figures = [n for k, n in found if k == "figure"]
    if figures:
        parts.append(f"the figure{'s' if len(figures) > 1 else ''} "
                     + ", ".join(f"<code>{html.escape(n)}</code>" for n in figures)
                     + " (a grey box stands in for the plot)")
    parts += [html.escape(n) for k, n in found if k == "table"]
    claims = [n for k, n in found if k == "claims"]
    if claims:
        parts.append("the claims " + html.escape(claims[0]) + " (status pending)")
    box = ('<div class="vibook-partial"><b>Partial build.</b> This page shows what this build did '
           "not measure: " + "; ".join(parts) + ". The prose describes the full build. "
           "<code>./build.sh book</code> runs the long studies and the benchmarks and fills "
           "them in.</div>\n")
    at = text.find('<div class="textblock">')
    if at < 0:
        sys.exit(f"partial_notice: no text block in {page}")
    at += len('<div class="textblock">')
    bookfiles.write_text(path, text[:at] + box + text[at:])
    changed += 1
print(f"partial_notice: {changed} pages carry a partial-build notice")
