set encoding utf8
set key box opaque
set grid

set multiplot layout 2,2 title 'Rig dynamics against its quasi-static limit: log10 |μ̄ − g_w(βκ/(1+κ), γ)| / g_w, β = 1, γ = 0.5, ζ = 0.1 (black: 1 %)'
set view map
set pm3d at b
set contour base
set cntrparam levels discrete -2
unset clabel
set xlabel 'log10 Ω = log10 √(k_x/m)/(2πf)'
set ylabel 'log10 κ = log10 k_s/k_x'
set cbrange [-6:0]
set xrange [-0.5:3]
set yrange [-1:2]
set palette defined (-6 '#1a9850', -2 '#ffffbf', 0 '#d73027')
unset key
set title 'sine'
splot 'rig_map.dat' index 0 using 1:2:3 with pm3d notitle, '' index 0 using 1:2:3 with lines lw 3 lc rgb 'black' nosurface notitle
set title 'triangle'
splot 'rig_map.dat' index 1 using 1:2:3 with pm3d notitle, '' index 1 using 1:2:3 with lines lw 3 lc rgb 'black' nosurface notitle
set title 'square'
splot 'rig_map.dat' index 2 using 1:2:3 with pm3d notitle, '' index 2 using 1:2:3 with lines lw 3 lc rgb 'black' nosurface notitle
set title 'sawtooth-left'
splot 'rig_map.dat' index 3 using 1:2:3 with pm3d notitle, '' index 3 using 1:2:3 with lines lw 3 lc rgb 'black' nosurface notitle

unset multiplot
