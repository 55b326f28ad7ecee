# Work–precision against wall-clock time, from the benchmark run (tests/bench/bench_work_precision.cpp
# via bench_table.py). Usage: gnuplot -c bench-work-precision.gp <work_precision.csv> <output-base>
csv = ARG1
out_base = ARG2
load ARG0[1:strstrt(ARG0, "bench-work-precision.gp") - 1] . "style.gp"
do for [fmt in "svg png"] {
  if (fmt eq "svg") { set terminal svg size 900,680 dynamic enhanced font "DejaVu Sans,15"; set output out_base . ".svg" }
  if (fmt eq "png") { set terminal pngcairo size 900,600 enhanced font "DejaVu Sans,10"; set output out_base . ".png" }
  set title "Kepler e = 0.6, 10 periods: LRL-angle error against wall-clock time (median)"
  set logscale xy
  set format x "10^{%T}"
  set format y "10^{%T}"
  set xlabel "seconds per run"
  set ylabel "|Δω| after 10 periods (rad)"
  set key below horizontal
  plot csv using (strcol(1) eq "se" ? $3 : 1/0):4 with linespoints pt 7 lc rgb "#e67e22" title "symplectic Euler", \
       csv using (strcol(1) eq "sv" ? $3 : 1/0):4 with linespoints pt 5 lc rgb "#c0392b" title "Störmer–Verlet", \
       csv using (strcol(1) eq "vi1" ? $3 : 1/0):4 with linespoints pt 9 lc rgb "#1b6ca8" title "VI-1", \
       csv using (strcol(1) eq "vi2" ? $3 : 1/0):4 with linespoints pt 11 lc rgb "#27ae60" title "VI-2"
  unset output
}
