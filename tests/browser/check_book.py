#!/usr/bin/python3
"""Open every page of the built book in headless Chromium (Debian's chromium and
chromium-driver, driven by python3-selenium) and fail on:
  - TeX left unrendered (raw \\( \\[ \\f$ in the text, or a MathJax error),
  - Doxygen markup shown as text (\\form#N placeholders, literal <strong>, **bold**),
  - a broken image (not loaded, or drawn 0 px wide or high: an <img>, or a figure's SVG
    <object>, which a shrink-to-fit wrapper once drew at 0 x 0 px on every chapter),
  - a broken local link (a file that does not exist),
  - any console error (including failed resource loads),
  - on the reproduction report: a claim row without its anchor (#claim-ID), or a status filter
    that does not hide exactly the rows of the status unticked, or a row without links to
    its evidence,
  - a page that scrolls sideways at 1024 px (the window is 1024 px wide; an element meant to
    scroll, such as a long derived formula, sits in its own overflow box and is allowed),
  - a formula cut off (it overflows a box that hides the overflow, or the page),
  - a figure whose text is displayed smaller than 12 px (the base size of each text element:
    a gnuplot sub- or superscript is smaller by design and is not counted),
  - a chapter, the report or the benchmarks page without its previous/next links,
  - a claim shown twice in the chapters,
  - a search box that finds nothing (the class MechanicalEpAVI, the claim ID S-F5, the
    equation number (4.21) and the paper figure "Shen & Sun Fig. 6", typed on the first page),
  - a chapter or appendix whose figure caption does not begin with the paper's figure it
    reproduces ("Sharma et al. Fig. 1", "Shen & Sun Figs. 3–5") or say "Not in the papers",
  - a chapter, appendix, the report or a table page without its box of contents (div.toc),
  - an appendix no chapter links to, or that links to no chapter,
  - a display or a claim's note wider than its column in the chapters, appendices and the
    report (a long formula is broken over lines, book/mathjax-config.js; the formula tables,
    whose narrow columns quote the papers' displays verbatim, let a display scroll),
  - a numbered list born of a sentence that ends in a number (Markdown reads "a drift 1." at
    the end of a line, followed by text, as a list: an <ol> with a single item or a start
    other than 1), and history words a reader has no use for ("this version", "a first
    version", "until now").
The book's own pages (chapters, report, index, anything with TeX), and the first page of each
kind of Doxygen API page, are opened in the browser. The other API pages (about 300, with no
TeX: the API documentation writes its formulas in Unicode) are checked without a browser for
broken links and images, which is what can go wrong there; opening each in Chromium to wait
for MathJax took 0.8 s a page, most of this test's time.
Usage: check_book.py BOOK_HTML_DIR"""
import os
import re
import sys
from html.parser import HTMLParser
from urllib.parse import unquote, urlparse

from selenium import webdriver
from selenium.webdriver.chrome.service import Service

html_dir = os.path.abspath(sys.argv[1])
# --forbid PATH (repeatable): a directory of this machine (the source and the build tree) whose
# path must not appear in any page's text: a reader's book never names where it was built.
forbidden = [os.path.abspath(sys.argv[i + 1]) for i in range(2, len(sys.argv) - 1)
             if sys.argv[i] == "--forbid"]
if not os.path.exists(os.path.join(html_dir, "index.html")):
    sys.exit(f"check_book: {html_dir}/index.html not found; build the book first (./build.sh book)")

opts = webdriver.ChromeOptions()
opts.binary_location = "/usr/bin/chromium"
for flag in ("--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
             "--disable-background-networking", "--disable-component-update", "--disable-sync",
             "--window-size=1024,900", "--allow-file-access-from-files"):
    opts.add_argument(flag)
opts.set_capability("goog:loggingPrefs", {"browser": "ALL"})
driver = webdriver.Chrome(service=Service("/usr/bin/chromedriver"), options=opts)
driver.set_script_timeout(60)

WAIT_MATHJAX = """
const done = arguments[arguments.length - 1];
const t0 = Date.now();
(function poll() {
  if (window.MathJax && MathJax.Hub && MathJax.Hub.Queue) {
    MathJax.Hub.Queue(function () { done("rendered"); });
  } else if (!document.querySelector('script[src*="MathJax.js"]')) {
    done("no-mathjax");
  } else if (Date.now() - t0 > 30000) {
    done("timeout");
  } else {
    setTimeout(poll, 50);
  }
})();
"""

