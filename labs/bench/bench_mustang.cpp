#include "bench/bench_mustang.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <cmath>
#include <iostream>
#include <limits>
#include <nlohmann/json.hpp>

#include "numlab/mechanisms/mustang_sweep.hpp"
#include "numlab/nonlinear/gsl_multiroot.hpp"
#include "output/table.hpp"
#include "bench/timing.hpp"

namespace numlab::cli {

namespace {

constexpr double sweep_start = -41.0, sweep_stop = 56.0, sweep_step = 0.5;

struct Choice {
  std::string label, solver, linear;
};

std::vector<Choice> choices(bool quick) {
  std::vector<Choice> all = {{"full", "full", "gepp"},          {"full-gsl-lu", "full", "gsl-lu"},
                             {"full-eigen-lu", "full", "eigen-lu"}, {"full-gauss-seidel", "full", "gauss-seidel"},
                             {"sequential", "sequential", "gepp"}, {"analytic", "analytic", "gepp"}};
  for (const std::string& type : nonlinear::gsl_multiroot_types()) {
    if (!quick || type == "newton") all.push_back({"gsl-" + type, "gsl-" + type, "gepp"});
  }
  return all;
}

double time_of(const std::vector<MustangBenchRow>& rows, const std::string& solver) {
  for (const auto& row : rows) {
    if (row.solver == solver) return row.time_s;
  }
  return std::nan("");
}

}  // namespace

std::vector<MustangBenchRow> bench_mustang(double tolerance, bool quick) {
  nonlinear::NewtonOptions options;
  options.residual_tolerance = tolerance;
  options.max_iterations = 100;
  const TimingPlan plan = quick ? TimingPlan{3, 10, 0.0} : TimingPlan{7, 1000, 0.3};
  mechanisms::MustangSweepOptions timed;
  timed.checks = false;  // the checks are run once, outside the timing
  std::vector<MustangBenchRow> rows;
  for (const Choice& choice : choices(quick)) {
    if (isatty(STDERR_FILENO) != 0) std::cerr << "\r\033[Kbench mustang: " << choice.label << std::flush;
    const auto solver = mechanisms::make_mustang_solver(choice.solver, choice.linear, options);
    // Once with every check (the error), then timed without.
    const auto checked = mechanisms::mustang_sweep(*solver, sweep_start, sweep_stop, sweep_step);
    int iterations = 0;
    for (const auto& pose : checked.poses) iterations += pose.outcome.iterations;
    const double error = checked.status == Status::converged ? checked.worst_closed_form_distance
                                                             : std::numeric_limits<double>::infinity();
    const double seconds =
        median_time([&] { return mechanisms::mustang_sweep(*solver, sweep_start, sweep_stop, sweep_step, timed); }, plan);
    rows.push_back({choice.label, tolerance, seconds, static_cast<int>(checked.poses.size()), error, iterations});
  }
  if (isatty(STDERR_FILENO) != 0) std::cerr << "\r\033[K" << std::flush;
  return rows;
}

void print_mustang_bench(std::ostream& out, const std::vector<MustangBenchRow>& rows) {
  const double full = time_of(rows, "full");
  out << fmt::format("Median time per sweep {:g}:{:g}:{:g} deg ({} poses, from the seed's start at 45 deg), Newton "
                     "tolerance {:g};\nratio = time / full Newton's (below 1 is faster); error = worst joint distance "
                     "from the closed form.\n\n",
                     sweep_start, sweep_stop, sweep_step, rows.empty() ? 0 : rows.front().poses,
                     rows.empty() ? 0.0 : rows.front().tolerance);
  Table table({"solver", "time per sweep", "per pose", "x full", "iterations", "error"});
  for (const auto& row : rows) {
    table.add_row({row.solver, fmt::format("{:.3g} s", row.time_s),
                   fmt::format("{:.3g} us", row.time_s / std::max(row.poses, 1) * 1e6),
                   fmt::format("{:.2f}", row.time_s / full), std::to_string(row.iterations), scientific(row.error)});
  }
  table.print(out);
}

int run_mustang_bench(const BenchOptions& common, bool quick) {
  const auto rows = bench_mustang(common.tolerance.value_or(1e-10), quick);
  if (common.format == Format::json) {
    nlohmann::ordered_json out = {{"benchmark", "mustang"}, {"rows", nlohmann::ordered_json::array()}};
    for (const auto& row : rows) {
      out["rows"].push_back({{"solver", row.solver},
                             {"tolerance", row.tolerance},
                             {"time_s", row.time_s},
                             {"ratio_to_full", row.time_s / time_of(rows, "full")},
                             {"poses", row.poses},
                             {"error", number_or_null(row.error)},
                             {"iterations", row.iterations}});
    }
    std::cout << out.dump(2) << '\n';
  } else {
    print_mustang_bench(std::cout, rows);
  }
  return exit_success;
}

}  // namespace numlab::cli
