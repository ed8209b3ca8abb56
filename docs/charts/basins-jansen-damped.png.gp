set terminal pngcairo size 1060,760 enhanced font 'Helvetica,11'
set output '/work/wt-basins/docs/charts/basins-jansen-damped.png'
set datafile separator ','
set key outside right top box opaque spacing 1.2 width 1
set xrange [-0.373912525:5.93028678]
set yrange [2.00790772:8.31210703]
set size ratio -1
set xlabel 'theta1 (rad)'
set ylabel 'theta7 (rad)'
set title 'Jansen leg at 1.57 rad: damped Newton from 300 x 300 starts (max 20 iterations)'
set tics out
$marks << EOD
2.77818713,5.16000737
2.62,5.14
EOD
plot 'docs/charts/basins-jansen-damped.png.data.csv' using 3:4:8:9:10 every ::1 with rgbimage notitle, \
     keyentry with boxes fs solid 1.0 noborder lc rgb '#1f77b4' title 'B- C- D- E- (8.9%)', \
     keyentry with boxes fs solid 1.0 noborder lc rgb '#ff7f0e' title 'B+ C- D- E- (4.4%)', \
     keyentry with boxes fs solid 1.0 noborder lc rgb '#2ca02c' title 'B- C- D+ E- (30.6%)', \
     keyentry with boxes fs solid 1.0 noborder lc rgb '#d62728' title 'B+ C- D+ E- (9.8%)', \
     keyentry with boxes fs solid 1.0 noborder lc rgb '#9467bd' title 'B- C- D- E+ (10.3%)', \
     keyentry with boxes fs solid 1.0 noborder lc rgb '#17becf' title 'B+ C- D- E+ (5.2%)', \
     keyentry with boxes fs solid 1.0 noborder lc rgb '#e377c2' title 'B- C- D+ E+ (20.0%)', \
     keyentry with boxes fs solid 1.0 noborder lc rgb '#637939' title 'B+ C- D+ E+ (10.8%)', \
     keyentry with boxes fs solid 1.0 noborder lc rgb '#6e6e6e' title 'max iterations (32 starts)', \
     keyentry with boxes fs solid 1.0 noborder lc rgb '#b8a000' title 'no progress (9 starts)', \
     keyentry with boxes fs solid 1.0 noborder lc rgb '#bcd6e9' title 'lighter: more iterations', \
     $marks every ::0::0 using 1:2 with points pt 7 ps 1.7 lc rgb 'white' notitle, \
     $marks every ::0::0 using 1:2 with points pt 6 ps 1.7 lw 2 lc rgb 'black' title 'solution (seed''s branch)', \
     $marks every ::1::1 using 1:2 with points pt 9 ps 1.7 lc rgb 'white' notitle, \
     $marks every ::1::1 using 1:2 with points pt 8 ps 1.7 lw 2 lc rgb 'black' title 'seed 000''s estimates'
