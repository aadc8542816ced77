set encoding utf8
set key box opaque
set grid

set title 'Longitudinal oscillation at a constant normal force: μ̄/μ0 against ξ = v0/(2π f u_x)'
set xlabel 'ξ = β/(2πa)'
set ylabel 'μ̄/μ0'
set key bottom right
set xrange [0:1.5]
set yrange [0:1.05]
plot 'inplane_xi.dat' index 0 using 1:2 with lines lw 2 lc rgb '#d73027' title 'a = 1', 'inplane_xi.dat' index 1 using 1:2 with lines lw 2 lc rgb '#4575b4' title 'a = 10', 'inplane_xi.dat' index 2 using 1:2 with lines lw 2 lc rgb '#1a9850' title 'a = 100', 'inplane_xi.dat' index 3 using 1:2 with lines lw 2 dt 2 lc rgb 'black' title 'rigid: (2/π) arcsin ξ'
