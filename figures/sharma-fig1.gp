# Sharma et al. 2022, Fig. 1 — EpAVI, AVI1, AVI2 on Kepler, e = 0.1, h0 = 0.001, 10 periods.
# Usage: gnuplot -c sharma-fig1.gp <data-dir> <output-base>
data_dir = ARG1
out_base = ARG2
fig_title = "e = 0.1"
load ARG0[1:strstrt(ARG0, "sharma-fig1.gp") - 1] . "sharma-fig12.inc"
