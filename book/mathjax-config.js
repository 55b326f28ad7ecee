// vibook book (Doxyfile MATHJAX_CODEFILE): every displayed equation of a page is numbered,
// (1), (2), ...; a display that restates a paper's equation carries the paper's number
// instead, written \tag{S 25} in the chapter.
MathJax.Hub.Config({ TeX: { equationNumbers: { autoNumber: "all" } } });
