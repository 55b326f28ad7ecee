# Shen & Sun 2025, Fig. 6 — errors of the LRL vector after one period against h = T/n ≈ 2^-i,
# for §5's two initial conditions and one off the orbit's axis (the paper gives none). Usage: gnuplot -c shen-sun-fig6.gp <data-dir> <out>
# Layout: the paper's two columns, (a) eccentricity error and (b) angle error; one row per
# initial condition, named on its left; one legend for the figure; the paper's step sizes
# h = 2^-6 ... 2^-1 shaded, the smaller steps ours.
data_dir = ARG1
out_base = ARG2
load ARG0[1:strstrt(ARG0, "shen-sun-fig6.gp") - 1] . "style.gp"
ics = "perihelion_e0.6 x0_-3_p0_0.45 e0.6_at_T_5"
ictitles = "'e = 0.6, from perihelion' '(x_0, p_0) = (-3, 0, 0, 0.45)' 'e = 0.6, T/5 after perihelion'"
titles = "'symplectic Euler' 'Störmer–Verlet' 'VI-1' 'VI-2'"
colors = "#e67e22 #c0392b #1b6ca8 #27ae60"
points = "7 5 9 13"
do for [fmt in "svg png"] {
  if (fmt eq "svg") { set terminal svg size 1000,1900 dynamic enhanced font "DejaVu Sans,18"; set output out_base . ".svg" }
  if (fmt eq "png") { set terminal pngcairo size 1200,2100 enhanced font "DejaVu Sans,12"; set output out_base . ".png" }
  set multiplot
  set logscale xy
  set xrange [6e-4:0.7]
  set format x "10^{%T}"
  set format y "10^{%T}"
  set mytics 10
  set object 1 rect from 2**-6, graph 0 to 2**-1, graph 1 behind fc rgb "#eeeeee" fs solid noborder
  # rows from the top: legend band 0.92..1, then three rows of height 0.305
  do for [j=1:3] {
    f = data_dir . "/" . word(ics, j) . ".csv"
    top = 0.92 - (j - 1) * 0.305
    do for [col=1:2] {
      set lmargin at screen (col == 1 ? 0.12 : 0.60)
      set rmargin at screen (col == 1 ? 0.47 : 0.95)
      set tmargin at screen top - 0.03
      set bmargin at screen top - 0.26
      set title (j == 1 ? (col == 1 ? "(a) eccentricity error" : "(b) angle error") : "")
      set xlabel (j == 3 ? "h" : "")
      set ylabel (col == 1 ? word(ictitles, j) : "") offset 1,0
      if (j == 1 && col == 1) {
        set key at screen 0.5, screen 0.985 center top vertical maxrows 3 width 3 samplen 2.5
      } else {
        unset key
      }
      if (col == 1) {
        plot for [i=1:4] f using 1:(column(1 + i) > 0 ? column(1 + i) : 1/0) with linespoints pt int(word(points, i)) ps 0.8 lw 1.8 lc rgb word(colors, i) title word(titles, i), \
             0.1 * x**2 with lines dt 2 lw 1.5 lc rgb "#777777" title "slope 2", \
             0.1 * x**4 with lines dt 3 lw 1.8 lc rgb "#333333" title "slope 4"
      } else {
        plot for [i=1:4] f using 1:(column(5 + i) > 0 ? column(5 + i) : 1/0) with linespoints pt int(word(points, i)) ps 0.8 lw 1.8 lc rgb word(colors, i) notitle, \
             0.1 * x**2 with lines dt 2 lw 1.5 lc rgb "#777777" notitle
      }
    }
  }
  unset multiplot
  unset output
}
