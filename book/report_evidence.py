#!/usr/bin/env python3
"""After Doxygen and figure_links.py (book/build_book.cmake, step 4): fill the reproduction
report's evidence cells.

Each claim row of report.html ends in <td class="claim-evidence" data-source="CHECK[, CHECK]">,
written empty by claims::Ledger::to_html. For every check named there this adds links to
  - the chapter that shows the check (the book page whose source includes CHECK.html or the
    image CHECK.svg), at the
    check's numbered figure when it has one (figure_links.py numbered them),
  - the check's CSV data (html/figures/CHECK/*.csv, written by `vibook figures`),
  - the check's source: the line of src/vibook/**/*.cpp that defines it, in Doxygen's source
    listing.
A check that no chapter shows, or whose source is not found, is an error: the report would
otherwise promise evidence it cannot link to.
Usage: report_evidence.py BOOK_HTML_DIR SOURCE_DIR"""
import glob
import html
import os
import re
import sys

import bookfiles

html_dir, source_dir = sys.argv[1], sys.argv[2]


def chapters():
    """CHECK -> (page id, chapter title) from the book's Markdown sources."""
    out = {}
    for page, title, text in bookfiles.pages(source_dir):
        for check in re.findall(r"\\htmlinclude\s+([\w-]+)\.html|\\image\s+html\s+([\w-]+)\.svg",
                                text):
            out.setdefault(check[0] or check[1], (page, title))
    return out


def definitions():
    """CHECK -> (path under src/, line) of the `return {"CHECK",` that defines it."""
    out = {}
    for path in sorted(glob.glob(os.path.join(source_dir, "src", "vibook", "**", "*.cpp"),
                              recursive=True)):
        if path.endswith("_test.cpp"):
            continue
        with open(path, encoding="utf-8") as f:
            for number, line in enumerate(f, 1):
                m = re.search(r'return\s*\{\s*"([\w-]+)",', line)
                if m:
                    out.setdefault(m.group(1), (os.path.relpath(path, os.path.join(source_dir, "src")),
                                                number))
    return out


def source_pages():
    """Doxygen's source listings: path under src/ (as the page's title names it) -> page."""
    out = {}
    for page in glob.glob(os.path.join(html_dir, "*_source.html")):
        with open(page, encoding="utf-8") as f:
            m = re.search(r"<title>vibook: (.*?) Source File</title>", f.read(4000))
        if m:
            out[m.group(1)] = os.path.basename(page)
    return out


chapter_of = chapters()
defined_at = definitions()
pages = source_pages()
report = os.path.join(html_dir, "report.html")
with open(report, encoding="utf-8") as f:
    text = f.read()
figure_number = {}
problems = []


def figure_anchor(page, check):
    key = (page, check)
    if key not in figure_number:
        figure_number[key] = None
        path = os.path.join(html_dir, page + ".html")
        if os.path.exists(path):
            with open(path, encoding="utf-8") as f:
                m = re.search(r'<div class="image" id="figure-([A-Z0-9]+\.\d+)"><a href="' +
                              re.escape(check) + r'\.svg"', f.read())
            if m:
                figure_number[key] = m.group(1)
    return figure_number[key]


def evidence(m):
    links = []
    for check in [c.strip() for c in html.unescape(m.group(1)).split(",") if c.strip()]:
        parts = []
        if check not in chapter_of:
            problems.append(f"check {check}: no chapter includes {check}.html")
        else:
            page, title = chapter_of[check]
            n = figure_anchor(page, check)
            where = f"#figure-{n}" if n else ""
            label = f"Figure {n}" if n else "results"
            parts.append(f'<a href="{page}.html{where}" title="{html.escape(title)}">'
                         f'{html.escape(title)}, {label}</a>')
        folder = os.path.join(html_dir, "figures", check)
        csvs = sorted(f for f in os.listdir(folder) if f.endswith(".csv")) if os.path.isdir(folder) else []
        if csvs:
            parts.append("data: " + " ".join(
                f'<a href="figures/{check}/{html.escape(c)}">{html.escape(c[:-4])}</a>' for c in csvs))
        if check not in defined_at:
            problems.append(f"check {check}: no definition `return {{\"{check}\",` under src/vibook")
        else:
            rel, line = defined_at[check]
            link = f"{pages[rel]}#l{line:05d}" if rel in pages else None
            if link is None:
                problems.append(f"check {check}: Doxygen wrote no source page for {rel}")
            else:
                parts.append(f'<a href="{link}">check: {html.escape(rel)}:{line}</a>')
        links.append(f'<span class="evidence"><code>{html.escape(check)}</code><br/>' + "<br/>".join(parts) +
                     "</span>")
    return m.group(0)[:-len("</td>")] + "<br/>".join(links) + "</td>"


new, count = re.subn(r'<td class="claim-evidence" data-source="([^"]*)"></td>', evidence, text)
if problems:
    for p in problems:
        print("report_evidence:", p, file=sys.stderr)
    sys.exit(1)
bookfiles.write_text(report, new)
print(f"report_evidence: evidence linked for {count} claims")
