# Sharma et al. 2022, (29): growth of EpAVI's discrete-energy error envelope with the number of
# steps, per precision, against the slopes 1/2 and 1. Usage: gnuplot -c sharma-eq29-long.gp <data-dir> <out>
data_dir = ARG1
out_base = ARG2
load ARG0[1:strstrt(ARG0, "sharma-eq29-long.gp") - 1] . "style.gp"
runs = "double long_double double_double quad double_target_E1 double_generic double_generic_absolute_time"
colors = "#1b6ca8 #c0392b #27ae60 #8e44ad #7fb3d5 #e67e22 #5d5d5d"
do for [fmt in "svg png"] {
  if (fmt eq "svg") { set terminal svg size 900,680 dynamic enhanced font "DejaVu Sans,15"; set output out_base . ".svg" }
  if (fmt eq "png") { set terminal pngcairo size 900,560 enhanced font "DejaVu Sans,10"; set output out_base . ".png" }
  set title "EpAVI, Kepler e = 0.7, h_0 = 0.01: max_{j≤k} |E_j - E_1| against k"
  set logscale xy
  set format x "10^{%T}"
  set format y "10^{%T}"
  set xlabel "steps k"
  set ylabel "discrete-energy error envelope"
  set key below horizontal maxcols 3
  plot for [i=1:7] data_dir . "/" . word(runs, i) . ".csv" using 1:($2 > 0 ? $2 : 1/0) with linespoints pt 7 ps 0.5 lw 1.5 lc rgb word(colors, i) title word(runs, i) noenhanced, \
       1e-16 * sqrt(x) with lines dt 2 lc rgb "#888888" title "∝ k^{1/2}", \
       1e-16 * x with lines dt 3 lc rgb "#444444" title "∝ k"
  unset output
}
