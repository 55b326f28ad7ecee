# Sharma et al. 2022, Fig. 5 — EpAVI with 18-digit MPFR, e = 0.7, h0 = 0.001, one period, over
# the solver tolerance. Usage: gnuplot -c sharma-fig5.gp <data-dir> <output-base>
data_dir = ARG1
out_base = ARG2
load ARG0[1:strstrt(ARG0, "sharma-fig5.gp") - 1] . "style.gp"
tols = "1e-10 1e-12 1e-14 1e-16 1e-17"
colors = "#c0392b #e67e22 #27ae60 #1b6ca8 #111111"
do for [fmt in "svg png"] {
  if (fmt eq "svg") { set terminal svg size 1000,540 dynamic enhanced font "DejaVu Sans,17"; set output out_base . ".svg" }
  if (fmt eq "png") { set terminal pngcairo size 1200,500 enhanced font "DejaVu Sans,10"; set output out_base . ".png" }
  set multiplot layout 1,2 title "EpAVI in 18-digit MPFR, Kepler e = 0.7, h_0 = 0.001"
  set xlabel "t"
  set key below horizontal
  set title "(a) discrete energy error |E_k - E_1|"
  set logscale y
  set format y "10^{%T}"
  plot for [i=1:5] data_dir . "/tol_" . word(tols, i) . ".csv" using 2:(abs($4) > 0 ? abs($4) : 1/0) with lines lw 1.5 lc rgb word(colors, i) title "tol = " . word(tols, i)
  unset logscale y
  set format y "%g"
  set key below horizontal
  set title "(b) time step h_k / h_0"
  plot for [i=1:5] data_dir . "/tol_" . word(tols, i) . ".csv" using 2:3 with lines lw (i == 5 ? 1 : 2.5) lc rgb word(colors, i) title "tol = " . word(tols, i)
  unset multiplot
  unset output
}
