#!/usr/bin/env python3
"""After Doxygen (book/build_book.cmake, step 4): every figure of a chapter is numbered, links
to its picture at full size, and its caption lists the CSV data it was drawn from.

A figure is an image Doxygen wrote as <div class="image"><object data="ID.svg">...<div
class="caption">...</div></div> for which the book build left data in html/figures/ID/
(`vibook figures --out`). The numbering restarts on every page.
Usage: figure_links.py BOOK_HTML_DIR"""
import html
import os
import re
import sys

import bookfiles

html_dir = sys.argv[1]
figures = os.path.join(html_dir, "figures")
FIGURE = re.compile(
    r'<div class="image">\s*(<object type="image/svg\+xml" data="([^"/]+)\.svg"[^>]*></object>)'
    r'\s*<div class="caption">\s*(.*?)</div></div>', re.S)


def data_links(fig_id):
    folder = os.path.join(figures, fig_id)
    csvs = sorted(f for f in os.listdir(folder) if f.endswith(".csv"))
    links = [f'<a href="figures/{fig_id}/{html.escape(f)}">{html.escape(f)}</a>' for f in csvs]
    return ("data: " + ", ".join(links)) if links else "no CSV data"


changed = 0
for page in sorted(os.listdir(html_dir)):
    if not page.endswith(".html"):
        continue
    path = os.path.join(html_dir, page)
    with open(path, encoding="utf-8") as f:
        text = f.read()
    count = 0

    def number(m):
        global count
        obj, fig_id, caption = m.group(1), m.group(2), m.group(3)
        if not os.path.isdir(os.path.join(figures, fig_id)):
            return m.group(0)
        count += 1
        return (f'<div class="image" id="figure-{count}"><a href="{fig_id}.svg" '
                f'title="open the figure at full size">{obj}</a>\n<div class="caption">\n'
                f'<b>Figure {count}.</b> {caption} <span class="figure-data">(Click to enlarge; '
                f'{data_links(fig_id)}.)</span></div></div>')

    new = FIGURE.sub(number, text)
    if new != text:
        bookfiles.write_text(path, new)
        changed += 1
print(f"figure_links: figures numbered and linked on {changed} pages")