INSPECT = """
const out = {errors: [], images: [], links: []};
document.querySelectorAll('.MathJax_Error, merror').forEach(e => out.errors.push('MathJax error: ' + e.textContent));
// A TeX error rendered by the SVG output (a red box) leaves no .MathJax_Error element: look
// for the merror node in each formula's MathML tree.
if (window.MathJax && MathJax.Hub && MathJax.Hub.getAllJax) {
  const hasError = (node, depth) => {
    if (!node || depth > 200) return false;
    if (node.type === 'merror') return true;
    return Array.isArray(node.data) && node.data.some(c => hasError(c, depth + 1));
  };
  MathJax.Hub.getAllJax().forEach(j => {
    if (hasError(j.root, 0))
      out.errors.push('MathJax error in the formula ' + String(j.originalText || '').slice(0, 80));
  });
}
const walker = document.createTreeWalker(document.body, NodeFilter.SHOW_TEXT);
while (walker.nextNode()) {
  const n = walker.currentNode;
  const p = n.parentElement;
  if (!p || p.closest('script, pre, code, .fragment, .line, style')) continue;
  const t = n.textContent;
  if (/\\\\\\(|\\\\\\[|\\\\f\\$|\\\\f\\[|Math Processing Error/.test(t)) out.errors.push('unrendered TeX: ' + t.trim().slice(0, 80));
  // Doxygen's own markup shown as text: a formula placeholder (\\form#N) or HTML/Markdown
  // left literal, as after a \\ref whose quoted text was broken across two lines.
  const raw = t.match(/\\\\_?form#\\d+|<\\/?(strong|em|a|code|tt|b)\\b[^>]*>|\\*\\*[A-Za-z]/);
  if (raw) out.errors.push('raw markup ' + raw[0] + ': ' + t.trim().slice(0, 80));
}
document.querySelectorAll('img').forEach(i => {
  if (!i.complete || i.naturalWidth === 0) out.images.push(i.getAttribute('src'));
});
document.querySelectorAll('object[data]').forEach(o => {
  out.links.push(o.getAttribute('data'));
  const r = o.getBoundingClientRect();
  if (r.width < 1 || r.height < 1) out.images.push(o.getAttribute('data') + ' (drawn ' + r.width + ' x ' + r.height + ' px)');
});
document.querySelectorAll('a[href]').forEach(a => out.links.push(a.href));
return out;
"""

FILTER = """
const out = [];
const all = Array.from(document.querySelectorAll('table.vibook-claims tr')).filter(r => !r.querySelector('th'));
const notes = all.filter(r => r.classList.contains('claim-note'));
const rows = all.filter(r => !r.classList.contains('claim-note'));
rows.forEach(r => {
  const a = r.cells[0] ? r.cells[0].querySelector('a') : null;
  const id = (a || r.cells[0] || r).textContent.trim();
  if (!id || r.id !== 'claim-' + id) out.push('claim row without its anchor: ' + id);
  if (!r.getAttribute('data-status')) out.push('claim row without data-status: ' + id);
  const ev = r.querySelector('td.claim-evidence');
  if (!ev || !ev.querySelector('a')) out.push('claim row without evidence links: ' + id);
});
const box = document.querySelector('p.vibook-filter input[value="reproduced"]');
if (!box) { out.push('status filter without a "reproduced" box'); return out; }
box.click();
rows.concat(notes).forEach(r => {
  const hidden = r.style.display === 'none';
  const want = r.getAttribute('data-status') === 'reproduced';
  if (hidden !== want) out.push('filter: row ' + r.id + (hidden ? ' hidden' : ' shown'));
});
box.click();
if (rows.some(r => r.style.display === 'none')) out.push('filter: rows stay hidden after re-ticking');
return out;
"""

