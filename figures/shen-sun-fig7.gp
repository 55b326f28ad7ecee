# Shen & Sun 2025, Fig. 7 — relativistic Kepler, orbits of (3.20) and (3.8) against the exact
# precessing orbit (dots). c = 5 (the paper gives none), h = 0.05, proper time τ in [0, 40].
# Usage: gnuplot -c shen-sun-fig7.gp <data-dir> <output-base>
data_dir = ARG1
out_base = ARG2
load ARG0[1:strstrt(ARG0, "shen-sun-fig7.gp") - 1] . "style.gp"
vi = data_dir . "/vi.csv"
vi2 = data_dir . "/vi2.csv"
ex = data_dir . "/exact.csv"
do for [fmt in "svg png"] {
  if (fmt eq "svg") { set terminal svg size 1000,580 dynamic enhanced font "DejaVu Sans,17"; set output out_base . ".svg" }
  if (fmt eq "png") { set terminal pngcairo size 1000,500 enhanced font "DejaVu Sans,10"; set output out_base . ".png" }
  set multiplot layout 1,2
  set size ratio -1
  set xlabel "x_1"
  set ylabel "x_2"
  set key below horizontal
  set title "variational integrator (3.20), first order"
  plot vi using 4:5 with lines ls 1 title "numerical", ex using 3:4 with points pt 7 ps 0.35 lc rgb "#111111" title "exact"
  set title "variational integrator (3.8), second order"
  plot vi2 using 4:5 with lines ls 1 title "numerical", ex using 3:4 with points pt 7 ps 0.35 lc rgb "#111111" title "exact"
  unset multiplot
  unset output
}
