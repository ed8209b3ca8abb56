#include "output/driving_chart.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "numlab/mechanisms/linkage/linkage_statics.hpp"

namespace numlab::cli {

std::string driving_chart_problem(const mechanisms::LinkageModel& model, const std::optional<mechanisms::LinkageOutput>& output) {
  if (!model.description().loads.empty() || output) return {};
  return "--chart: " + model.description().name + " has no [[load]] and no output, nothing to chart: add loads or give --output LINK";
}

void draw_driving_chart(const ChartFiles& files, const mechanisms::LinkageModel& model, const mechanisms::LinkageSweep& sweep,
                        const std::optional<mechanisms::LinkageOutput>& output) {
  using namespace mechanisms;
  const LinkageDescription& d = model.description();
  const bool loads = !d.loads.empty(), crank = model.crank_driven();
  const char* load_column = crank ? "driver_torque" : "driver_force";
  // 1. Per pose: the driver's load (statics) and the output's mechanical advantage (link_motion.hpp).
  auto cell = [](double value) { return std::isfinite(value) ? fmt::format("{:.17g}", value) : std::string(); };
  const auto lines = link_lines(d);
  LinkageStaticsSolver statics(model);
  std::vector<std::string> rows;
  std::vector<double> advantages, sizes;  // sizes: |mechanical advantage| where finite
  for (const LinkagePose& pose : sweep.poses) {
    const LinkageStatics& load = statics.solve(pose);
    double advantage = std::nan("");
    if (output && pose.outcome.status == Status::converged) {
      advantage = mechanical_advantage(output_rate(*output, lines, joint_motions(model, pose.q, pose.velocity, pose.acceleration)));
    }
    if (std::isfinite(advantage)) sizes.push_back(std::abs(advantage));
    advantages.push_back(advantage);
    rows.push_back(fmt::format("{:.10g},{},{},{}\n", pose.driver, loads ? cell(load.driver) : std::string(),
                               loads ? std::string(to_string(load.status)) : std::string("no_loads"), cell(advantage)));
  }
  // 2. The advantage's axis: 5 times the median size, when a pole reaches beyond it.
  double clip = 0.0, median = 0.0;
  if (!sizes.empty()) {
    std::nth_element(sizes.begin(), sizes.begin() + static_cast<std::ptrdiff_t>(sizes.size() / 2), sizes.end());
    median = sizes[sizes.size() / 2];
    if (*std::max_element(sizes.begin(), sizes.end()) > 5.0 * median && median > 0.0) clip = 5.0 * median;
  }
  // A pole between two poses (the advantage beyond its median size on both sides, of opposite signs:
  // the output's velocity ratio crossed zero) breaks the curve: a blank line, which gnuplot does not join.
  std::string csv = fmt::format("driver,{},statics,mechanical_advantage\n", load_column);
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const double a = k > 0 ? advantages[k - 1] : std::nan(""), b = advantages[k];
    if (median > 0.0 && a * b < 0.0 && std::min(std::abs(a), std::abs(b)) > median) csv += '\n';
    csv += rows[k];
  }
  // 3. The script: one panel per quantity, the driver along x (a quote in the title doubled, as
  // gnuplot's single-quoted strings want; the texts not enhanced, so that '_' stays a '_').
  std::string title;
  for (const char c : d.title.empty() ? d.name : d.title) title += c == '\'' ? std::string("''") : std::string(1, c);
  const std::string x_label = crank ? "crank angle (deg)" : "slider travel (length unit)";
  const std::string load_label = crank ? "driving torque (N x length unit, CCW +)" : "driving force (N, along the line)";
  std::string panels;
  if (loads) {
    panels += fmt::format("set ylabel '{}' noenhanced\nplot '{}' using 1:2 skip 1 with lines lw 2 lc rgb '#c0392b' title '{}'\n",
                          load_label, files.data, crank ? "driver torque" : "driver force");
  }
  if (output) {
    panels += fmt::format("set ylabel 'mechanical advantage of {}' noenhanced\n{}plot '{}' using 1:4 skip 1 with lines lw 2 lc rgb '#2471a3' "
                          "title 'mechanical advantage (output/input){}'\n",
                          output->name, clip > 0.0 ? fmt::format("set yrange [{:.6g}:{:.6g}]\n", -clip, clip) : std::string(),
                          files.data, clip > 0.0 ? fmt::format(", axis clipped at +-{:.3g}", clip) : std::string());
  }
  const std::string what = loads && output ? "driving torque and mechanical advantage"
                           : loads         ? "driving torque (no output named: no mechanical advantage)"
                                           : "mechanical advantage only (no [[load]] in the file: no driving torque)";
  std::string script = "# The driving torque (statics under the file's [[load]]s) and the output's mechanical advantage\n"
                       "# against the driver (numlab mechanism --chart). Empty cells: singular poses, toggles, poses\n"
                       "# that did not assemble.\n";
  script += gnuplot_output_lines(files, 900, loads && output ? 800 : 500);
  script += fmt::format("set datafile separator ','\nset datafile missing ''\nset grid\nset key top right box opaque\n"
                        "set xlabel '{}'\n{}{}{}",
                        x_label, loads && output ? fmt::format("set multiplot layout 2,1 title '{}: {}' noenhanced\n", title, what)
                                                 : fmt::format("set title '{}: {}' noenhanced\n", title, what),
                        panels, loads && output ? "unset multiplot\n" : "");
  draw_chart(files, csv, script);
}

}  // namespace numlab::cli
