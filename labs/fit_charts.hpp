#pragma once
// Charts of polynomial fits: data points with their fitted curves (seed 001 Figure 3), and the
// degree sweep (digits and residual against the degree, one line per method).

#include <Eigen/Core>
#include <string>
#include <vector>

#include "chart.hpp"

namespace numlab::cli {

struct FitSeries {
  std::string label;
  Eigen::VectorXd x, y;          // the data
  Eigen::VectorXd coefficients;  // the fit, increasing powers; empty draws no curve
};

// Points and curves; the CSV holds series, x, y and the fitted value at each point.
void draw_fit_chart(const ChartFiles& files, const std::string& title, const std::vector<FitSeries>& series);

struct DegreeSweepRow {
  std::string method;
  int degree;
  double digits;       // min LRE of the coefficients against the reference (0 when there is no fit)
  double residual_sd;  // NaN when there is no fit
};

// Two panels: digits against degree, and residual standard deviation against degree.
void draw_degree_sweep_chart(const ChartFiles& files, const std::string& title, const std::vector<DegreeSweepRow>& rows);

}  // namespace numlab::cli
