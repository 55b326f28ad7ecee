# Vermeeren 2017, Fig. 1 — harmonic oscillator, Störmer–Verlet with h = 1.
# Usage: gnuplot -c vermeeren-fig1.gp <data-dir> <output-base>
data_dir = ARG1
out_base = ARG2
load ARG0[1:strstrt(ARG0, "vermeeren-fig1.gp") - 1] . "style.gp"
data = data_dir . "/discrete.csv"
curves = data_dir . "/curves.csv"
svg_out = out_base . ".svg"
png_out = out_base . ".png"

do for [fmt in "svg png"] {
  if (fmt eq "svg") { set terminal svg size 1000,500 dynamic enhanced font "DejaVu Sans,17"; set output svg_out }
  if (fmt eq "png") { set terminal pngcairo size 1100,420 enhanced font "DejaVu Sans,10"; set output png_out }
  set multiplot layout 1,2
  set xlabel "t"
  set ylabel "x"
  set yrange [-1.25:1.6]
  set key below horizontal
  set title "t in [0, 100]"
  plot curves using 1:2 with lines ls 2 title "exact x = cos t", \
       curves using 1:3 with lines ls 1 title "modified, order 2", \
       data using 2:3 with points ls 3 title "Störmer–Verlet, h = 1"
  set title "zoom: t in [80, 100]"
  set xrange [80:100]
  plot curves using 1:2 with lines ls 2 title "exact", \
       curves using 1:3 with lines ls 1 title "order 2", \
       curves using 1:4 with lines ls 4 title "order 4", \
       data using 2:3 with points ls 3 title "discrete"
  unset xrange
  unset multiplot
  unset output
}
