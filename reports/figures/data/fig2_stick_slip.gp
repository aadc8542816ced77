set encoding utf8
set key box opaque
set grid

set multiplot layout 1,2 title 'Stick–slip over one period, harmonic wave, β = 2'
set xlabel 'phase φ = f t'
set ylabel 'force / (μ_0 k_z A)'
set xrange [0:1]
set yrange [0:*]
set title 'γ = 1.5 (no jumping)'
plot 'fig2_trace.dat' index 0 using 1:2 with lines lw 2 lc rgb '#1f77b4' title 'μ_0 F_z (normal, n)', \
     '' index 0 using 1:3 with lines lw 2 dt 2 lc rgb '#d62728' title 'F_x (tangential, s)'
set title 'γ = 0 (jumping: no contact while n = 0)'
plot 'fig2_trace.dat' index 1 using 1:2 with lines lw 2 lc rgb '#1f77b4' title 'μ_0 F_z (normal, n)', \
     '' index 1 using 1:3 with lines lw 2 dt 2 lc rgb '#d62728' title 'F_x (tangential, s)'
unset multiplot
