#!/usr/bin/env python3
"""After Doxygen, figure_links.py and chapter_nav.py (book/build_book.cmake, step 4): where
each paper's figures, theorems and numbered equations are in the book, read from the built
pages, the papers' own text and this build's ledger; nothing is listed by hand.

1. The first page's map (index.html, the placeholder <div id="paper-map">): per paper, every
   figure and every theorem-like statement (theorem, lemma, proposition, corollary,
   definition, example) the paper's text numbers, each with the book's figure or section and
   the claims that measure it, with their status; "not checked" where no claim does. Then
   every numbered equation, each linked to its row of the formula tables.
2. Doxygen's offline search (html/search/, the "All" index): entries for every claim ID
   (its report row and the chapter section that shows it), every numbered equation ("(4.21)":
   its formula-table row per paper), every paper figure ("Shen & Sun Fig. 6", "Fig. 6") and
   every figure ID ("shen-sun-fig6"), so that the search box finds them as it finds classes.
   Doxygen's search indexes titles and symbols only; the entries are added to its files in
   its own format (Doxygen 1.9.4, Debian 12: search/searchdata.js names the first characters
   with a results page each, all_N.js holds that character's entries).
Usage: paper_map.py BOOK_HTML_DIR SOURCE_DIR CLAIMS_JSON DISPLAYS_JSON"""
import ast
import html
import json
import os
import re
import sys

import bookfiles

html_dir, source_dir, claims_json, displays_json = sys.argv[1:5]
PAPERS = [("S", "Sharma et al. 2022", "Sharma et al.", "sharma2022-epavi.md"),
          ("V", "Vermeeren 2017", "Vermeeren", "vermeeren2017-modified-equations.md"),
          ("SS", "Shen & Sun 2025", "Shen & Sun", "shen-sun2025-splitting-vi.md")]
KINDS = {"Thm": "Theorem", "Thms": "Theorem", "Theorem": "Theorem", "Theorems": "Theorem",
         "Lemma": "Lemma", "Prop": "Proposition", "Props": "Proposition",
         "Proposition": "Proposition", "Propositions": "Proposition", "Def": "Definition",
         "Definition": "Definition", "Example": "Example", "Corollary": "Corollary",
         "Fig": "Figure", "Figs": "Figure", "Figure": "Figure", "Figures": "Figure"}

with open(claims_json, encoding="utf-8") as f:
    claims = {c["id"]: c for c in json.load(f)["claims"]}
with open(displays_json, encoding="utf-8") as f:
    displays = json.load(f)
labels = bookfiles.chapter_labels(source_dir)
titles = {page: title for page, title, _ in bookfiles.pages(source_dir)}


def read(page):
    with open(os.path.join(html_dir, page), encoding="utf-8") as f:
        return f.read()


def text_of(fragment):
    return html.unescape(re.sub(r"<[^>]+>", "", fragment)).strip()


# --- Where the built chapters show each claim and each figure --------------------------------
HEADING = re.compile(r'<h[1-4]><a class="anchor" id="([^"]+)"></a>\s*(.*?)</h[1-4]>', re.S)
claim_place, figure_place = {}, {}
for page in sorted(p for p in os.listdir(html_dir)
                   if p.endswith(".html") and p[:-5] in labels):
    text = read(page)
    heads = [(m.start(), m.group(1), text_of(m.group(2))) for m in HEADING.finditer(text)]

    def section(pos):
        before = [h for h in heads if h[0] < pos]
        return (before[-1][1], before[-1][2]) if before else ("", titles.get(page[:-5], page))

    for m in re.finditer(r'class="claim-id"><a href="report\.html#claim-([\w.-]+)"', text):
        anchor, title = section(m.start())
        claim_place.setdefault(m.group(1), (page, anchor, title))
    for m in re.finditer(r'<div class="image" id="figure-([A-Z0-9]+\.\d+)">.*?<b>Figure [^<]*</b>'
                         r'\s*(.*?)<span class="figure-data">', text, re.S):
        caption = text_of(m.group(2))
        for key, _, short, _ in PAPERS:
            c = re.match(re.escape(short) + r" Figs?\. (\d+)(?:–(\d+))?", caption)
            if c:
                for n in range(int(c.group(1)), int(c.group(2) or c.group(1)) + 1):
                    figure_place.setdefault((key, n), []).append((page, m.group(1)))


