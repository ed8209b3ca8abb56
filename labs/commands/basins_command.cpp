#include "commands/basins_command.hpp"

#include <fmt/format.h>

#include <charconv>
#include <iostream>
#include <nlohmann/json.hpp>
#include <cmath>
#include <thread>

#include "basins/basin_chart.hpp"
#include "basins/basin_run.hpp"
#include "basins/basin_sentences.hpp"
#include "parsing/argument_parsing.hpp"
#include "numlab/printable_text.hpp"
#include "output/table.hpp"

namespace numlab::cli {

namespace {

int grid_side(std::string_view text, const std::string& whole) {
  int value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  const bool number = !text.empty() && error == std::errc() && end == text.data() + text.size();
  if (!number || value < 2 || value > basins::max_grid_side) {
    throw std::invalid_argument(fmt::format("--grid '{}': each side must be a whole number from 2 to {}",
                                            printable(whole.substr(0, 40)), basins::max_grid_side));
  }
  return value;
}

struct Outcome {
  std::string name;
  int count;
};

std::vector<Outcome> outcomes(const basins::BasinRun& run) {
  const auto counts = basins::tally(run.map, static_cast<int>(run.mode_labels.size()));
  std::vector<Outcome> rows;
  for (std::size_t mode = 0; mode < counts.per_mode.size(); ++mode) {
    if (counts.per_mode[mode] > 0) rows.push_back({"mode " + run.mode_labels[mode], counts.per_mode[mode]});
  }
  const std::vector<Outcome> others = {{"root of no known mode", counts.unknown}, {"diverged", counts.diverged},
                                       {"singular", counts.singular},             {"max_iterations", counts.max_iterations},
                                       {"non_finite", counts.non_finite},         {"no_progress", counts.no_progress}};
  for (const Outcome& other : others) {
    if (other.count > 0) rows.push_back(other);
  }
  return rows;
}

}  // namespace

std::pair<int, int> parse_grid(const std::string& text) {
  const auto cross = text.find('x');
  if (cross == std::string::npos) {
    const int n = grid_side(text, text);
    return {n, n};
  }
  return {grid_side(std::string_view(text).substr(0, cross), text), grid_side(std::string_view(text).substr(cross + 1), text)};
}

std::pair<double, double> parse_slice_range(const std::string& text, const std::string& option) {
  const auto colon = text.find(':');
  const std::string shown = printable(text.substr(0, 40));
  if (colon == std::string::npos) throw std::invalid_argument(option + " '" + shown + "': give it as MIN:MAX");
  double low = 0.0, high = 0.0;
  try {
    low = parse_finite_number(std::string_view(text).substr(0, colon));
    high = parse_finite_number(std::string_view(text).substr(colon + 1));
  } catch (const std::invalid_argument& error) {
    throw std::invalid_argument(option + " '" + shown + "': " + error.what());
  }
  if (!(low < high)) throw std::invalid_argument(option + " '" + shown + "': MIN must be below MAX");
  if (!std::isfinite(high - low)) {
    throw std::invalid_argument(option + " '" + shown + "': the width MAX - MIN overflows the doubles");
  }
  return {low, high};
}

BasinsCommand::BasinsCommand(CLI::App& app) {
  command_ = app.add_subcommand("basins", "Basin map: Newton from a grid of starts, coloured by the mode reached");
  command_->add_option("system", system_, "fractal (z^3 - 1), four-bar or jansen")->required();
  command_->add_option("--grid", grid_, "Grid of starts: N or NxM (columns x rows), each 2 to 1000 (default 400)");
  command_->add_option("--u-range", u_range_, "MIN:MAX of the first unknown (default: the system's own)");
  command_->add_option("--v-range", v_range_, "MIN:MAX of the second unknown (default: the system's own)");
  command_->add_option("--axes", axes_, "jansen: the two angles of the slice, e.g. theta1,theta7 (the default)");
  command_->add_flag("--damped", damped_, "Damped Newton (backtracking on ||f||^2) instead of plain");
  command_->add_option("--threads", threads_, "Worker threads (default: all cores)")
      ->check(CLI::Range(1, basins::max_threads));
  command_->add_option("--chart", chart_, "The picture (.png or .svg); default OUT/basins-SYSTEM.png");
  add_common_options(*command_, common_);
}

int BasinsCommand::run() const {
  const CommonOptions common = checked_common_options(common_, "basins");
  basins::BasinRequest request;
  request.system = system_;
  if (std::find(basins::basin_system_names().begin(), basins::basin_system_names().end(), system_) ==
      basins::basin_system_names().end()) {
    throw std::invalid_argument("unknown system '" + printable(system_.substr(0, 40)) +
                                "' (known: fractal, four-bar, jansen)");
  }
  std::tie(request.columns, request.rows) = parse_grid(grid_);
  if (given(*command_, "--u-range")) {
    const auto [low, high] = parse_slice_range(u_range_, "--u-range");
    request.u_min = low;
    request.u_max = high;
  }
  if (given(*command_, "--v-range")) {
    const auto [low, high] = parse_slice_range(v_range_, "--v-range");
    request.v_min = low;
    request.v_max = high;
  }
  if (given(*command_, "--axes")) {
    require_applies(true, system_ == "jansen", "--axes", "basins jansen");
    const auto comma = axes_.find(',');
    if (comma == std::string::npos) throw std::invalid_argument("--axes: give two angles, e.g. theta1,theta7");
    request.axis_u = axes_.substr(0, comma);
    request.axis_v = axes_.substr(comma + 1);
    for (const std::string& axis : {request.axis_u, request.axis_v}) {
      const auto& names = basins::jansen_axis_names();
      if (std::find(names.begin(), names.end(), axis) == names.end()) {
        throw std::invalid_argument("--axes: unknown angle '" + printable(axis.substr(0, 40)) + "' (theta1 ... theta8)");
      }
    }
    if (request.axis_u == request.axis_v) throw std::invalid_argument("--axes: the two angles must differ");
  }
  request.damped = damped_;
  request.threads = threads_ > 0 ? threads_ : std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  request.max_iterations = common.max_iterations;
  if (request.max_iterations && *request.max_iterations > 32767) {
    throw std::invalid_argument("--max-iter: basin maps count at most 32767 iterations per start");
  }
  const ChartFiles files =
      chart_files(chart_.empty() ? common.out_dir + "/basins-" + system_ + ".png" : output_path(common, chart_));
  check_outputs(planned_files(files, chart_.empty() ? "basins' chart" : "--chart"), {});

  const basins::BasinRun run = basins::run_basins(request);
  const std::string method = request.damped ? "damped Newton" : "plain Newton";
  const std::string title = fmt::format("{}: {} from {} x {} starts (max {} iterations)",
                                        system_ == "fractal" ? "z^3 - 1" : system_ == "four-bar" ? "Grashof four-bar at 60 deg" : "Jansen leg at 1.57 rad",
                                        method, request.columns, request.rows, run.max_iterations);
  basins::draw_basin_chart(files, run, title);
  const int total = static_cast<int>(run.map.points.size());
  const double rate = total / run.seconds;
  const auto rows = outcomes(run);
  if (common.format == Format::json) {
    nlohmann::ordered_json out = {{"system", system_}, {"method", method}, {"columns", request.columns},
                                  {"rows", request.rows}, {"u", run.u_name}, {"v", run.v_name},
                                  {"threads", request.threads}, {"max_iterations", run.max_iterations},
                                  {"time_s", run.seconds}, {"solves_per_second", rate},
                                  {"chart", files.chart}, {"csv", files.data}, {"outcomes", nlohmann::ordered_json::array()}};
    for (const Outcome& row : rows) out["outcomes"].push_back({{"outcome", row.name}, {"count", row.count}});
    std::cout << out.dump(2) << '\n';
  } else if (common.format == Format::csv) {
    std::cout << "outcome,count,share\n";
    for (const Outcome& row : rows) std::cout << fmt::format("{},{},{}\n", row.name, row.count, basins::percent(row.count, total));
  } else {
    std::cout << fmt::format("basins             {} ({}), {} x {} starts over {} and {}\n", system_, method,
                             request.columns, request.rows, run.u_name, run.v_name);
    Table table({"outcome", "starts", "share"});
    for (const Outcome& row : rows) table.add_row({row.name, std::to_string(row.count), basins::percent(row.count, total)});
    table.print(std::cout);
    std::cout << fmt::format("time               {:.3g} s on {} threads ({:.3g} solves per second)\n", run.seconds,
                             request.threads, rate)
              << "chart              " << files.chart << " (every start in " << files.data << ")\n";
  }
  return exit_success;
}

}  // namespace numlab::cli
