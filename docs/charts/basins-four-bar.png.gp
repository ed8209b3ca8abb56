set terminal pngcairo size 1060,760 enhanced font 'Helvetica,11'
set output '/work/wt-basins/docs/charts/basins-four-bar.png'
set datafile separator ','
set key outside right top box opaque spacing 1.2 width 1
set xrange [-3.15209965:3.15209965]
set yrange [-3.15209965:3.15209965]
set size ratio -1
set xlabel 'theta3 (coupler, rad)'
set ylabel 'theta4 (rocker, rad)'
set title 'Grashof four-bar at 60 deg: plain Newton from 300 x 300 starts (max 40 iterations)'
set tics out
$marks << EOD
0.459213879,1.31298823
-1.12616022,-1.97993457
EOD
plot 'docs/charts/basins-four-bar.png.data.csv' using 3:4:8:9:10 every ::1 with rgbimage notitle, \
     keyentry with boxes fs solid 1.0 noborder lc rgb '#1f77b4' title 'B+ (left of A->O4) (38.2%)', \
     keyentry with boxes fs solid 1.0 noborder lc rgb '#ff7f0e' title 'B- (right of A->O4) (38.1%)', \
     keyentry with boxes fs solid 1.0 noborder lc rgb '#ff00ff' title 'singular (0.3%)', \
     keyentry with boxes fs solid 1.0 noborder lc rgb '#6e6e6e' title 'max iterations (23.4%)', \
     keyentry with boxes fs solid 1.0 noborder lc rgb '#bcd6e9' title 'lighter: more iterations', \
     x with lines lw 2 dt 2 lc rgb 'black' title 'toggle: theta3 - theta4 = k pi (J singular)', \
     x + pi with lines lw 2 dt 2 lc rgb 'black' notitle, x - pi with lines lw 2 dt 2 lc rgb 'black' notitle, \
     $marks every ::0::0 using 1:2 with points pt 7 ps 1.7 lc rgb 'white' notitle, \
     $marks every ::0::0 using 1:2 with points pt 6 ps 1.7 lw 2 lc rgb 'black' title 'closed form, B+', \
     $marks every ::1::1 using 1:2 with points pt 9 ps 1.7 lc rgb 'white' notitle, \
     $marks every ::1::1 using 1:2 with points pt 8 ps 1.7 lw 2 lc rgb 'black' title 'closed form, B-'
