# `vibook verify --report DIR`: the measured order beside Störmer–Verlet and the implicit
# midpoint rule (error at T against the number of steps: work–precision in steps), and the
# envelope of the energy error over the long run.
# Usage: gnuplot -c verify-report.gp <data-dir> <output-base>
data_dir = ARG1
out_base = ARG2
load ARG0[1:strstrt(ARG0, "verify-report.gp") - 1] . "style.gp"
conv = data_dir . "/convergence.csv"
energy = data_dir . "/energy.csv"
do for [fmt in "svg png"] {
  if (fmt eq "svg") { set terminal svg size 1000,540 dynamic enhanced font "DejaVu Sans,17"; set output out_base . ".svg" }
  if (fmt eq "png") { set terminal pngcairo size 1100,460 enhanced font "DejaVu Sans,12"; set output out_base . ".png" }
  set multiplot layout 1,2
  set logscale xy
  set format x "10^{%T}"
  set format y "10^{%T}"
  set title "Error at T against steps (work–precision)"
  set xlabel "steps to T"
  set ylabel "max |z(T) − z_{ref}(T)|"
  set key below horizontal
  plot conv using 2:4 with linespoints pt 5 ps 1.3 lc rgb "#c0392b" title "Störmer–Verlet", \
       conv using 2:5 with linespoints pt 9 lc rgb "#27ae60" title "implicit midpoint", \
       conv using 2:3 with linespoints ls 1 pt 7 title "typed L_d"
  set title "Energy error envelope"
  set xlabel "steps K"
  set ylabel "max_{k ≤ K} |H_k − H_0|"
  set key below horizontal
  plot energy using 1:2 with linespoints ls 1 pt 7 title "typed L_d"
  unset multiplot
  unset output
}
