# Perihelion advance per revolution against the speed of light: exact 2π(1/Γ − 1) and the
# values measured from the numerical orbits. The Newtonian limit is 0 (c → ∞).
# Usage: gnuplot -c relativistic-precession.gp <data-dir> <output-base>
data_dir = ARG1
out_base = ARG2
load ARG0[1:strstrt(ARG0, "relativistic-precession.gp") - 1] . "style.gp"
sweep = data_dir . "/sweep.csv"
do for [fmt in "svg png"] {
  if (fmt eq "svg") { set terminal svg size 800,600 dynamic enhanced font "DejaVu Sans,14"; set output out_base . ".svg" }
  if (fmt eq "png") { set terminal pngcairo size 800,520 enhanced font "DejaVu Sans,10"; set output out_base . ".png" }
  set logscale xy
  set xlabel "speed of light c"
  set ylabel "perihelion advance per revolution (rad)"
  set key below horizontal
  set title "Relativistic Kepler, x_0 = (0.4, 0), u_0 = (0, 2): precession against c (Newtonian limit: 0)"
  plot sweep using 1:2 with lines ls 2 title "exact 2π(1/Γ − 1)", \
       sweep using 1:3 with points pt 7 ps 1.2 lc rgb "#1b6ca8" title "measured, (3.8), h = 5·10^{-4}", \
       sweep using 1:4 with points pt 6 ps 1.8 lc rgb "#c0392b" title "measured, (3.20), h = 5·10^{-4}"
  unset output
}
