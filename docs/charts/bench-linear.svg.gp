# Median time per solve against n (numlab bench linear). Redraw: gnuplot docs/charts/bench-linear.svg.gp
set terminal svg size 900,600 dynamic enhanced font 'Helvetica,13' background rgb 'white'
set output '/work/main/docs/charts/bench-linear.svg'
set datafile separator ','
set logscale xy
set grid
set key top left box opaque
set title 'Linear solvers: median time per solve (diagonally dominant A)'
set xlabel 'n'
set ylabel 'time per solve (s)'
set format y '10^{%T}'
guide(n) = 1.54228e-10 * n**3
set xrange [1.3333333333333333:1536]
set xtics (2, 8, 64, 256, 512, 1024)
plot 'docs/charts/bench-linear.svg.data.csv' using 1:2 with linespoints lw 2 pt 5 title 'gepp', 'docs/charts/bench-linear.svg.data.csv' using 1:3 with linespoints lw 2 pt 6 title 'gsl-lu', 'docs/charts/bench-linear.svg.data.csv' using 1:4 with linespoints lw 2 pt 7 title 'eigen-lu', 'docs/charts/bench-linear.svg.data.csv' using 1:5 with linespoints lw 2 pt 8 title 'gauss-seidel', 'docs/charts/bench-linear.svg.data.csv' using 1:6 with linespoints lw 2 pt 9 title 'gauss-seidel-plain', [2:1024] guide(x) with lines dt 2 lc rgb 'gray40' title 'n^3 guide'
