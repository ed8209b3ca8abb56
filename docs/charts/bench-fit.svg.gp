# Digits and residual against the polynomial degree, one line per method (numlab lab fit).
# A gap means the method gave no coefficients at that degree (e.g. GEPP found V^T V singular).
set terminal svg size 900,600 dynamic enhanced font 'Helvetica,13' background rgb 'white'
set output '/work/main/docs/charts/bench-fit.svg'
set datafile separator ','
set datafile missing ''
set grid
set multiplot layout 1,2 title 'NIST Wampler4: digits and residual against degree'
set xlabel 'degree'
set ylabel 'correct digits (weighted coefficients vs long-double reference)'
set yrange [0:16]
set key bottom left box opaque
plot 'docs/charts/bench-fit.svg.data.csv' using 1:2 skip 1 with linespoints lw 2 pt 5 lc rgb '#1f77b4' title 'normal', 'docs/charts/bench-fit.svg.data.csv' using 1:4 skip 1 with linespoints lw 2 pt 7 lc rgb '#d62728' title 'normal-scaled', 'docs/charts/bench-fit.svg.data.csv' using 1:6 skip 1 with linespoints lw 2 pt 9 lc rgb '#2ca02c' title 'gsl', 'docs/charts/bench-fit.svg.data.csv' using 1:8 skip 1 with linespoints lw 2 pt 11 lc rgb '#9467bd' title 'eigen-qr'
set ylabel 'residual standard deviation'
set autoscale y
set logscale y
set format y '10^{%T}'
set key top right box opaque
plot 'docs/charts/bench-fit.svg.data.csv' using 1:3 skip 1 with linespoints lw 2 pt 5 lc rgb '#1f77b4' title 'normal', 'docs/charts/bench-fit.svg.data.csv' using 1:5 skip 1 with linespoints lw 2 pt 7 lc rgb '#d62728' title 'normal-scaled', 'docs/charts/bench-fit.svg.data.csv' using 1:7 skip 1 with linespoints lw 2 pt 9 lc rgb '#2ca02c' title 'gsl', 'docs/charts/bench-fit.svg.data.csv' using 1:9 skip 1 with linespoints lw 2 pt 11 lc rgb '#9467bd' title 'eigen-qr'
unset multiplot