# Layout at 1024 px: sideways scrolling of the page, formulas cut off, figure text < 12 px.
LAYOUT = """
const out = [];
const content = document.querySelector('#doc-content') || document.scrollingElement;
if (content.scrollWidth > content.clientWidth + 1)
  out.push('page scrolls sideways at ' + window.innerWidth + ' px: content ' + content.scrollWidth +
           ' px wide in ' + content.clientWidth + ' px');
const right = content.getBoundingClientRect().left + content.clientWidth;
function box(el) {  // the nearest ancestor that clips or scrolls sideways, below the page
  for (let a = el.parentElement; a && a !== content; a = a.parentElement) {
    const ox = getComputedStyle(a).overflowX;
    if (ox !== 'visible') return a;
  }
  return null;
}
document.querySelectorAll('.MathJax_SVG svg, .MathJax_SVG_Display svg').forEach(m => {
  const r = m.getBoundingClientRect();
  if (r.width === 0) return;
  const b = box(m);
  const tex = (m.closest('.MathJax_SVG_Display') || m.closest('.MathJax_SVG') || m).nextElementSibling;
  const what = tex && tex.tagName === 'SCRIPT' ? tex.textContent.trim().slice(0, 60) : '';
  if (b && getComputedStyle(b).overflowX === 'hidden') {
    if (r.right > b.getBoundingClientRect().right + 1) out.push('formula cut off: ' + what);
  } else if (!b && r.right > right + 1) {
    out.push('formula wider than the page: ' + what);
  } else if (b && r.width > b.clientWidth + 1 && !arguments[0]) {
    // in a box that scrolls: readable, but not as a display should be (break it over lines)
    out.push('display wider than its column (' + Math.round(r.width) + ' px in ' + b.clientWidth +
             ' px): ' + what);
  }
});
// A claim's note (chapter tables and the report) wraps within its cell.
document.querySelectorAll('table.vibook-claims div.note, table.vibook-claims td').forEach(n => {
  if (n.scrollWidth > n.clientWidth + 1)
    out.push('note wider than its column (' + n.scrollWidth + ' px in ' + n.clientWidth + ' px): ' +
             n.textContent.trim().slice(0, 60));
});
document.querySelectorAll('div.image object[data$=".svg"]').forEach(o => {
  const doc = o.contentDocument;
  if (!doc) { out.push('figure not readable: ' + o.getAttribute('data')); return; }
  let smallest = Infinity, sample = '';
  doc.querySelectorAll('text').forEach(t => {
    if (!t.textContent.trim()) return;
    const ctm = t.getScreenCTM();
    if (!ctm) return;
    const px = parseFloat(doc.defaultView.getComputedStyle(t).fontSize) * Math.hypot(ctm.a, ctm.b);
    if (px < smallest) { smallest = px; sample = t.textContent.trim().slice(0, 30); }
  });
  if (smallest < 11.95)
    out.push('figure ' + o.getAttribute('data') + ': text displayed at ' + smallest.toFixed(1) +
             ' px ("' + sample + '"), below 12 px');
});
return out;
"""

TEX = re.compile(r"\\\(|\\\[|\\f\$|\\f\[|\$\$")

# The book's shape: figure captions name the paper's figure, a box of contents, no numbered
# list made of a sentence, no history words. Arguments: is a chapter or appendix, is a page of
# the book (chapters, appendices, report, tables).
SHAPE = """
const out = [];
const chapter = arguments[0], bookPage = arguments[1];
if (chapter) {
  document.querySelectorAll('div.image div.caption').forEach(c => {
    const t = c.textContent.replace(/\\s+/g, ' ').trim();
    if (!/^Figure [A-Z0-9]+\\.\\d+\\. ((Sharma et al\\.|Vermeeren|Shen & Sun) Figs?\\. \\d|Not in the papers)/.test(t))
      out.push('figure caption does not name the figure of the paper: ' + t.slice(0, 70));
  });
}
if (bookPage && !document.querySelector('div.toc'))
  out.push('no box of contents (write [TOC] under the title)');
document.querySelectorAll('div.contents ol').forEach(ol => {
  const start = ol.getAttribute('start');
  if ((start && start !== '1') || ol.querySelectorAll(':scope > li').length === 1)
    out.push('a numbered list of ' + ol.querySelectorAll(':scope > li').length +
             ' item(s) starting at ' + (start || '1') + ', born of a sentence ending in a number? "' +
             ol.textContent.trim().slice(0, 60) + '"');
});
const words = /\\b(this version|previous version|first version|earlier version|until now|until this|used to be)\\b/i;
const walker = document.createTreeWalker(document.querySelector('div.contents') || document.body,
                                         NodeFilter.SHOW_TEXT);
while (walker.nextNode()) {
  const n = walker.currentNode;
  if (n.parentElement && n.parentElement.closest('pre, code, .fragment, script')) continue;
  const m = n.textContent.match(words);
  if (m) out.push('history words "' + m[0] + '": ' + n.textContent.trim().slice(0, 70));
}
return out;
"""


def api_kind(page):
    """The kind of a Doxygen-generated API page (None for the book's own pages)."""
    if page.endswith("_source.html"):
        return "source"
    if re.search(r"_8(hpp|cpp|md)\.html$", page):
        return "file"
    for kind in ("class", "struct", "namespace", "dir_", "functions", "globals", "hierarchy",
                 "annotated", "files", "pages", "union"):
        if page.startswith(kind):
            return kind
    return None


