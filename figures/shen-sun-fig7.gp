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
# The worldline (x1(τ), x2(τ), t(τ)) of (3.8) over the exact orbit's, in 3-D with axes, ticks and
# a legend (the book's figure; the OSMesa rendering shen-sun-fig7-worldline.png is the shaded view).
do for [fmt in "svg"] {
  set terminal svg size 1000,900 dynamic enhanced font "DejaVu Sans,17"; set output out_base . "-worldline.svg"
  set title "Worldline of the relativistic Kepler orbit, c = 5, τ ∈ [0, 40]"
  set xlabel "x_1" offset 0,-0.5
  set ylabel "x_2" offset 0,-0.5
  set zlabel "t" rotate parallel offset -1,0
  set view 62, 32, 1, 1.1
  set ticslevel 0
  set xtics 0.5 offset 0,-0.3
  set ytics 0.5
  set ztics auto
  set grid x y z vertical lc rgb "#dddddd"
  set border 4095 lc rgb "#888888"
  set key at screen 0.5, screen 0.06 center bottom horizontal
  splot ex using 3:4:2 with points pt 7 ps 0.45 lc rgb "#555555" title "exact precessing orbit", \
        vi2 using 4:5:3 with lines lw 1.6 lc rgb "#1b6ca8" title "variational integrator (3.8)"
  unset output
}
