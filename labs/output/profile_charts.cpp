#include "output/profile_charts.hpp"

#include <fmt/format.h>

#include <stdexcept>

namespace numlab::cli {

void draw_profile_chart(const ChartFiles& files, const ProfileCurves& curves) {
  if (curves.x.empty()) throw std::invalid_argument("a profile needs at least one point: no solver solved any case");
  std::string csv = "x";
  for (const std::string& solver : curves.solvers) csv += "," + solver;
  csv += '\n';
  // A row of zeros at the left edge when the first breakpoint lies right of it, and the last
  // values again at the right edge, so that every step is drawn whole.
  const double left = curves.log2_axis ? 1.0 : curves.x.front() / 1.5;
  const double right = curves.x.back() * 2.0;
  auto add_row = [&](double x, auto value_at) {
    csv += fmt::format("{:.6g}", x);
    for (std::size_t s = 0; s < curves.values.size(); ++s) csv += fmt::format(",{:.6g}", value_at(s));
    csv += '\n';
  };
  if (left < curves.x.front()) add_row(left, [](std::size_t) { return 0.0; });
  for (std::size_t i = 0; i < curves.x.size(); ++i) add_row(curves.x[i], [&](std::size_t s) { return curves.values[s].at(i); });
  add_row(right, [&](std::size_t s) { return curves.values[s].back(); });
  // Hand-written solvers solid, GSL's dashed; each its own colour (gnuplot's own cycle, offset for
  // GSL so that the two families do not repeat each other's colours) and a small vertical lift so
  // that solvers with identical profiles stay visible side by side.
  std::string plots;
  int hand_written = 0;
  for (std::size_t s = 0; s < curves.solvers.size(); ++s) {
    const bool gsl = curves.solvers[s].starts_with("gsl-");
    const int colour = gsl ? 9 + static_cast<int>(s) - hand_written : ++hand_written;
    const double lift = 0.004 * static_cast<double>(s);
    plots += fmt::format("{}'{}' using 1:(${} + {:.3f}) skip 1 with steps lw 2 dt {} lc {} title '{}'", s ? ", " : "",
                         files.data, s + 2, lift, gsl ? 2 : 1, colour, curves.solvers[s]);
  }
  std::string script = fmt::format("# {} (numlab bench robustness). Redraw: gnuplot {}\n", curves.title, files.script);
  script += "# Each line is lifted by 0.004 per solver so that equal profiles stay visible.\n";
  script += gnuplot_output_lines(files, 1100, 650);
  script += "set datafile separator ','\nset grid\nset key outside right box opaque\n";
  script += curves.log2_axis ? "set logscale x 2\n" : "set logscale x 10\n";
  script += fmt::format("set xrange [{:.6g}:{:.6g}]\nset yrange [0:1.08]\n", left, right);
  script += fmt::format("set title \"{}\\n{{/*0.8 {}}}\"\nset xlabel '{}'\nset ylabel 'fraction of cases'\n", curves.title,
                        curves.note, curves.x_label);
  script += "plot " + plots + "\n";
  draw_chart(files, csv, script);
}

}  // namespace numlab::cli
