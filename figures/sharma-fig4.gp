# Sharma et al. 2022, Fig. 4 — EpAVI and AVI2 at h0 = 0.001 and 0.01, e = 0.7, 10 periods.
# Usage: gnuplot -c sharma-fig4.gp <data-dir> <output-base>
data_dir = ARG1
out_base = ARG2
load ARG0[1:strstrt(ARG0, "sharma-fig4.gp") - 1] . "style.gp"
e1 = data_dir . "/h0_0.001_epavi.csv"
e2 = data_dir . "/h0_0.01_epavi.csv"
a1 = data_dir . "/h0_0.001_avi2.csv"
a2 = data_dir . "/h0_0.01_avi2.csv"
do for [fmt in "svg png"] {
  if (fmt eq "svg") { set terminal svg size 1000,560 dynamic enhanced font "DejaVu Sans,17"; set output out_base . ".svg" }
  if (fmt eq "png") { set terminal pngcairo size 1200,500 enhanced font "DejaVu Sans,10"; set output out_base . ".png" }
  set multiplot layout 1,2 title "Effect of h_0, Kepler e = 0.7"
  set xlabel "t"
  set key below horizontal
  set title "(a) energy error"
  set logscale y
  set format y "10^{%T}"
  plot e1 using 2:(abs($4)) with lines lw 1.5 lc rgb "#1b6ca8" title "EpAVI |E_k - E_1|, h_0 = 0.001", \
       e2 using 2:(abs($4)) with lines lw 1.5 dt 2 lc rgb "#1b6ca8" title "EpAVI, h_0 = 0.01", \
       a1 using 2:(abs($5)) with lines lw 1.2 lc rgb "#27ae60" title "AVI2 |H - H_0|, h_0 = 0.001", \
       a2 using 2:(abs($5)) with lines lw 1.2 dt 2 lc rgb "#27ae60" title "AVI2, h_0 = 0.01"
  unset logscale y
  set format y "%g"
  set title "(b) time step h_k / h_0"
  plot e1 using 2:3 with lines lw 1.5 lc rgb "#1b6ca8" title "EpAVI, h_0 = 0.001", \
       e2 using 2:3 with lines lw 1.5 dt 2 lc rgb "#1b6ca8" title "EpAVI, h_0 = 0.01", \
       a1 using 2:3 with lines lw 1.2 lc rgb "#27ae60" title "AVI2, h_0 = 0.001", \
       a2 using 2:3 with lines lw 1.2 dt 2 lc rgb "#27ae60" title "AVI2, h_0 = 0.01"
  unset multiplot
  unset output
}
