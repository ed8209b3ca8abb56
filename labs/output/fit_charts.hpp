#pragma once
// Charts of polynomial fits: data points with their fitted curves (seed 001 Figure 3), and the
// degree sweep (digits and residual against the degree, one line per method).

#include <Eigen/Core>
#include <string>
#include <vector>

#include "output/chart.hpp"
#include "numlab/fitting/degree_sweep.hpp"

namespace numlab::cli {

struct FitSeries {
  std::string label;
  Eigen::VectorXd x, y;          // the data
  Eigen::VectorXd coefficients;  // the fit, increasing powers; empty draws no curve
};

// Points and curves; the CSV holds series, x, y and the fitted value at each point.
void draw_fit_chart(const ChartFiles& files, const std::string& title, const std::vector<FitSeries>& series);

// Two panels: digits against degree, and residual standard deviation against degree.
void draw_degree_sweep_chart(const ChartFiles& files, const std::string& title, const std::vector<fitting::DegreeSweepRow>& rows);

}  // namespace numlab::cli
