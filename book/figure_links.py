#!/usr/bin/env python3
"""After Doxygen (book/build_book.cmake, step 4): every figure of a chapter is numbered by its
chapter (Figure 3.2 is the second figure of chapter 3, Figure A.1 the first of appendix A),
links to its picture at full size, and its caption ends with how to get it: the CSV data it
was drawn from and the command that regenerates it.

A figure is an image Doxygen wrote as <div class="image"><object data="ID.svg">...<div
class="caption">...</div></div> (or <img src="ID.png"> for a rendered picture). Its data is
html/figures/FIG/, where FIG is ID or, for a second picture of the same figure, the longest
figure ID that ID begins with (shen-sun-fig7-worldline.png belongs to shen-sun-fig7). A folder
with a claims.json was written by `vibook figure FIG`; the verify report by `vibook verify
--report`; a picture without a folder comes from the benchmarks.
The caption's text, written in the chapter, begins with the paper's figure it reproduces
("Shen & Sun Fig. 4: ...") or says "Not in the papers"; the browser test checks that.
Usage: figure_links.py BOOK_HTML_DIR SOURCE_DIR"""
import html
import os
import re
import sys

import bookfiles

html_dir, source_dir = sys.argv[1], sys.argv[2]
figures = os.path.join(html_dir, "figures")
labels = bookfiles.chapter_labels(source_dir)
FIGURE = re.compile(
    r'<div class="image">\s*(<object type="image/svg\+xml" data="([^"/]+)\.svg"[^>]*></object>'
    r'|<img src="([^"/]+)\.png"[^>]*/?>)'
    r'\s*<div class="caption">\s*(.*?)</div></div>', re.S)


def data_folder(fig_id):
    """The folder of html/figures/ that holds this picture's data, or None."""
    folders = [d for d in os.listdir(figures) if os.path.isdir(os.path.join(figures, d))]
    owners = [d for d in folders if fig_id == d or fig_id.startswith(d + "-")]
    return max(owners, key=len) if owners else None


def how_to_get(fig_id):
    """The caption's last sentence: the data and the command that regenerates the figure."""
    folder = data_folder(fig_id)
    if folder is None:
        return ("drawn from the benchmark run: <code>./build.sh bench</code>, then "
                "<code>./build.sh book</code>")
    path = os.path.join(figures, folder)
    csvs = sorted(f for f in os.listdir(path) if f.endswith(".csv"))
    links = [f'<a href="figures/{folder}/{html.escape(f)}">{html.escape(f)}</a>' for f in csvs]
    data = ("data: " + ", ".join(links)) if links else "no CSV data"
    if os.path.exists(os.path.join(path, "claims.json")):
        command = f"<code>vibook figure {html.escape(folder)}</code>"
    else:
        command = "the <code>vibook verify --report</code> run quoted in the text"
    return f"{data}; regenerate: {command}"


changed = 0
for page in sorted(os.listdir(html_dir)):
    if not page.endswith(".html"):
        continue
    path = os.path.join(html_dir, page)
    with open(path, encoding="utf-8") as f:
        text = f.read()
    label = labels.get(page[:-len(".html")])
    count = 0

    def number(m):
        global count
        picture, fig_id, caption = m.group(1), m.group(2) or m.group(3), m.group(4)
        full = fig_id + (".svg" if m.group(2) else ".png")
        if label is None:
            return m.group(0)
        count += 1
        n = f"{label}.{count}"
        return (f'<div class="image" id="figure-{n}"><a href="{full}" '
                f'title="open the figure at full size">{picture}</a>\n<div class="caption">\n'
                f'<b>Figure {n}.</b> {caption} <span class="figure-data">(Click to enlarge; '
                f'{how_to_get(fig_id)}.)</span></div></div>')

    new = FIGURE.sub(number, text)
    if new != text:
        bookfiles.write_text(path, new)
        changed += 1
print(f"figure_links: figures numbered and linked on {changed} pages")
