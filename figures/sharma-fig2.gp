# Sharma et al. 2022, Fig. 2 — EpAVI, AVI1, AVI2 on Kepler, e = 0.7, h0 = 0.001, 10 periods.
# Usage: gnuplot -c sharma-fig2.gp <data-dir> <output-base>
data_dir = ARG1
out_base = ARG2
fig_title = "e = 0.7"
load ARG0[1:strstrt(ARG0, "sharma-fig2.gp") - 1] . "sharma-fig12.inc"
