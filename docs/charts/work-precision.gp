# Work-precision diagram (numlab bench): median time per run against the worst joint error
# vs the closed form, one line per solver over Newton tolerances 1e-2..1e-13.
set terminal svg size 1100,650 dynamic enhanced font 'Helvetica,13' background rgb 'white'
set output '/work/main/labs/charts/work-precision.svg'
set datafile separator ','
set logscale xy
set grid
set key outside right box opaque
set offsets graph 0.04, graph 0.04, graph 0.04, graph 0.04
set xlabel 'worst joint error vs the closed form (length units)'
set ylabel 'median time per run (s)'
set format x '10^{%T}'
set format y '10^{%T}'
set title 'Jansen leg, 360-pose cycle (lower left is better)'
plot 'labs/charts/work-precision.csv' using (strcol(1) eq 'analytic' ? $4 : 1/0):3 skip 1 with points pt 7 ps 2.5 lc rgb 'black' title 'closed form', 'labs/charts/work-precision.csv' using (strcol(1) eq 'full' ? $4 : 1/0):3 skip 1 with linespoints lw 2 pt 5 ps 1.2 dt 1 lc rgb '#d62728' title 'full', 'labs/charts/work-precision.csv' using (strcol(1) eq 'full-eigen-lu' ? $4 : 1/0):3 skip 1 with linespoints lw 2 pt 6 ps 1.2 dt 1 lc rgb '#2ca02c' title 'full-eigen-lu', 'labs/charts/work-precision.csv' using (strcol(1) eq 'full-gauss-seidel' ? $4 : 1/0):3 skip 1 with linespoints lw 2 pt 7 ps 1.2 dt 1 lc rgb '#9467bd' title 'full-gauss-seidel', 'labs/charts/work-precision.csv' using (strcol(1) eq 'full-gsl-lu' ? $4 : 1/0):3 skip 1 with linespoints lw 2 pt 8 ps 1.2 dt 1 lc rgb '#ff7f0e' title 'full-gsl-lu', 'labs/charts/work-precision.csv' using (strcol(1) eq 'gsl-broyden' ? $4 : 1/0):3 skip 1 with linespoints lw 2 pt 9 ps 1.2 dt 2 lc rgb '#8c564b' title 'gsl-broyden', 'labs/charts/work-precision.csv' using (strcol(1) eq 'gsl-dnewton' ? $4 : 1/0):3 skip 1 with linespoints lw 2 pt 10 ps 1.2 dt 2 lc rgb '#e377c2' title 'gsl-dnewton', 'labs/charts/work-precision.csv' using (strcol(1) eq 'gsl-gnewton' ? $4 : 1/0):3 skip 1 with linespoints lw 2 pt 11 ps 1.2 dt 2 lc rgb '#7f7f7f' title 'gsl-gnewton', 'labs/charts/work-precision.csv' using (strcol(1) eq 'gsl-hybrid' ? $4 : 1/0):3 skip 1 with linespoints lw 2 pt 12 ps 1.2 dt 2 lc rgb '#bcbd22' title 'gsl-hybrid', 'labs/charts/work-precision.csv' using (strcol(1) eq 'gsl-hybridj' ? $4 : 1/0):3 skip 1 with linespoints lw 2 pt 13 ps 1.2 dt 2 lc rgb '#17becf' title 'gsl-hybridj', 'labs/charts/work-precision.csv' using (strcol(1) eq 'gsl-hybrids' ? $4 : 1/0):3 skip 1 with linespoints lw 2 pt 4 ps 1.2 dt 2 lc rgb '#000080' title 'gsl-hybrids', 'labs/charts/work-precision.csv' using (strcol(1) eq 'gsl-hybridsj' ? $4 : 1/0):3 skip 1 with linespoints lw 2 pt 5 ps 1.2 dt 2 lc rgb '#808000' title 'gsl-hybridsj', 'labs/charts/work-precision.csv' using (strcol(1) eq 'gsl-newton' ? $4 : 1/0):3 skip 1 with linespoints lw 2 pt 6 ps 1.2 dt 2 lc rgb '#800000' title 'gsl-newton', 'labs/charts/work-precision.csv' using (strcol(1) eq 'sequential' ? $4 : 1/0):3 skip 1 with linespoints lw 2 pt 7 ps 1.2 dt 1 lc rgb '#008080' title 'sequential'
