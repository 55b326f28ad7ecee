# Shen & Sun 2025, Fig. 2 — Kepler e = 0.6, h = 0.05, t in [0, 200]: orbits of symplectic Euler,
# Störmer–Verlet, VI-1 and VI-2 against the exact ellipse. Usage: gnuplot -c shen-sun-fig2.gp <data-dir> <out>
data_dir = ARG1
out_base = ARG2
load ARG0[1:strstrt(ARG0, "shen-sun-fig2.gp") - 1] . "style.gp"
names = "se sv vi1 vi2"
titles = "'symplectic Euler' 'Störmer–Verlet' 'VI-1' 'VI-2'"
do for [fmt in "svg png"] {
  if (fmt eq "svg") { set terminal svg size 1000,1000 dynamic enhanced font "DejaVu Sans,17"; set output out_base . ".svg" }
  if (fmt eq "png") { set terminal pngcairo size 1000,900 enhanced font "DejaVu Sans,10"; set output out_base . ".png" }
  set multiplot layout 2,2 title "Kepler e = 0.6, h = 0.05, t ∈ [0, 200]"
  set size ratio -1
  set xlabel "x_1"
  set ylabel "x_2"
  set key below horizontal
  do for [i=1:4] {
    set title word(titles, i)
    plot data_dir . "/" . word(names, i) . ".csv" using 2:3 with lines lw 0.8 lc rgb "#1b6ca8" title "numerical", \
         data_dir . "/exact.csv" using 2:3 with lines lw 2 dt 2 lc rgb "#c0392b" title "exact"
  }
  unset multiplot
  unset output
}
