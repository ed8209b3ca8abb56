#include "output/fit_charts.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "numlab/fitting/polynomial_fit.hpp"

namespace numlab::cli {

namespace {

// The polynomial as a gnuplot expression in Horner form, undefined outside [low, high].
std::string gnuplot_polynomial(const Eigen::VectorXd& c, double low, double high) {
  std::string horner = fmt::format("{:.17g}", c(c.size() - 1));
  for (Eigen::Index k = c.size() - 2; k >= 0; --k) horner = fmt::format("({:.17g} + x*{})", c(k), horner);
  return fmt::format("(x >= {:.17g} && x <= {:.17g} ? {} : 1/0)", low, high, horner);
}

const std::vector<std::string>& line_colours() {
  static const std::vector<std::string> colours = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b"};
  return colours;
}

}  // namespace

void draw_fit_chart(const ChartFiles& files, const std::string& title, const std::vector<FitSeries>& series) {
  std::string csv = "series,x,y,fitted\n";
  std::string plots;
  for (std::size_t s = 0; s < series.size(); ++s) {
    const FitSeries& one = series[s];
    const bool has_fit = one.coefficients.size() > 0;
    for (Eigen::Index i = 0; i < one.x.size(); ++i) {
      const double fitted = has_fit ? fitting::evaluate_polynomial(one.coefficients, one.x(i)) : std::nan("");
      csv += fmt::format("{},{:.17g},{:.17g},{:.17g}\n", one.label, one.x(i), one.y(i), fitted);
    }
    const std::string colour = line_colours()[s % line_colours().size()];
    plots += fmt::format("{}'{}' using 2:(strcol(1) eq '{}' ? $3 : 1/0) skip 1 with points pt 7 ps 0.5 lc rgb '{}' "
                         "title '{} (data)'",
                         plots.empty() ? "" : ", ", files.data, one.label, colour, one.label);
    if (has_fit) {
      plots += fmt::format(", {} with lines lw 2 lc rgb '{}' title '{} (degree-{} fit)'",
                           gnuplot_polynomial(one.coefficients, one.x.minCoeff(), one.x.maxCoeff()), colour, one.label,
                           one.coefficients.size() - 1);
    }
  }
  std::string script = "# Data points and their least-squares polynomials (numlab fit).\n";
  script += gnuplot_output_lines(files);
  script += fmt::format("set datafile separator ','\nset grid\nset key outside below\nset samples 1000\n"
                        "set xlabel 'x'\nset ylabel 'y'\nset title '{}'\nplot {}\n",
                        title, plots);
  draw_chart(files, csv, script);
}

void draw_degree_sweep_chart(const ChartFiles& files, const std::string& title, const std::vector<fitting::DegreeSweepRow>& rows) {
  std::vector<std::string> methods;
  std::vector<int> degrees;
  for (const auto& row : rows) {
    if (std::find(methods.begin(), methods.end(), row.method) == methods.end()) methods.push_back(row.method);
    if (std::find(degrees.begin(), degrees.end(), row.degree) == degrees.end()) degrees.push_back(row.degree);
  }
  // Wide CSV: degree, then digits and residual sd per method; an empty cell where a method gave no fit.
  std::string csv = "degree";
  for (const auto& method : methods) csv += fmt::format(",digits {0},residual_sd {0}", method);
  csv += '\n';
  for (int degree : degrees) {
    csv += std::to_string(degree);
    for (const auto& method : methods) {
      const auto row = std::find_if(rows.begin(), rows.end(),
                                    [&](const fitting::DegreeSweepRow& r) { return r.method == method && r.degree == degree; });
      const bool has_fit = row != rows.end() && std::isfinite(row->residual_sd);
      csv += has_fit ? fmt::format(",{:.4g},{:.6g}", row->digits, row->residual_sd) : ",,";
    }
    csv += '\n';
  }
  std::string digits_plot, residual_plot;
  for (std::size_t m = 0; m < methods.size(); ++m) {
    const std::string style = fmt::format(" with linespoints lw 2 pt {} lc rgb '{}' title '{}'", 5 + 2 * static_cast<int>(m),
                                          line_colours()[m % line_colours().size()], methods[m]);
    if (m > 0) {
      digits_plot += ", ";
      residual_plot += ", ";
    }
    digits_plot += fmt::format("'{}' using 1:{} skip 1", files.data, 2 + 2 * m) + style;
    residual_plot += fmt::format("'{}' using 1:{} skip 1", files.data, 3 + 2 * m) + style;
  }
  std::string script = "# Digits and residual against the polynomial degree, one line per method (numlab lab fit).\n"
                       "# A gap means the method gave no coefficients at that degree (e.g. GEPP found V^T V singular).\n";
  script += gnuplot_output_lines(files);
  script += fmt::format(
      "set datafile separator ','\nset datafile missing ''\nset grid\nset multiplot layout 1,2 title '{}'\n"
      "set xlabel 'degree'\nset ylabel 'correct digits (weighted coefficients vs long-double reference)'\n"
      "set yrange [0:16]\nset key bottom left box opaque\nplot {}\n"
      "set ylabel 'residual standard deviation'\nset autoscale y\nset logscale y\nset format y '10^{{%T}}'\n"
      "set key top right box opaque\nplot {}\nunset multiplot\n",
      title, digits_plot, residual_plot);
  draw_chart(files, csv, script);
}

}  // namespace numlab::cli
