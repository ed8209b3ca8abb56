#include "output/profile_charts.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>
#include <vector>

namespace numlab::cli {

namespace {

// Text for gnuplot's enhanced mode: "||f||_inf" keeps its whole subscript ("_{inf}").
std::string gnuplot_text(std::string text) {
  for (std::size_t at = text.find("_inf"); at != std::string::npos; at = text.find("_inf", at + 6)) {
    text.replace(at, 4, "_{inf}");
  }
  return text;
}

}  // namespace

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
  // Hand-written solvers solid, GSL's dashed, each its own colour. Solvers with the same profile
  // draw the same steps: the lines get thinner from the first solver to the last, so that each one
  // drawn over another leaves the other's edges showing.
  static const std::vector<std::string> colours = {"#6a3d9a", "#1b9e77", "#377eb8", "#e6ab02", "#a6761d",
                                                   "#e7298a", "#66a61e", "#000000", "#d95f02", "#7570b3",
                                                   "#e41a1c", "#4daf4a", "#984ea3", "#ff7f00", "#a65628",
                                                   "#f781bf", "#999999", "#17becf"};
  std::string plots;
  const double count = static_cast<double>(curves.solvers.size());
  for (std::size_t s = 0; s < curves.solvers.size(); ++s) {
    const bool gsl = curves.solvers[s].starts_with("gsl-");
    const double width = 1.5 + 3.5 * (count - 1.0 - static_cast<double>(s)) / std::max(count - 1.0, 1.0);
    plots += fmt::format("{}'{}' using 1:{} skip 1 with steps lw {:.2f} dt {} lc rgb '{}' title '{}'", s ? ", " : "",
                         files.data, s + 2, width, gsl ? 2 : 1, colours[s % colours.size()], curves.solvers[s]);
  }
  std::string script = fmt::format("# {} (numlab bench robustness). Redraw: gnuplot {}\n", curves.title, files.script);
  script += "# Lines thin out from the first solver to the last, so that equal profiles stay visible.\n";
  script += gnuplot_output_lines(files, 1100, 650);
  script += "set datafile separator ','\nset grid\nset key outside right box opaque\n";
  script += curves.log2_axis ? "set logscale x 2\n" : "set logscale x 10\n";
  script += fmt::format("set xrange [{:.6g}:{:.6g}]\nset yrange [0:1.08]\n", left, right);
  script += fmt::format("set title \"{}\\n{{/*0.8 {}}}\"\nset xlabel '{}'\nset ylabel 'fraction of cases'\n", curves.title,
                        gnuplot_text(curves.note), gnuplot_text(curves.x_label));
  script += "plot " + plots + "\n";
  draw_chart(files, csv, script);
}

}  // namespace numlab::cli
