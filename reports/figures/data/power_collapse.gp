set encoding utf8
set key box opaque
set grid

set multiplot layout 1,2 title 'power:3 — collapse under the self-similar remapping (left), not under Eq. 24 as printed (right)'
set ylabel 'μ̄ / μ_0'
set key right bottom
set yrange [0:1.02]
set xrange [0:12]
set xlabel 'β (1+γ)^{−(p−1)/p}  (self-similar, proved)'
plot 'power_collapse.dat' index 0 using 2:4 with lines lw 2 lc rgb '#1b9e77' title 'γ = 0', \
     '' index 1 using 2:4 with lines lw 2 lc rgb '#d95f02' title 'γ = -0.3', \
     '' index 2 using 2:4 with lines lw 2 lc rgb '#7570b3' title 'γ = -0.6', \
     '' index 3 using 2:4 with lines lw 2 lc rgb '#e7298a' title 'γ = -0.9', \
     '' index 4 using 2:4 with lines lw 2 lc rgb '#66a61e' title 'γ = -0.99'
set xlabel 'β (1+γ)^{−1/p}  (Eq. 24 as printed)'
set xrange [0:30]
plot 'power_collapse.dat' index 0 using 3:4 with lines lw 2 lc rgb '#1b9e77' title 'γ = 0', \
     '' index 1 using 3:4 with lines lw 2 lc rgb '#d95f02' title 'γ = -0.3', \
     '' index 2 using 3:4 with lines lw 2 lc rgb '#7570b3' title 'γ = -0.6', \
     '' index 3 using 3:4 with lines lw 2 lc rgb '#e7298a' title 'γ = -0.9', \
     '' index 4 using 3:4 with lines lw 2 lc rgb '#66a61e' title 'γ = -0.99'
unset multiplot
