#pragma once
// Performance and data profiles as step charts (gnuplot, CSV and script beside the chart), in the
// style of the work-precision charts: hand-written solvers solid, GSL's dashed.

#include <string>
#include <vector>

#include "output/chart.hpp"

namespace numlab::cli {

struct ProfileCurves {
  std::string title;
  std::string x_label;            // "tau (time within tau x the best)" and the like
  std::string note;               // one line under the title: what "solved" means, the budget
  bool log2_axis = false;         // Dolan & Moré draw tau on a log2 axis
  std::vector<std::string> solvers;
  std::vector<double> x;                    // breakpoints, increasing
  std::vector<std::vector<double>> values;  // values[s][i]: solver s's profile at x[i]
};

void draw_profile_chart(const ChartFiles& files, const ProfileCurves& curves);

}  // namespace numlab::cli
