// vibook book (Doxyfile MATHJAX_CODEFILE): every displayed equation of a page is numbered,
// (1), (2), ...; a display that restates a paper's equation carries the paper's number
// instead, written \tag{S 25} in the chapter.
// Long formulas (engine-derived expressions, evaluation points in claims' notes) are broken
// over lines at the width of their column, at top-level operators, as a typesetter would.
MathJax.Hub.Config({ TeX: { equationNumbers: { autoNumber: "all" } },
                     SVG: { linebreaks: { automatic: true } } });
// A formula wider than its column (a long difference or evaluation point in a claim's note)
// scrolls sideways inside the column instead of widening the page: after typesetting, such
// a formula gets the class vibook-wide (vibook.css gives it a scroll bar). Only the wide ones:
// a box that scrolls loses the text's baseline, so narrow formulas are left inline.
MathJax.Hub.Register.MessageHook("End Process", function () {
  var blockOf = function (e) {
    for (var a = e.parentElement; a; a = a.parentElement) {
      var d = window.getComputedStyle(a).display;
      if (d !== "inline" && d !== "contents") return a;
    }
    return document.body;
  };
  var spans = document.querySelectorAll("span.MathJax_SVG");
  for (var i = 0; i < spans.length; ++i) {
    var s = spans[i], b = blockOf(s);
    var cs = window.getComputedStyle(b);
    var room = b.clientWidth - parseFloat(cs.paddingLeft) - parseFloat(cs.paddingRight);
    if (s.getBoundingClientRect().width > room) s.classList.add("vibook-wide");
  }
});
