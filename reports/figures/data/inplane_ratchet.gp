set encoding utf8
set key box opaque
set grid

set title 'The ratchet: mean force ∫s/∫n at β = 0 against the phase P of the longitudinal oscillation (γ = 0.5)'
set xlabel 'P (periods)'
set ylabel '∫s dφ / ∫n dφ at β = 0'
set key bottom right
set xrange [0:1]
plot 'inplane_ratchet.dat' index 0 using 1:2 with linespoints pt 7 ps 0.6 lw 2 lc rgb '#d73027' title 'a = 0.5', 'inplane_ratchet.dat' index 1 using 1:2 with linespoints pt 7 ps 0.6 lw 2 lc rgb '#4575b4' title 'a = 1', 'inplane_ratchet.dat' index 2 using 1:2 with linespoints pt 7 ps 0.6 lw 2 lc rgb '#1a9850' title 'a = 2'