# --- What each paper numbers, and which claims measure it ------------------------------------
def paper_items(filename):
    """[(kind, number)] of the figures and theorem-like statements the paper's text numbers."""
    with open(os.path.join(source_dir, "papers", filename), encoding="utf-8") as f:
        text = f.read()
    found = set()
    # a statement or caption begins a line, or is set in bold ("**Definition 7.**")
    for m in re.finditer(r"(?:^|\*\*)(Figure|Theorem|Lemma|Proposition|Corollary|Definition|"
                         r"Example) (\d+)\b", text, re.M):
        found.add((m.group(1), int(m.group(2))))
    order = ["Figure", "Theorem", "Lemma", "Proposition", "Corollary", "Definition", "Example"]
    return sorted(found, key=lambda x: (order.index(x[0]), x[1]))


def cited(where):
    """{(kind, number)} that a claim's `where` names: "Thms 2–4", "Props 2, 4", "Fig. 1"."""
    out = set()
    for m in re.finditer(r"\b(Thms?|Theorems?|Lemma|Props?|Propositions?|Def|Definition|Example|"
                         r"Corollary|Figs?|Figures?)\.?\s+(\d+(?:\s*(?:–|-|,|and)\s*\d+)*)", where):
        kind = KINDS[m.group(1)]
        numbers = m.group(2)
        for a, b in re.findall(r"(\d+)\s*(?:–|-)\s*(\d+)", numbers):
            out.update((kind, n) for n in range(int(a), int(b) + 1))
        out.update((kind, int(n)) for n in re.findall(r"\d+", numbers))
    return out


def claim_link(cid):
    c = claims[cid]
    status = html.escape(c["status"])
    return (f'<a href="report.html#claim-{html.escape(cid)}">{html.escape(cid)}</a> '
            f'<span class="map-status status-{status}">{status}</span>')


def place_link(page, anchor, title):
    label = labels.get(page[:-5], "")
    kind = "Appendix" if page.startswith("appendix-") else "Chapter"
    return (f'<a href="{page}#{anchor}">{kind} {html.escape(label)}: {html.escape(title)}</a>'
            if label else f'<a href="{page}#{anchor}">{html.escape(title)}</a>')


def formula_row(key, d):
    return f'formulas.html#formula-{key}-{d["id"]}'


# --- 1. The map on the first page -------------------------------------------------------------
out = ['<p class="vibook-map-intro">Generated from the papers\' text, the built chapters and '
       'this build\'s ledger. A statement no claim measures says <em>not checked</em>.</p>']
for key, name, short, filename in PAPERS:
    by_item = {}
    for cid, c in claims.items():
        if c["paper"] != key:
            continue
        for item in cited(c.get("where", "") + "; " + c.get("title", "")):
            by_item.setdefault(item, []).append(cid)
    rows = []
    for kind, n in paper_items(filename):
        ids = sorted(set(by_item.get((kind, n), [])), key=list(claims).index)
        places = []
        if kind == "Figure":
            for page, fig in figure_place.get((key, n), []):
                places.append(f'<a href="{page}#figure-{fig}">Figure {fig}</a>')
        for cid in ids:
            if cid in claim_place and kind != "Figure":
                places.append(place_link(*claim_place[cid]))
        places = list(dict.fromkeys(places))
        where = ", ".join(places) if places else ""
        measured = "; ".join(claim_link(cid) for cid in ids) if ids else "<em>not checked</em>"
        rows.append(f"<tr><td>{kind} {n}</td><td>{where}</td><td>{measured}</td></tr>")
    numbered = [d for d in displays if d["paper"] == key and d.get("number")]
    eqs = ", ".join(f'<a href="{formula_row(key, d)}">{html.escape(d["label"])}</a>'
                    for d in numbered)
    out.append(f'<h3 class="vibook-map-paper">{html.escape(name)}</h3>\n'
               '<table class="vibook-map"><tr><th>in the paper</th><th>in the book</th>'
               '<th>claims (status measured in this build)</th></tr>\n' + "\n".join(rows) +
               f'\n<tr><td>numbered equations ({len(numbered)})</td><td colspan="2">{eqs}</td>'
               '</tr>\n</table>')
