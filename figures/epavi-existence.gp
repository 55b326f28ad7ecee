# Where EpAVI can step: time reached before "no admissible time step", over e, for three h0.
# Usage: gnuplot -c epavi-existence.gp <data-dir> <output-base>
data_dir = ARG1
out_base = ARG2
load ARG0[1:strstrt(ARG0, "epavi-existence.gp") - 1] . "style.gp"
f = data_dir . "/existence.csv"
do for [fmt in "svg png"] {
  if (fmt eq "svg") { set terminal svg size 900,580 dynamic enhanced font "DejaVu Sans,15"; set output out_base . ".svg" }
  if (fmt eq "png") { set terminal pngcairo size 900,500 enhanced font "DejaVu Sans,10"; set output out_base . ".png" }
  set title "EpAVI from perihelion: time reached (filled: run completed; open: no admissible step)"
  set xlabel "eccentricity e"
  set ylabel "t reached"
  set logscale y
  set key below horizontal
  plot f using ($2 == 0.01 && $3 == 1 ? $1 : 1/0):4 with points pt 7 ps 1.0 lc rgb "#c0392b" title "h_0 = 1e-2", \
       f using ($2 == 0.01 && $3 == 0 ? $1 : 1/0):4 with points pt 6 ps 1.0 lc rgb "#c0392b" notitle, \
       f using ($2 == 0.001 && $3 == 1 ? $1 : 1/0):4 with points pt 5 ps 0.9 lc rgb "#1b6ca8" title "h_0 = 1e-3", \
       f using ($2 == 0.001 && $3 == 0 ? $1 : 1/0):4 with points pt 4 ps 0.9 lc rgb "#1b6ca8" notitle, \
       f using ($2 == 0.0001 && $3 == 1 ? $1 : 1/0):4 with points pt 9 ps 1.0 lc rgb "#27ae60" title "h_0 = 1e-4 (quarter period)", \
       f using ($2 == 0.0001 && $3 == 0 ? $1 : 1/0):4 with points pt 8 ps 1.0 lc rgb "#27ae60" notitle
  unset output
}
