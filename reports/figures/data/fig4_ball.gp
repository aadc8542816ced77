set encoding utf8
set key box opaque
set grid

set multiplot layout 1,2 title 'Harmonic wave, 11 values of γ: flat punch (left, Fig. 4) and sphere (right, MDR)'
set xlabel 'β = G^* v_0 / (μ_0 E^* A f)   (on the punch k_x/k_z = G^*/E^*)'
set ylabel 'μ̄ / μ_0'
set xrange [0:7]
set yrange [0:1.02]
set key right bottom font ',11' spacing 0.9
set title 'flat-ended cylinder'
plot 'fig4_harmonic.dat' index 0 using 1:2 with lines lw 2 lc rgb '#77000c' dt 1 title 'γ = 1', \
     '' index 1 using 1:2 with lines lw 2 lc rgb '#8b002e' dt 1 title 'γ = 0.8', \
     '' index 2 using 1:2 with lines lw 2 lc rgb '#991950' dt 1 title 'γ = 0.6', \
     '' index 3 using 1:2 with lines lw 2 lc rgb '#a13473' dt 1 title 'γ = 0.4', \
     '' index 4 using 1:2 with lines lw 2 lc rgb '#a24e94' dt 1 title 'γ = 0.2', \
     '' index 5 using 1:2 with lines lw 2 lc rgb '#9e67b3' dt (12,5,2,5) title 'γ = 0', \
     '' index 6 using 1:2 with lines lw 2 lc rgb '#805ba8' dt (10,6) title 'γ = -0.2', \
     '' index 7 using 1:2 with lines lw 2 lc rgb '#62509c' dt (10,6) title 'γ = -0.4', \
     '' index 8 using 1:2 with lines lw 2 lc rgb '#42458f' dt (10,6) title 'γ = -0.6', \
     '' index 9 using 1:2 with lines lw 2 lc rgb '#183b81' dt (10,6) title 'γ = -0.8', \
     '' index 10 using 1:2 with lines lw 2 lc rgb '#003072' dt (10,6) title 'γ = -0.999'
set title 'sphere (σ = x²)'
plot 'fig4_ball.dat' index 0 using 1:2 with lines lw 2 lc rgb '#77000c' dt 1 title 'γ = 1', \
     '' index 1 using 1:2 with lines lw 2 lc rgb '#8b002e' dt 1 title 'γ = 0.8', \
     '' index 2 using 1:2 with lines lw 2 lc rgb '#991950' dt 1 title 'γ = 0.6', \
     '' index 3 using 1:2 with lines lw 2 lc rgb '#a13473' dt 1 title 'γ = 0.4', \
     '' index 4 using 1:2 with lines lw 2 lc rgb '#a24e94' dt 1 title 'γ = 0.2', \
     '' index 5 using 1:2 with lines lw 2 lc rgb '#9e67b3' dt (12,5,2,5) title 'γ = 0', \
     '' index 6 using 1:2 with lines lw 2 lc rgb '#805ba8' dt (10,6) title 'γ = -0.2', \
     '' index 7 using 1:2 with lines lw 2 lc rgb '#62509c' dt (10,6) title 'γ = -0.4', \
     '' index 8 using 1:2 with lines lw 2 lc rgb '#42458f' dt (10,6) title 'γ = -0.6', \
     '' index 9 using 1:2 with lines lw 2 lc rgb '#183b81' dt (10,6) title 'γ = -0.8', \
     '' index 10 using 1:2 with lines lw 2 lc rgb '#003072' dt (10,6) title 'γ = -0.999'
unset multiplot