index = os.path.join(html_dir, "index.html")
text = read("index.html")
placeholder = '<div id="paper-map"></div>'
if placeholder not in text:
    sys.exit("paper_map: index.html has no <div id=\"paper-map\"></div> (book/index.md)")
bookfiles.write_text(index, text.replace(placeholder, '<div id="paper-map">' + "\n".join(out) +
                                         "</div>"))

# --- 2. The search entries ----------------------------------------------------------------------
entries = {}  # term -> [(url, scope)]


def add(term, url, scope):
    entries.setdefault(term, [])
    if (url, scope) not in entries[term]:
        entries[term].append((url, scope))


for cid, c in claims.items():
    add(cid, f"report.html#claim-{cid}", f"claim: {c['title']} (reproduction report)")
    if cid in claim_place:
        page, anchor, title = claim_place[cid]
        add(cid, f"{page}#{anchor}", f"claim {cid} in the book: {title}")
for key, name, short, _ in PAPERS:
    for d in displays:
        if d["paper"] == key and d.get("number"):
            add(d["label"], formula_row(key, d), f"{name}, equation {d['label']}: formula table")
    for (k, n), places in sorted(figure_place.items()):
        if k != key:
            continue
        for page, fig in places:
            url = f"{page}#figure-{fig}"
            add(f"{short} Fig. {n}", url, f"Figure {fig} of the book")
            add(f"Fig. {n}", url, f"{name} Fig. {n}: Figure {fig} of the book")
for page in sorted(p for p in os.listdir(html_dir) if p.endswith(".html") and p[:-5] in labels):
    for m in re.finditer(r'<div class="image" id="figure-([A-Z0-9]+\.\d+)"><a href="([\w-]+)\.'
                         r'(?:svg|png)"', read(page)):
        add(m.group(2), f"{page}#figure-{m.group(1)}", f"Figure {m.group(1)} of the book")


def convert_to_id(term):
    """Doxygen's search.js convertToId, on the lower-cased term."""
    out = ""
    for ch in term.lower():
        if re.match(r"[a-z0-9\u0080-\uffff]", ch):
            out += ch
        else:
            out += f"_{ord(ch):02x}" if ord(ch) >= 16 else f"_0{ord(ch):x}"
    return out


search = os.path.join(html_dir, "search")
data_js = os.path.join(search, "searchdata.js")
with open(data_js, encoding="utf-8") as f:
    data = f.read()
m = re.search(r'(indexSectionsWithContent\s*=\s*\{\s*0:\s*")([^"]*)(")', data)
if not m:
    sys.exit("paper_map: search/searchdata.js is not in the format of Doxygen 1.9.4")
old_chars = m.group(2)
by_char = {}
for i, ch in enumerate(old_chars):
    with open(os.path.join(search, f"all_{i:x}.js"), encoding="utf-8") as f:
        js = f.read()
    body = re.fullmatch(r"\s*var searchData\s*=\s*(\[.*\])\s*;?\s*", js, re.S)
    if not body:
        sys.exit(f"paper_map: search/all_{i:x}.js is not in the format of Doxygen 1.9.4")
    by_char[ch] = ast.literal_eval(body.group(1))
