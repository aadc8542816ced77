set encoding utf8
set key box opaque
set grid

set title 'Cost of one evaluation of μ̄ against working precision (mpfr)'
set xrange [15:1200]
set xlabel 'working precision (decimal digits)'
set ylabel 'CPU time per evaluation (µs)'
set logscale xy
set key left top
plot 'cost_digits.dat' index 0 using 1:2 with linespoints lw 2 pt 7 title 'power:3', \
     '' index 1 using 1:2 with linespoints lw 2 pt 7 title 'sawtooth-left', \
     '' index 2 using 1:2 with linespoints lw 2 pt 7 title 'sawtooth-right', \
     '' index 3 using 1:2 with linespoints lw 2 pt 7 title 'sine', \
     '' index 4 using 1:2 with linespoints lw 2 pt 7 title 'square', \
     '' index 5 using 1:2 with linespoints lw 2 pt 7 title 'triangle', \
     '' index 6 using 1:2 with linespoints lw 2 pt 7 title 'sphere + sine (curved)'
