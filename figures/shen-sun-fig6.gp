# Shen & Sun 2025, Fig. 6 — errors of the LRL vector after one period against h = T/n ≈ 2^-i,
# for §5's two initial conditions and one off the orbit's axis (the paper gives none). Usage: gnuplot -c shen-sun-fig6.gp <data-dir> <out>
data_dir = ARG1
out_base = ARG2
load ARG0[1:strstrt(ARG0, "shen-sun-fig6.gp") - 1] . "style.gp"
ics = "perihelion_e0.6 x0_-3_p0_0.45 e0.6_at_T_5"
ictitles = "'e = 0.6 from perihelion' '(x_0, p_0) = (-3, 0, 0, 0.45)' 'e = 0.6, T/5 after perihelion'"
titles = "'symplectic Euler' 'Störmer–Verlet' 'VI-1' 'VI-2'"
colors = "#e67e22 #c0392b #1b6ca8 #27ae60"
do for [fmt in "svg png"] {
  if (fmt eq "svg") { set terminal svg size 1000,1400 dynamic enhanced font "DejaVu Sans,17"; set output out_base . ".svg" }
  if (fmt eq "png") { set terminal pngcairo size 1200,1350 enhanced font "DejaVu Sans,10"; set output out_base . ".png" }
  set multiplot layout 3,2 title "LRL vector after one period (period closed exactly)"
  set logscale xy
  set format x "10^{%T}"
  set format y "10^{%T}"
  set xlabel "h"
  set key below horizontal
  do for [j=1:3] {
    f = data_dir . "/" . word(ics, j) . ".csv"
    set title "(a) eccentricity error, " . word(ictitles, j)
    plot for [i=1:4] f using 1:(column(1 + i) > 0 ? column(1 + i) : 1/0) with linespoints pt 7 ps 0.6 lc rgb word(colors, i) title word(titles, i), \
         0.1 * x**2 with lines dt 2 lc rgb "#888888" title "h^2", 0.1 * x**4 with lines dt 3 lc rgb "#444444" title "h^4"
    set title "(b) angle error, " . word(ictitles, j)
    plot for [i=1:4] f using 1:(column(5 + i) > 0 ? column(5 + i) : 1/0) with linespoints pt 7 ps 0.6 lc rgb word(colors, i) title word(titles, i), \
         0.1 * x**2 with lines dt 2 lc rgb "#888888" title "h^2"
  }
  unset multiplot
  unset output
}
