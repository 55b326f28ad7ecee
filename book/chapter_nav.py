#!/usr/bin/env python3
"""After Doxygen (book/build_book.cmake, step 4): previous/next links on every page of the
book, in the order of the table of contents on the first page (book/index.md, its
`\\subpage` list), so that the book reads front to back as well as through the side tree.

The bar goes at the top and the bottom of each page's contents:
    ← previous: TITLE    contents    next: TITLE →
Usage: chapter_nav.py BOOK_HTML_DIR SOURCE_DIR"""
import glob
import html
import os
import re
import sys

import bookfiles

html_dir, source_dir = sys.argv[1], sys.argv[2]


with open(os.path.join(source_dir, "book", "index.md"), encoding="utf-8") as f:
    order = re.findall(r"\\subpage\s+([\w-]+)", f.read())
title = {page: t for page, t, _ in bookfiles.pages(source_dir)}
title["mainpage"] = "vibook"
pages = ["mainpage"] + order
files = {p: ("index.html" if p == "mainpage" else p + ".html") for p in pages}


def link(page, rel, text):
    return (f'<a class="nav-{rel}" rel="{rel}" href="{files[page]}">{text}'
            f'{html.escape(title.get(page, page))}</a>')


# Doxygen also writes an empty file page beside each page of the book (NAME_8md.html, reached
# only from its search index). Each becomes a redirect to the page its Markdown file holds, so
# that no stray page is left and a search for the file name still lands on the chapter.
redirected = 0
for md in sorted(glob.glob(os.path.join(source_dir, "book", "*.md"))):
    name = os.path.basename(md)[:-3]
    stray = os.path.join(html_dir, name.replace("_", "__") + "_8md.html")
    if not os.path.exists(stray):
        continue
    with open(md, encoding="utf-8") as f:
        head = re.match(r"#\s+(.*?)\s*\{#([\w-]+)\}", f.read())
    target = ("index.html" if not head or head.group(2) == "mainpage" else head.group(2) + ".html")
    bookfiles.write_text(stray, '<!DOCTYPE html>\n<html><head><meta charset="utf-8">'
                                f'<meta http-equiv="refresh" content="0; url={target}">'
                                f'<title>{html.escape(name)}.md</title></head><body>'
                                f'<p><a href="{target}">{html.escape(name)}.md</a></p>'
                                '</body></html>\n')
    redirected += 1

changed = 0
for i, page in enumerate(pages):
    path = os.path.join(html_dir, files[page])
    if not os.path.exists(path):
        sys.exit(f"chapter_nav: {path} not found (is {page} in the book's \\subpage list?)")
    with open(path, encoding="utf-8") as f:
        text = f.read()
    if 'class="vibook-pagenav"' in text:
        continue  # already done (the book build reruns Doxygen from scratch, so never)
    prev_link = link(pages[i - 1], "prev", "← previous: ") if i > 0 else "<span></span>"
    next_link = link(pages[i + 1], "next", "next: ") if i + 1 < len(pages) else "<span></span>"
    if next_link.endswith("</a>"):
        next_link = next_link[:-4] + " →</a>"
    contents = '<a class="nav-contents" href="index.html#chapters">contents</a>' \
        if page != "mainpage" else "<span></span>"
    bar = f'<div class="vibook-pagenav">{prev_link}{contents}{next_link}</div>'
    start = text.find('<div class="contents">')
    end = text.rfind("</div><!-- contents -->")
    if start < 0 or end < 0:
        sys.exit(f"chapter_nav: no contents block in {files[page]}")
    start += len('<div class="contents">')
    text = text[:start] + "\n" + bar + text[start:end] + bar + "\n" + text[end:]
    bookfiles.write_text(path, text)
    changed += 1
print(f"chapter_nav: previous/next links on {changed} pages, {redirected} file pages "
      "redirected to their pages")
