# Gauss-Seidel on the normal equations: sweeps to converge against kappa(A) (numlab bench).
set terminal svg size 900,600 dynamic enhanced font 'Helvetica,13' background rgb 'white'
set output '/work/main/docs/charts/bench-seidel.svg'
set datafile separator ','
set logscale xy
set grid
set key top left box opaque
set xlabel 'kappa_2(A)'
set ylabel 'sweeps to tolerance 1e-9'
set title 'Gauss-Seidel on A^T A x = A^T b (n = 8): sweeps grow like kappa^2'
plot 'docs/charts/bench-seidel.svg.data.csv' using 1:2 skip 1 with linespoints lw 2 pt 7 title 'sweeps', 1.02551 * x**2 with lines dt 2 lc rgb 'gray40' title 'kappa^2 guide'
