set encoding utf8
set key box opaque
set grid

set title 'Sphere with a wear flat against the flat punch, β = 1 (the triangle with γ ≤ 1 is exact at every λ)'
set xlabel 'λ = b² / (R A)   (b: flat radius, R: sphere radius, A: amplitude)'
set ylabel '|μ̄_{wear flat} − μ̄_{flat}| / μ_0'
set logscale xy
set format x '10^{%L}'
set format y '10^{%L}'
set key left bottom
plot 'wearflat.dat' index 0 using 1:2 with linespoints lw 2 pt 7 ps 0.6 lc rgb '#1f77b4' title 'sine, γ = 1.5', \
     '' index 1 using 1:2 with linespoints lw 2 pt 7 ps 0.6 lc rgb '#2ca02c' title 'sine, γ = 0.5', \
     '' index 2 using 1:2 with linespoints lw 2 pt 7 ps 0.6 lc rgb '#9467bd' title 'sine, γ = -0.5', \
     '' index 3 using 1:2 with linespoints lw 2 pt 7 ps 0.6 lc rgb '#d62728' title 'square, γ = 1.5', \
     '' index 4 using 1:2 with linespoints lw 2 pt 7 ps 0.6 lc rgb '#ff7f0e' title 'square, γ = -0.5', \
     '' index 5 using 1:2 with linespoints lw 2 pt 7 ps 0.6 lc rgb '#8c564b' title 'triangle, γ = 1.5', \
     [1:1e4] 0.05/x**2 with lines dt 2 lw 1.5 lc rgb 'black' title '∝ λ^{−2}'
