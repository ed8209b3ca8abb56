#pragma once
// A basin map as a picture: one colour per mode reached, lighter the more iterations it took; flat
// colours of their own for each way of failing; the solution and the seed's estimates marked; the
// four-bar's toggle lines drawn. Drawn by gnuplot (`with rgbimage`) from a CSV beside the chart
// that holds every grid point: i, j, u, v, status, mode, iterations, and the pixel's r, g, b.

#include <string>

#include "basins/basin_run.hpp"
#include "output/chart.hpp"

namespace numlab::basins {

// The CSV of every point (header i,j,u,v,status,mode,iterations,r,g,b): mode is the mode number,
// -1 for a root of no known mode, -2 when the start did not converge.
std::string basin_csv(const BasinRun& run);

// Writes the chart, its CSV and its gnuplot script (draw_chart).
void draw_basin_chart(const cli::ChartFiles& files, const BasinRun& run, const std::string& title);

// The legend's name of a status ("max iterations" for max_iterations).
std::string failure_name(Status status);

}  // namespace numlab::basins
