# Shared style of vibook's figures. Loaded by every figures/<id>.gp.
set datafile separator ","
set key autotitle columnhead
set border lw 1.2
set grid lc rgb "#dddddd" lw 1
set tics nomirror
set style line 1 lc rgb "#1b6ca8" lw 2          # numerical / modified solution
set style line 2 lc rgb "#666666" lw 1.5 dt 2   # exact solution, dashed
set style line 3 lc rgb "#c0392b" pt 7 ps 0.6   # discrete points
set style line 4 lc rgb "#111111" lw 2.5        # second modified solution (dark)
set style line 5 lc rgb "#27ae60" lw 1 dt 3
# A figure script sets data_dir and out_base from its arguments *before* loading this file
# (gnuplot's `load` clears ARG1..ARG9), then writes out_base.svg (book) and out_base.png.
