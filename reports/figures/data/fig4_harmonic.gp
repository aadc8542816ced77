set encoding utf8
set key box opaque
set grid

set multiplot
set title 'Harmonic wave, 11 values of γ (Fig. 4); markers: Eq. 23 relative to γ_0 = −0.3'
set xlabel 'β = k_x v_0 / (μ_0 k_z A f)'
set ylabel 'μ̄ / μ_0'
set key outside right top
set xrange [0:7]
set yrange [0:1.02]
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
     '' index 10 using 1:2 with lines lw 2 lc rgb '#003072' dt (10,6) title 'γ = -0.999', \
     'fig4_eq23.dat' index 0 using 1:2 with points pt 5 ps 1.3 lc rgb '#62509c' title 'Eq. 23, γ = -0.4', \
     '' index 0 using 1:2 with points pt 4 ps 1.3 lw 1 lc rgb 'black' notitle, \
     'fig4_eq23.dat' index 1 using 1:2 with points pt 7 ps 1.3 lc rgb '#42458f' title 'Eq. 23, γ = -0.6', \
     '' index 1 using 1:2 with points pt 6 ps 1.3 lw 1 lc rgb 'black' notitle, \
     'fig4_eq23.dat' index 2 using 1:2 with points pt 9 ps 1.3 lc rgb '#183b81' title 'Eq. 23, γ = -0.8', \
     '' index 2 using 1:2 with points pt 8 ps 1.3 lw 1 lc rgb 'black' notitle, \
     'fig4_eq23.dat' index 3 using 1:2 with points pt 13 ps 1.3 lc rgb '#003072' title 'Eq. 23, γ = -0.999', \
     '' index 3 using 1:2 with points pt 12 ps 1.3 lw 1 lc rgb 'black' notitle
set origin 0.36, 0.13
set size 0.33, 0.42
set title 'inset: μ̄(β, γ) − μ̄(β, 1), γ = 0.2 … 0.8' font ',12'
set xlabel 'β' font ',12'
set ylabel ''
set xtics 2 font ',11'
set ytics font ',11'
set format y '%.0e'
set xrange [0:7]
set yrange [*:*]
unset key
set object 1 rectangle from graph 0, graph 0 to graph 1, graph 1 behind fillcolor rgb 'white' fillstyle solid noborder
plot 'fig4_close.dat' index 0 using 1:2 with lines lw 2 lc rgb '#8b002e' dt 1 title 'γ = 0.8', \
     '' index 1 using 1:2 with lines lw 2 lc rgb '#991950' dt 1 title 'γ = 0.6', \
     '' index 2 using 1:2 with lines lw 2 lc rgb '#a13473' dt 1 title 'γ = 0.4', \
     '' index 3 using 1:2 with lines lw 2 lc rgb '#a24e94' dt 1 title 'γ = 0.2'
unset multiplot