with open(os.path.join(search, "all_0.html"), encoding="utf-8") as f:
    template = f.read()
serial = sum(len(v) for v in by_char.values())
for term, targets in sorted(entries.items()):
    key = convert_to_id(term)
    first = term.lower()[0]
    items = [term] + [["../" + url, 1, scope] for url, scope in targets]
    by_char.setdefault(first, []).append([f"{key}_{serial}", items])
    serial += 1
chars = "".join(sorted(by_char))
for name in os.listdir(search):
    if re.fullmatch(r"all_[0-9a-f]+\.(js|html)", name):
        os.remove(os.path.join(search, name))
for i, ch in enumerate(chars):
    rows = sorted(by_char[ch], key=lambda e: e[0])
    js = "var searchData=\n[\n" + ",\n".join("  " + repr(r) for r in rows) + "\n];\n"
    bookfiles.write_text(os.path.join(search, f"all_{i:x}.js"), js)
    bookfiles.write_text(os.path.join(search, f"all_{i:x}.html"),
                         template.replace('src="all_0.js"', f'src="all_{i:x}.js"'))
bookfiles.write_text(data_js, data[:m.start(2)] + chars.replace("\\", "\\\\").replace('"', '\\"') +
                     data[m.end(2):])
# --- 3. API pages link back to the book ---------------------------------------------------------
# Each file or class page that a chapter or appendix names in its prose (not in a quoted
# snippet) gets a box under its title: the sections that use it, with the paper they implement.
papers_of = {}
for page_id, _, md in bookfiles.pages(source_dir):
    m = re.search(r"\\paper\{([^}]*)\}", md)
    papers_of[page_id] = m.group(1) if m else ""
used_in = {}
for page in sorted(p for p in os.listdir(html_dir) if p.endswith(".html") and p[:-5] in labels):
    text = read(page)
    prose = re.sub(r'<div class="fragment">.*?</div><!-- fragment -->', "", text, flags=re.S)
    heads = [(m.start(), m.group(1), text_of(m.group(2))) for m in HEADING.finditer(prose)]
    for m in re.finditer(r'<a class="el" href="((?:class|struct)[\w]+\.html|[\w]+_8hpp\.html)"',
                         prose):
        before = [h for h in heads if h[0] < m.start()]
        anchor, title = (before[-1][1], before[-1][2]) if before else ("", "")
        used_in.setdefault(m.group(1), []).append((page, anchor, title))
linked = 0
for api, places in sorted(used_in.items()):
    path = os.path.join(html_dir, api)
    if not os.path.exists(path):
        continue
    items = []
    for page, anchor, title in dict.fromkeys(places):
        label, name = labels[page[:-5]], titles.get(page[:-5], page)
        kind = "Appendix" if page.startswith("appendix-") else "Chapter"
        where = f" — {html.escape(title)}" if title else ""
        paper = papers_of.get(page[:-5], "")
        items.append(f'<li><a href="{page}{"#" + anchor if anchor else ""}">{kind} {label}. '
                     f'{html.escape(name)}{where}</a>'
                     f'{" <span class=paperref>(" + html.escape(paper) + ")</span>" if paper else ""}'
                     "</li>")
    box = ('<div class="vibook-used-in"><b>In the book:</b> the chapter sections that use this '
           'code, and the paper they implement.<ul>' + "".join(items) + "</ul></div>")
    text = read(api)
    if 'class="vibook-used-in"' in text:
        continue
    at = text.find('<div class="contents">')
    if at < 0:
        continue
    at += len('<div class="contents">')
    bookfiles.write_text(path, text[:at] + box + text[at:])
    linked += 1
print(f"paper_map: {linked} API pages link back to the chapters that use them")
print(f"paper_map: {sum(len(r) for r in out) // 1000} kB map on the first page; "
      f"{len(entries)} search entries ({len(claims)} claims, equations, figures)")
