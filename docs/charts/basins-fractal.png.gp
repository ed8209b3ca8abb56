set terminal pngcairo size 1060,760 enhanced font 'Helvetica,11'
set output '/work/wt-basins/docs/charts/basins-fractal.png'
set datafile separator ','
set key outside right top box opaque spacing 1.2 width 1
set xrange [-2.00668896:2.00668896]
set yrange [-2.00668896:2.00668896]
set size ratio -1
set xlabel 'Re z'
set ylabel 'Im z'
set title 'z^3 - 1: plain Newton from 300 x 300 starts (max 40 iterations)'
set tics out
$marks << EOD
1,0
EOD
plot 'docs/charts/basins-fractal.png.data.csv' using 3:4:8:9:10 every ::1 with rgbimage notitle, \
     keyentry with boxes fs solid 1.0 noborder lc rgb '#1f77b4' title 'z = 1 (35.3%)', \
     keyentry with boxes fs solid 1.0 noborder lc rgb '#ff7f0e' title 'z = e^{2 pi i/3} (32.4%)', \
     keyentry with boxes fs solid 1.0 noborder lc rgb '#2ca02c' title 'z = e^{-2 pi i/3} (32.4%)', \
     keyentry with boxes fs solid 1.0 noborder lc rgb '#6e6e6e' title 'max iterations (4 starts)', \
     keyentry with boxes fs solid 1.0 noborder lc rgb '#bcd6e9' title 'lighter: more iterations', \
     $marks every ::0::0 using 1:2 with points pt 7 ps 1.7 lc rgb 'white' notitle, \
     $marks every ::0::0 using 1:2 with points pt 6 ps 1.7 lw 2 lc rgb 'black' title 'root 1'
