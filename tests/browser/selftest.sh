#!/usr/bin/env bash
# The book checker must be able to fail: each defect it looks for (unrendered TeX, a broken
# image, a broken link, a console error, leaked markup, a path of the machine, a report row without anchor or
# evidence, a broken filter, sideways scrolling, a formula cut off, figure text under 12 px, a
# chapter without previous/next links, quoted code linking to a .cpp's file-local symbol, a
# caption that names no paper figure, a page without contents box, a numbered list born of a
# sentence, history words, an appendix no chapter links to, a formula MathJax cannot parse) must
# be reported, and a clean page must pass.
set -u
here=$(cd "$(dirname "$0")" && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cat >"$tmp/index.html" <<'HTML'
<!DOCTYPE html><html><head><title>ok</title></head><body><p>A clean page.</p>
<a href="index.html">self</a></body></html>
HTML
"/usr/bin/python3" "$here/check_book.py" "$tmp" >"$tmp/clean.log" 2>&1 || { echo "FAIL: clean page rejected"; cat "$tmp/clean.log"; exit 1; }
cat >"$tmp/bad.html" <<'HTML'
<!DOCTYPE html><html><head><title>bad</title></head><body>
<p>Energy \f$H = T + U\f$ left as TeX.</p>
<img src="missing.svg" alt="missing">
<a href="nowhere.html">dead link</a>
<p>A leaked placeholder \form#12 and &lt;strong&gt;markup&lt;/strong&gt; shown as text.</p>
<script>console.error("deliberate console error");</script>
</body></html>
HTML
# API pages after the first of their kind are checked without the browser: a broken link and a
# broken image there must be reported too.
cat >"$tmp/classA.html" <<'HTML'
<!DOCTYPE html><html><head><title>A</title></head><body><a href="classB.html">B</a></body></html>
HTML
cat >"$tmp/classB.html" <<'HTML'
<!DOCTYPE html><html><head><title>B</title></head><body>
<a href="classNowhere.html#x">dead API link</a><img src="gone.png" alt="gone"></body></html>
HTML
# A report whose row has no anchor and whose status filter hides nothing (no script).
cat >"$tmp/reportbad.html" <<'HTML'
<!DOCTYPE html><html><head><title>report</title></head><body>
<p class="vibook-filter">Show: <label><input type="checkbox" value="reproduced" checked> reproduced</label></p>
<table class="vibook-claims"><tr><th>ID</th></tr>
<tr class="status-reproduced" data-status="reproduced"><td>X-1</td></tr>
<tr class="status-reproduced" id="claim-X-2" data-status="reproduced"><td>X-2</td></tr></table>
</body></html>
HTML
# A chapter without previous/next links, that scrolls sideways at 1024 px, with a formula cut
# off by its box, a figure whose text is 8 px and a figure drawn 0 px wide.
cat >"$tmp/small.svg" <<'SVG'
<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 400 200"><text x="10" y="50" font-size="8">tiny label</text></svg>
SVG
cat >"$tmp/chapter-bad.html" <<'HTML'
<!DOCTYPE html><html><head><title>chapter</title></head><body>
<div style="width:1500px">a block wider than the window</div>
<div style="overflow:hidden;width:200px"><div class="MathJax_SVG_Display"><span class="MathJax_SVG"><svg xmlns="http://www.w3.org/2000/svg" width="600" height="20"></svg></span></div><script type="math/tex; mode=display">x = y + long</script></div>
<div class="image" style="width:400px"><object type="image/svg+xml" data="small.svg" style="width:400px"></object></div>
<div class="image"><span style="display:inline-block"><object type="image/svg+xml" data="small.svg"></object></span></div>
<table class="vibook-claims"><tr><td class="claim-id"><a href="report.html#claim-X-9">X-9</a></td></tr>
<tr><td class="claim-id"><a href="report.html#claim-X-9">X-9</a></td></tr></table>
<div class="fragment"><a class="code" href="helper_8cpp.html#a0123">k</a></div>
<div class="contents"><div class="image"><div class="caption">Figure 1.1. Kepler orbits, with no paper figure named.</div></div>
<p>The verdict needs a drift</p><ol start="1"><li>The verdict follows.</li></ol>
<p>In this version the step is faster.</p></div>
</body></html>
HTML
# An appendix that no chapter links to and that links to no chapter.
cat >"$tmp/appendix-orphan.html" <<'HTML'
<!DOCTYPE html><html><head><title>appendix</title></head><body><div class="contents">
<div class="toc">contents</div><p>Engineering.</p></div></body></html>
HTML
cat >"$tmp/helper_8cpp.html" <<'HTML'
<!DOCTYPE html><html><head><title>helper.cpp</title></head><body><a id="a0123">k</a></body></html>
HTML
# A formula MathJax cannot parse (an accent without its argument), configured as the book's
# pages are (Doxygen's: no noErrors extension): the SVG output draws it in red without a
# .MathJax_Error element, so the checker must ask MathJax itself.
cat >"$tmp/mathbad.html" <<'HTML'
<!DOCTYPE html><html><head><title>math</title>
<script type="text/x-mathjax-config">MathJax.Hub.Config({extensions: ["tex2jax.js"],
  jax: ["input/TeX", "output/SVG"], tex2jax: {inlineMath: [['\\(','\\)']]}});</script>
<script src="file:///usr/share/javascript/mathjax/MathJax.js"></script>
</head><body><p>A slip: \(\dot\) read as \(\ddot x\).</p></body></html>
HTML
# The engine's internal name of an abstract function, where the paper writes U.
cat >"$tmp/internal.html" <<'HTML'
<!DOCTYPE html><html><head><title>internal</title></head><body>
<p>Ours: -vibook_abstract1(0,q0)/2</p></body></html>
HTML
cat >"$tmp/leak.html" <<HTML
<!DOCTYPE html><html><head><title>leak</title></head><body>
<pre>report: $tmp/build/book/figures/verify-report/index.html</pre></body></html>
HTML
"/usr/bin/python3" "$here/check_book.py" "$tmp" --forbid "$tmp/build" >"$tmp/bad.log" 2>&1
rc=$?
fail=0
[ $rc -ne 0 ] || { echo "FAIL: checker passed a broken page"; fail=1; }
for what in "unrendered TeX" "broken image" "broken link" "deliberate console error" "raw markup"; do
  grep -q "bad.html: .*$what" "$tmp/bad.log" || { echo "FAIL: not reported: $what"; fail=1; }
done
grep -q "reportbad.html: claim row without its anchor: X-1" "$tmp/bad.log" || { echo "FAIL: row without anchor not reported"; fail=1; }
grep -q "reportbad.html: filter: row claim-X-2 shown" "$tmp/bad.log" || { echo "FAIL: broken filter not reported"; fail=1; }
for what in "no previous/next links" "page scrolls sideways at 1024 px" "formula cut off: x = y + long" \
    "figure small.svg: text displayed at 8.0 px" "broken image small.svg (drawn 0 x"; do
  grep -q "chapter-bad.html: $what" "$tmp/bad.log" || { echo "FAIL: not reported: $what"; fail=1; }
done
for what in "figure caption does not name the figure of the paper: Figure 1.1. Kepler" \
    "no box of contents" "a numbered list of 1 item(s)" 'history words "this version"'; do
  grep -q "chapter-bad.html: $what" "$tmp/bad.log" || { echo "FAIL: not reported: $what"; fail=1; }
done
grep -q "appendix-orphan.html: no chapter links to this appendix" "$tmp/bad.log" || { echo "FAIL: orphan appendix not reported"; fail=1; }
grep -q "appendix-orphan.html: the appendix links to no chapter" "$tmp/bad.log" || { echo "FAIL: appendix without a chapter link not reported"; fail=1; }
grep -q "chapter-bad.html: claim X-9 shown 2 times" "$tmp/bad.log" || { echo "FAIL: claim shown twice not reported"; fail=1; }
grep -q "chapter-bad.html: quoted code links 'k' to a file-local symbol of helper_8cpp.html" "$tmp/bad.log" || { echo "FAIL: link to a .cpp-local symbol not reported"; fail=1; }
grep -q "reportbad.html: claim row without evidence links: X-2" "$tmp/bad.log" || { echo "FAIL: row without evidence not reported"; fail=1; }
grep -q "classB.html: broken link classNowhere.html#x" "$tmp/bad.log" || { echo "FAIL: static broken link not reported"; fail=1; }
grep -q "classB.html: broken image gone.png" "$tmp/bad.log" || { echo "FAIL: static broken image not reported"; fail=1; }
grep -q 'mathbad.html: MathJax error in the formula .dot$' "$tmp/bad.log" || { echo "FAIL: a MathJax parse error not reported"; fail=1; }
grep -q 'mathbad.html: .*ddot x' "$tmp/bad.log" && { echo "FAIL: a formula that parses was reported"; fail=1; }
grep -q "leak.html: names the machine's directory $tmp/build" "$tmp/bad.log" || { echo "FAIL: a build path in a page not reported"; fail=1; }
grep -q "internal.html: internal name vibook_abstract1" "$tmp/bad.log" || { echo "FAIL: an internal name not reported"; fail=1; }
grep -q "index.html\|classA.html" "$tmp/bad.log" && { echo "FAIL: a clean page was reported"; fail=1; }
[ $fail = 0 ] && echo "book checker selftest: passed" || cat "$tmp/bad.log"
exit $fail
