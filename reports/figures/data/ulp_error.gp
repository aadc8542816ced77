set encoding utf8
set key box opaque
set grid

set title 'Error of the fixed-precision paths of vibrofric mu (sine), against 40-digit mpfr'
set xlabel 'β'
set ylabel 'error in ulp of the type (floored at 10^{−3})'
set logscale xy
set format y '10^{%L}'
set format x '10^{%L}'
# The key sits below the plot, clear of every point (inside, it hid the largest errors at small β); the y range
# is the data's plus 4 % of the plot height either way, so that neither the largest errors nor the floored ones lie
# on the border.
set key at screen 0.5, screen 0.01 center bottom vertical maxrows 3
set bmargin 7.5
set autoscale y noextend
set offsets 0, 0, graph 0.04, graph 0.04
plot 'ulp_error.dat' index 0 using 1:2 with linespoints pt 7 ps 0.4 lw 1 lc rgb '#d62728' dt 1 title 'raw double, γ = 0.5', \
     '' index 1 using 1:2 with linespoints pt 7 ps 0.4 lw 1 lc rgb '#1f77b4' dt 1 title 'guaranteed double, γ = 0.5', \
     '' index 2 using 1:2 with linespoints pt 7 ps 0.4 lw 1 lc rgb '#2ca02c' dt 1 title 'raw long double, γ = 0.5', \
     '' index 3 using 1:2 with linespoints pt 7 ps 0.4 lw 1 lc rgb '#d62728' dt 2 title 'raw double, γ = -0.9', \
     '' index 4 using 1:2 with linespoints pt 7 ps 0.4 lw 1 lc rgb '#1f77b4' dt 2 title 'guaranteed double, γ = -0.9', \
     '' index 5 using 1:2 with linespoints pt 7 ps 0.4 lw 1 lc rgb '#2ca02c' dt 2 title 'raw long double, γ = -0.9'
