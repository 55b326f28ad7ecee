# Sharma et al. 2022, Fig. 3 — t(a) over one period, h0 = 0.001, a = k·h0 (t'(0) = 1).
# Usage: gnuplot -c sharma-fig3.gp <data-dir> <output-base>
data_dir = ARG1
out_base = ARG2
load ARG0[1:strstrt(ARG0, "sharma-fig3.gp") - 1] . "style.gp"
do for [fmt in "svg png"] {
  if (fmt eq "svg") { set terminal svg size 1000,540 dynamic enhanced font "DejaVu Sans,17"; set output out_base . ".svg" }
  if (fmt eq "png") { set terminal pngcairo size 1200,500 enhanced font "DejaVu Sans,10"; set output out_base . ".png" }
  set multiplot layout 1,2 title "Time transformation t(a) over one period, h_0 = 0.001 (a = k h_0)"
  set xlabel "a"
  set ylabel "t"
  set key below horizontal
  do for [tag in "e01 e07"] {
    set title (tag eq "e01" ? "(a) e = 0.1" : "(b) e = 0.7")
    plot data_dir . "/" . tag . "_epavi.csv" using 1:2 with lines lw 2 lc rgb "#1b6ca8" title "EpAVI", \
         data_dir . "/" . tag . "_avi1.csv" using 1:2 with lines lw 1.5 dt 2 lc rgb "#c0392b" title "AVI1", \
         data_dir . "/" . tag . "_avi2.csv" using 1:2 with lines lw 1.5 lc rgb "#27ae60" title "AVI2", \
         x with lines lw 1 dt 3 lc rgb "#888888" title "t = a"
  }
  unset multiplot
  unset output
}
