set encoding utf8
set key box opaque
set grid

set title 'Transverse oscillation at a constant normal force: μ̄/μ0 against ξ = v0/(2π f u_y)'
set xlabel 'ξ = β/(2πa)'
set ylabel 'μ̄/μ0'
set key bottom right
set xrange [0:1.5]
set yrange [0:1.05]
plot 'inplane_xi_transverse.dat' index 0 using 1:2 with linespoints pt 7 ps 0.5 lw 2 lc rgb '#d73027' title 'a = 1', 'inplane_xi_transverse.dat' index 1 using 1:2 with linespoints pt 7 ps 0.5 lw 2 lc rgb '#4575b4' title 'a = 3', 'inplane_xi_transverse.dat' index 2 using 1:2 with linespoints pt 7 ps 0.5 lw 2 lc rgb '#1a9850' title 'a = 10', 'inplane_xi_transverse.dat' index 3 using 1:2 with lines lw 2 dt 2 lc rgb 'black' title 'rigid: (2/π) ξ/√(1+ξ²) K(1/√(1+ξ²))'