class Refs(HTMLParser):
    """The local references of a page: a[href], img[src], object[data]."""

    def __init__(self):
        super().__init__()
        self.refs = []

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        for t, k in (("a", "href"), ("img", "src"), ("object", "data")):
            if tag == t and a.get(k):
                self.refs.append((t, a[k]))


def static_check(page, text):
    out = []
    parser = Refs()
    parser.feed(text)
    for tag, ref in parser.refs:
        u = urlparse(ref)
        if u.scheme not in ("", "file") or not u.path:
            continue
        target = os.path.normpath(os.path.join(html_dir, unquote(u.path)))
        if not os.path.exists(target):
            out.append(f"{page}: {'broken image' if tag == 'img' else 'broken link'} {ref}")
    return out


# Names of the engine that mean nothing to a reader: the abstract functions' GiNaC names.
INTERNAL = re.compile(r"vibook_abstract[0-9]")
pages = sorted(f for f in os.listdir(html_dir) if f.endswith(".html"))
problems = []
checked = 0
browser_pages, seen_kinds = [], set()
for page in pages:
    with open(os.path.join(html_dir, page), encoding="utf-8", errors="replace") as f:
        text = f.read()
    for path in forbidden:
        if path + "/" in text:
            problems.append(f"{page}: names the machine's directory {path}")
    kind = api_kind(page)
    # Doxygen's empty file page of a book page (NAME_8md.html) is a redirect to that page
    # (chapter_nav.py): nothing else, and its target exists.
    if page.endswith("_8md.html"):
        m = re.search(r'http-equiv="refresh" content="0; url=([\w.-]+)"', text)
        if not m or 'class="contents"' in text:
            problems.append(f"{page}: a stray Doxygen file page (chapter_nav.py makes it a "
                            f"redirect to its book page)")
        elif not os.path.exists(os.path.join(html_dir, m.group(1))):
            problems.append(f"{page}: redirects to {m.group(1)}, which does not exist")
        checked += 1
        continue
    # A page that shows a placeholder (a figure or table this build did not measure) says so
    # at its top (book/partial_notice.py).
    if kind is None and 'class="vibook-partial"' not in text:
        shows = [r for r in re.findall(r'(?:data|src)="([\w.-]+\.svg)"', text)
                 if os.path.exists(os.path.join(html_dir, r)) and
                 "not run in this build" in open(os.path.join(html_dir, r), encoding="utf-8",
                                                   errors="replace").read()]
        if shows or "Not measured in this build" in text:
            problems.append(f"{page}: shows what this build did not measure "
                            f"({', '.join(shows) or 'a table'}) without a partial-build notice")
    # The engine's internal names never reach a reader (the API pages document them).
    if kind is None:
        for name in sorted(set(INTERNAL.findall(text))):
            problems.append(f"{page}: internal name {name} (print it in the paper's notation)")
    if kind is None or TEX.search(text) or kind not in seen_kinds:
        browser_pages.append(page)
        if kind is not None:
            seen_kinds.add(kind)
    else:
        problems += static_check(page, text)
        checked += 1
print(f"book_in_browser: {len(browser_pages)} pages in Chromium, {checked} checked statically")

# The chapters, the report and the benchmarks page carry previous/next links (chapter_nav.py).
book_pages = {p for p in pages if p.startswith(("chapter-", "appendix-")) or
              p.startswith("errata-") or p in ("report.html", "formulas.html", "benchmarks.html")}
for page in browser_pages:
    kind = api_kind(page)
    path = os.path.join(html_dir, page)
    driver.get("file://" + path)
    state = driver.execute_async_script(WAIT_MATHJAX)
    if state == "timeout":
        problems.append(f"{page}: MathJax did not finish within 30 s")
    res = driver.execute_script(INSPECT)
    for e in res["errors"]:
        problems.append(f"{page}: {e}")
    for src in res["images"]:
        problems.append(f"{page}: broken image {src}")
    for href in res["links"]:
        u = urlparse(href)
        if u.scheme in ("", "file"):
            target = unquote(u.path) if u.scheme == "file" else os.path.join(html_dir, unquote(u.path))
            if target and not os.path.exists(target):
                problems.append(f"{page}: broken link {href}")
    if kind is None:  # the book's own pages: layout at 1024 px, previous/next links
        # The formula tables and the errata sheets show the papers' displays as printed, in
        # boxes that scroll sideways: a wide one is the paper's line, not ours to break.
        papers_displays = page == "formulas.html" or page.startswith("errata-")
        for e in driver.execute_script(LAYOUT, papers_displays):
            problems.append(f"{page}: {e}")
        for e in driver.execute_script(SHAPE, page.startswith(("chapter-", "appendix-")),
                                       page in book_pages):
            problems.append(f"{page}: {e}")
        if page in book_pages and not driver.execute_script(
                "return document.querySelectorAll('div.vibook-pagenav').length === 2"):
            problems.append(f"{page}: no previous/next links (book/chapter_nav.py)")
    if driver.execute_script("return document.querySelector('p.vibook-filter') !== null"):
        for e in driver.execute_script(FILTER):
            problems.append(f"{page}: {e}")
    for entry in driver.get_log("browser"):
        if entry["level"] in ("SEVERE", "ERROR"):
            problems.append(f"{page}: console {entry['level']}: {entry['message'][:200]}")
    checked += 1
