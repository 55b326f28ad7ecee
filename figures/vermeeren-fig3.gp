# Vermeeren 2017, Fig. 3 — Kepler, Störmer–Verlet h = 0.5, x0 = (−3, 0), ẋ0 = (0, 0.4): left the
# discrete orbit, right the solution of the modified equation truncated after h², both with the
# exact ellipse (dashed); the first 100 time units are drawn. Usage: gnuplot -c vermeeren-fig3.gp <data-dir> <out>
data_dir = ARG1
out_base = ARG2
load ARG0[1:strstrt(ARG0, "vermeeren-fig3.gp") - 1] . "style.gp"
do for [fmt in "svg png"] {
  if (fmt eq "svg") { set terminal svg size 1000,640 dynamic enhanced font "DejaVu Sans,17"; set output out_base . ".svg" }
  if (fmt eq "png") { set terminal pngcairo size 1100,560 enhanced font "DejaVu Sans,10"; set output out_base . ".png" }
  set multiplot layout 1,2 title "Kepler, Störmer–Verlet h = 0.5, t ∈ [0, 100] (the precession is measured over [0, 700])"
  set size ratio -1
  set xlabel "x_1"
  set ylabel "x_2"
  set key below horizontal
  set title "discrete solution"
  plot data_dir . "/discrete.csv" using ($1 <= 100 ? $2 : 1/0):3 with points pt 7 ps 0.25 lc rgb "#1b6ca8" title "x_j", \
       data_dir . "/exact.csv" using 2:3 with lines lw 2 dt 2 lc rgb "#c0392b" title "exact"
  set title "modified equation, truncated after h^2"
  plot data_dir . "/modified.csv" using ($1 <= 100 ? $2 : 1/0):3 with lines lw 0.6 lc rgb "#1b6ca8" title "modified", \
       data_dir . "/exact.csv" using 2:3 with lines lw 2 dt 2 lc rgb "#c0392b" title "exact"
  unset multiplot
  unset output
}
