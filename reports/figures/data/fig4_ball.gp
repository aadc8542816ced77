set encoding utf8
set key box opaque
set grid

set multiplot layout 1,2 title 'Harmonic wave, 11 values of γ: flat punch (left, Fig. 4) and sphere (right, MDR)'
set xlabel 'β = k_x v_0 / (μ_0 k_z A f)'
set ylabel 'μ̄ / μ_0'
set xrange [0:7]
set yrange [0:1.02]
set key right bottom font ',11' spacing 0.9
set title 'flat-ended cylinder'
plot 'fig4_harmonic.dat' index 0 using 1:2 with lines lw 2 lc rgb '#67001f' title 'γ = 1', \
     '' index 1 using 1:2 with lines lw 2 lc rgb '#b2182b' title 'γ = 0.8', \
     '' index 2 using 1:2 with lines lw 2 lc rgb '#d6604d' title 'γ = 0.6', \
     '' index 3 using 1:2 with lines lw 2 lc rgb '#f4a582' title 'γ = 0.4', \
     '' index 4 using 1:2 with lines lw 2 lc rgb '#fddbc7' title 'γ = 0.2', \
     '' index 5 using 1:2 with lines lw 2 lc rgb '#999999' title 'γ = 0', \
     '' index 6 using 1:2 with lines lw 2 lc rgb '#d1e5f0' title 'γ = -0.2', \
     '' index 7 using 1:2 with lines lw 2 lc rgb '#92c5de' title 'γ = -0.4', \
     '' index 8 using 1:2 with lines lw 2 lc rgb '#4393c3' title 'γ = -0.6', \
     '' index 9 using 1:2 with lines lw 2 lc rgb '#2166ac' title 'γ = -0.8', \
     '' index 10 using 1:2 with lines lw 2 lc rgb '#053061' title 'γ = -0.999'
set title 'sphere (σ = x²)'
plot 'fig4_ball.dat' index 0 using 1:2 with lines lw 2 lc rgb '#67001f' title 'γ = 1', \
     '' index 1 using 1:2 with lines lw 2 lc rgb '#b2182b' title 'γ = 0.8', \
     '' index 2 using 1:2 with lines lw 2 lc rgb '#d6604d' title 'γ = 0.6', \
     '' index 3 using 1:2 with lines lw 2 lc rgb '#f4a582' title 'γ = 0.4', \
     '' index 4 using 1:2 with lines lw 2 lc rgb '#fddbc7' title 'γ = 0.2', \
     '' index 5 using 1:2 with lines lw 2 lc rgb '#999999' title 'γ = 0', \
     '' index 6 using 1:2 with lines lw 2 lc rgb '#d1e5f0' title 'γ = -0.2', \
     '' index 7 using 1:2 with lines lw 2 lc rgb '#92c5de' title 'γ = -0.4', \
     '' index 8 using 1:2 with lines lw 2 lc rgb '#4393c3' title 'γ = -0.6', \
     '' index 9 using 1:2 with lines lw 2 lc rgb '#2166ac' title 'γ = -0.8', \
     '' index 10 using 1:2 with lines lw 2 lc rgb '#053061' title 'γ = -0.999'
unset multiplot