# Each claim is shown once in the chapters (other checks that measure it link to its row).
# And the code a chapter quotes links to the library's API, never to a file-local helper of a
# .cpp (a member anchor on a .cpp's file page; its source listing, *_8cpp_source.html, is fine):
# a name like x, k or ok in a snippet linked there while Doxygen parsed the .cpp files whole
# (Doxyfile, FILTER_PATTERNS).
shown = {}
for page in sorted(p for p in pages if p.startswith("chapter-")):
    with open(os.path.join(html_dir, page), encoding="utf-8") as f:
        text = f.read()
    for cid in re.findall(r'class="claim-id"><a href="report\.html#claim-([\w.-]+)"', text):
        shown.setdefault(cid, []).append(page)
    for target, name in sorted(set(re.findall(r'<a [^>]*href="([^"#]*_8cpp\.html)#[^"]*"[^>]*>([^<]*)</a>',
                                              text))):
        problems.append(f"{page}: quoted code links {name!r} to a file-local symbol of {target}")
for cid, where in sorted(shown.items()):
    if len(where) > 1:
        problems.append(f"{where[0]}: claim {cid} shown {len(where)} times ({', '.join(where)})")

# Engineering moved out of a chapter lives in an appendix that the chapter links to, and that
# links back to it.
chapter_text = {}
for page in pages:
    if page.startswith("chapter-"):
        with open(os.path.join(html_dir, page), encoding="utf-8") as f:
            chapter_text[page] = f.read()
for page in sorted(p for p in pages if p.startswith("appendix-") and not p.endswith("_8md.html")):
    if not any(f'href="{page}' in text for text in chapter_text.values()):
        problems.append(f"{page}: no chapter links to this appendix")
    with open(os.path.join(html_dir, page), encoding="utf-8") as f:
        body = f.read()
    body = body[body.find('<div class="contents">'):]
    body = re.sub(r'<div class="vibook-pagenav">.*?</div>', "", body, flags=re.S)
    if not re.search(r'href="chapter-[\w-]+\.html', body):
        problems.append(f"{page}: the appendix links to no chapter")

# Doxygen's offline search: each term typed on the first page lists what it names (a
# Doxygen book only: the selftest's pages have no search box). Claim IDs, equation numbers and
# paper figures are added to Doxygen's index by book/paper_map.py.
SEARCHES = [("MechanicalEpAVI", "MechanicalEpAVI"), ("S-F5", "S-F5"), ("(4.21)", "(4.21)"),
            ("Shen & Sun Fig. 6", "Shen & Sun Fig. 6")]
if os.path.exists(os.path.join(html_dir, "navtreedata.js")):
    from selenium.webdriver.common.by import By
    for term, want in SEARCHES:
        driver.get("file://" + os.path.join(html_dir, "index.html"))
        field = driver.find_elements(By.ID, "MSearchField")
        if not field:
            problems.append("index.html: no search box (Doxyfile SEARCHENGINE)")
            break
        field[0].click()
        field[0].send_keys(term)
        found = ""
        for _ in range(50):  # up to 5 s for the results frame
            frames = driver.find_elements(By.ID, "MSearchResults")
            if frames:
                driver.switch_to.frame(frames[0])
                found = driver.execute_script(
                    "return Array.from(document.querySelectorAll('div.SRResult'))"
                    ".filter(r => r.style.display === 'block').map(r => r.innerText).join(' | ')")
                driver.switch_to.default_content()
                if want in found:
                    break
            driver.execute_script("return new Promise(r => setTimeout(r, 100))")
        if want not in found:
            problems.append(f"index.html: the search for {term!r} found nothing ({found[:60]!r})")
driver.quit()

for p in problems:
    print("FAIL:", p)
print(f"book_in_browser: {checked - len({p.split(':')[0] for p in problems})} passed, "
      f"{len({p.split(':')[0] for p in problems})} failed")
sys.exit(1 if problems else 0)
