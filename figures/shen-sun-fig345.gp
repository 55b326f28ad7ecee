# Shen & Sun 2025, Figs. 3–5 — (x0, p0) = (-3, 0, 0, 0.45), h = 0.05: energy error, eccentricity
# error and LRL-angle error of the four methods. Usage: gnuplot -c shen-sun-fig345.gp <data-dir> <out>
data_dir = ARG1
out_base = ARG2
load ARG0[1:strstrt(ARG0, "shen-sun-fig345.gp") - 1] . "style.gp"
names = "se sv vi1 vi2"
titles = "'symplectic Euler' 'Störmer–Verlet' 'VI-1' 'VI-2'"
# The paper's grouping: red for the classical splittings (symplectic Euler, Störmer–Verlet),
# blue for the new variational integrators; within a group, solid and dashed.
colors = "#b03a2e #e8776b #1b4f8a #5dade2"
dashes = "1 2 1 2"
faint = "#d8b03a2e #d8e8776b #d81b4f8a #d85dade2"
# Errors span four decades between the methods and oscillate with the orbit: |error| on a log
# axis, faint, and its running maximum max_{s<=t} |error(s)| bold, so that every method is
# visible and a bounded error shows as a flat envelope (an exact zero, which a log axis
# cannot show, is left out of the faint curve).
absnz(x) = (abs(x) > 0 ? abs(x) : NaN)
runmax(x) = (column(0) == 0 ? (m = abs(x)) : (m = (abs(x) > m ? abs(x) : m)))
m = 0
do for [fmt in "svg png"] {
  if (fmt eq "svg") { set terminal svg size 1000,1100 dynamic enhanced font "DejaVu Sans,17"; set output out_base . ".svg" }
  if (fmt eq "png") { set terminal pngcairo size 1200,1100 enhanced font "DejaVu Sans,12"; set output out_base . ".png" }
  set multiplot layout 3,1 title "(x_0, p_0) = (-3, 0, 0, 0.45), h = 0.05; red: symplectic Euler, Störmer–Verlet; blue: VI-1, VI-2"
  set xlabel "t"
  set logscale y
  set format y "10^{%T}"
  set key outside top center horizontal
  set title "Fig. 3: energy error |H - H_0| (faint) and its running maximum (bold)"
  plot for [i=1:4] data_dir . "/" . word(names, i) . ".csv" using 1:(absnz($4)) with lines lw 1 lc rgb word(faint, i) notitle, \
       for [i=1:4] data_dir . "/" . word(names, i) . ".csv" using 1:(runmax($4)) with lines lw 2.5 dt int(word(dashes, i)) lc rgb word(colors, i) title word(titles, i)
  unset key  # one key, above the first panel, for all three
  set title "Fig. 4: eccentricity error ||A| - e|"
  plot for [i=1:4] data_dir . "/" . word(names, i) . ".csv" using 1:(absnz($5)) with lines lw 1 lc rgb word(faint, i) notitle, \
       for [i=1:4] data_dir . "/" . word(names, i) . ".csv" using 1:(runmax($5)) with lines lw 2.5 dt int(word(dashes, i)) lc rgb word(colors, i) title word(titles, i)
  set title "Fig. 5: LRL-angle error (rad), absolute value"
  plot for [i=1:4] data_dir . "/" . word(names, i) . ".csv" using 1:(absnz($6)) with lines lw 1 lc rgb word(faint, i) notitle, \
       for [i=1:4] data_dir . "/" . word(names, i) . ".csv" using 1:(runmax($6)) with lines lw 2.5 dt int(word(dashes, i)) lc rgb word(colors, i) title word(titles, i)
  unset multiplot
  set key
  unset output
}
