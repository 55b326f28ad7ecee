# Shen & Sun 2025, Figs. 3–5 — (x0, p0) = (-3, 0, 0, 0.45), h = 0.05: energy error, eccentricity
# error and LRL-angle error of the four methods. Usage: gnuplot -c shen-sun-fig345.gp <data-dir> <out>
data_dir = ARG1
out_base = ARG2
load ARG0[1:strstrt(ARG0, "shen-sun-fig345.gp") - 1] . "style.gp"
names = "se sv vi1 vi2"
titles = "'symplectic Euler' 'Störmer–Verlet' 'VI-1' 'VI-2'"
colors = "#e67e22 #c0392b #1b6ca8 #27ae60"
do for [fmt in "svg png"] {
  if (fmt eq "svg") { set terminal svg size 1200,1000 dynamic enhanced font "DejaVu Sans,11"; set output out_base . ".svg" }
  if (fmt eq "png") { set terminal pngcairo size 1200,1000 enhanced font "DejaVu Sans,10"; set output out_base . ".png" }
  set multiplot layout 3,1 title "(x_0, p_0) = (-3, 0, 0, 0.45), h = 0.05"
  set xlabel "t"
  set key outside right font ",9"
  set title "Fig. 3: energy error H - H_0"
  plot for [i=1:4] data_dir . "/" . word(names, i) . ".csv" using 1:4 with lines lw 1 lc rgb word(colors, i) title word(titles, i)
  set title "Fig. 4: eccentricity error |A| - e"
  plot for [i=1:4] data_dir . "/" . word(names, i) . ".csv" using 1:5 with lines lw 1 lc rgb word(colors, i) title word(titles, i)
  set title "Fig. 5: LRL-angle error (rad)"
  plot for [i=1:4] data_dir . "/" . word(names, i) . ".csv" using 1:6 with lines lw 1.5 lc rgb word(colors, i) title word(titles, i)
  unset multiplot
  unset output
}
