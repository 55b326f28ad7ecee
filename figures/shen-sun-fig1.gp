# Shen & Sun 2025, Fig. 1 — pendulum φ = cos x, symplectic Euler (4.16), (x0, v0, h) = (π/2, 0.5, 0.25):
# the discrete points and the level sets through the initial point of H, of H_mod,1 (4.20) and of
# H_mod,2. Usage: gnuplot -c shen-sun-fig1.gp <data-dir> <out>
data_dir = ARG1
out_base = ARG2
load ARG0[1:strstrt(ARG0, "shen-sun-fig1.gp") - 1] . "style.gp"
do for [fmt in "svg png"] {
  if (fmt eq "svg") { set terminal svg size 820,700 dynamic enhanced font "DejaVu Sans,14"; set output out_base . ".svg" }
  if (fmt eq "png") { set terminal pngcairo size 820,620 enhanced font "DejaVu Sans,10"; set output out_base . ".png" }
  set title "Pendulum φ = cos x, symplectic Euler h = 0.25"
  set xlabel "x"
  set ylabel "p"
  set key below horizontal
  # The level sets as closed lines (written in order around their centre). H_mod,1 and
  # H_mod,2 nearly coincide: H_mod,1 wide and light underneath, H_mod,2 thin and dashed on top.
  set xrange [1:5]
  set yrange [-1.9:1.9]
  plot data_dir . "/level_H.csv" using 1:2 with lines lw 2 lc rgb "#7f8c8d" title "H = H(x_0, p_0)", \
       data_dir . "/level_Hmod1.csv" using 1:2 with lines lw 6 lc rgb "#f0b0a8" title "H_{mod,1} level set", \
       data_dir . "/level_Hmod2.csv" using 1:2 with lines lw 1.8 dt 2 lc rgb "#1e7b34" title "H_{mod,2} level set", \
       data_dir . "/discrete.csv" using 2:3 with points pt 6 ps 0.8 lc rgb "#1b6ca8" title "(x_n, p_n), n ≤ 200"
  unset output
}
