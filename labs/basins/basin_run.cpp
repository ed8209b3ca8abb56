#include "basins/basin_run.hpp"

#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "basins/basin_systems.hpp"
#include "numlab/mechanisms/jansen_closure.hpp"

namespace numlab::basins {

namespace {

constexpr double pi = std::numbers::pi;
// The four-bar's fixed crank angle: 60 degrees.
constexpr double four_bar_crank = pi / 3;

template <typename Work>
double seconds_of(Work&& work) {
  const auto begin = std::chrono::steady_clock::now();
  work();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
}

nonlinear::BasinSlice slice_of(const BasinRequest& request, int axis_u, int axis_v, double u0, double u1, double v0,
                               double v1) {
  nonlinear::BasinSlice slice;
  slice.axis_u = axis_u;
  slice.axis_v = axis_v;
  slice.u_min = request.u_min.value_or(u0);
  slice.u_max = request.u_max.value_or(u1);
  slice.v_min = request.v_min.value_or(v0);
  slice.v_max = request.v_max.value_or(v1);
  slice.columns = request.columns;
  slice.rows = request.rows;
  return slice;
}

nonlinear::NewtonOptions options_of(const BasinRequest& request, int default_iterations) {
  nonlinear::NewtonOptions options;
  options.damped = request.damped;
  options.max_iterations = request.max_iterations.value_or(default_iterations);
  return options;
}

int axis_index(const std::string& name, const std::string& fallback) {
  const std::string& wanted = name.empty() ? fallback : name;
  const auto& names = jansen_axis_names();
  for (std::size_t k = 0; k < names.size(); ++k) {
    if (names[k] == wanted) return static_cast<int>(k);
  }
  throw std::invalid_argument("unknown jansen axis '" + wanted + "' (known: theta1 ... theta8)");
}

void run_fractal(const BasinRequest& request, BasinRun& run) {
  const CubeRoots system;
  const auto slice = slice_of(request, 0, 1, -2.0, 2.0, -2.0, 2.0);
  const auto options = options_of(request, 40);
  run.u_name = "Re z";
  run.v_name = "Im z";
  run.mode_labels = {"z = 1", "z = e^{2 pi i/3}", "z = e^{-2 pi i/3}"};
  run.max_iterations = options.max_iterations;
  run.marks = {{1.0, 0.0, "root 1"}};
  const auto classify = [](const Vector<2>& z) { return CubeRoots::mode_of(z); };
  run.seconds = seconds_of([&] { run.map = nonlinear::basin_map(system, Vector<2>(0.0, 0.0), slice, options, classify, request.threads); });
}

void run_four_bar(const BasinRequest& request, BasinRun& run) {
  const FourBar system(four_bar_crank);
  const auto slice = slice_of(request, 0, 1, -pi, pi, -pi, pi);
  const auto options = options_of(request, 40);
  run.u_name = "theta3 (coupler, rad)";
  run.v_name = "theta4 (rocker, rad)";
  run.mode_labels = {"B+ (left of A->O4)", "B- (right of A->O4)"};
  run.max_iterations = options.max_iterations;
  run.toggle_lines = true;
  for (int mode = 0; mode < 2; ++mode) {
    const Vector<2> exact = system.closed_form(mode);
    run.marks.push_back({exact(0), exact(1), "closed form, " + run.mode_labels[mode].substr(0, 2)});
  }
  const auto classify = [&system](const Vector<2>& theta) { return system.mode_of(theta); };
  run.seconds = seconds_of([&] { run.map = nonlinear::basin_map(system, system.closed_form(0), slice, options, classify, request.threads); });
}

void run_jansen(const BasinRequest& request, BasinRun& run) {
  using Closure = mechanisms::JansenClosureOf<mechanisms::TableSines>;  // the crank sweep's closure
  const double crank = mechanisms::JansenClosure::seed_crank_angle;
  const Closure system(crank);
  const JansenModes modes(crank);
  const Vector<8> estimates = mechanisms::JansenClosure::seed_estimates();
  Vector<8> solution;
  if (!modes.closed_form_angles(JansenModes::seed_mode(), estimates, solution)) {
    throw std::logic_error("the Jansen leg's seed branch does not close");
  }
  const int u = axis_index(request.axis_u, "theta1"), v = axis_index(request.axis_v, "theta7");
  if (u == v) throw std::invalid_argument("the two jansen axes must differ, got " + jansen_axis_names()[u] + " twice");
  const auto slice = slice_of(request, u, v, solution(u) - pi, solution(u) + pi, solution(v) - pi, solution(v) + pi);
  const auto options = options_of(request, 20);
  run.u_name = jansen_axis_names()[u] + " (rad)";
  run.v_name = jansen_axis_names()[v] + " (rad)";
  for (int mode = 0; mode < JansenModes::count; ++mode) run.mode_labels.push_back(JansenModes::label(mode));
  run.home_mode = JansenModes::seed_mode();
  run.max_iterations = options.max_iterations;
  run.marks = {{solution(u), solution(v), "solution (seed's branch)"}, {estimates(u), estimates(v), "seed 000's estimates"}};
  const auto classify = [&modes](const Vector<8>& theta) { return modes.mode_of(theta); };
  run.seconds = seconds_of([&] { run.map = nonlinear::basin_map(system, solution, slice, options, classify, request.threads); });
}

}  // namespace

const std::vector<std::string>& basin_system_names() {
  static const std::vector<std::string> names = {"fractal", "four-bar", "jansen"};
  return names;
}

const std::vector<std::string>& jansen_axis_names() {
  static const std::vector<std::string> names = {"theta1", "theta2", "theta3", "theta4",
                                                 "theta5", "theta6", "theta7", "theta8"};
  return names;
}

BasinRun run_basins(const BasinRequest& request) {
  const auto side = [](int n, const char* what) {
    if (n < 2 || n > max_grid_side) {
      throw std::invalid_argument(std::string("grid ") + what + " must be 2 to " + std::to_string(max_grid_side) +
                                  ", got " + std::to_string(n));
    }
  };
  side(request.columns, "columns");
  side(request.rows, "rows");
  if (request.threads < 1 || request.threads > max_threads) {
    throw std::invalid_argument("threads must be 1 to " + std::to_string(max_threads) + ", got " +
                                std::to_string(request.threads));
  }
  if (request.system != "jansen" && (!request.axis_u.empty() || !request.axis_v.empty())) {
    throw std::invalid_argument("axes can be chosen only for jansen (fractal and four-bar have two unknowns)");
  }
  BasinRun run;
  run.system = request.system;
  if (request.system == "fractal") run_fractal(request, run);
  else if (request.system == "four-bar") run_four_bar(request, run);
  else if (request.system == "jansen") run_jansen(request, run);
  else throw std::invalid_argument("unknown system '" + request.system + "' (known: fractal, four-bar, jansen)");
  return run;
}

BasinTally tally(const nonlinear::BasinMap& map, int modes) {
  BasinTally counts;
  counts.per_mode.assign(static_cast<std::size_t>(modes), 0);
  for (const auto& point : map.points) {
    ++counts.total;
    switch (point.status) {
      case Status::converged:
        if (point.mode >= 0 && point.mode < modes) ++counts.per_mode[static_cast<std::size_t>(point.mode)];
        else ++counts.unknown;
        break;
      case Status::diverged: ++counts.diverged; break;
      case Status::singular: ++counts.singular; break;
      case Status::max_iterations: ++counts.max_iterations; break;
      case Status::non_finite: ++counts.non_finite; break;
      default: ++counts.no_progress; break;
    }
  }
  return counts;
}

namespace {
template <typename Pick>
double nearest_where(const nonlinear::BasinMap& map, double u, double v, Pick pick) {
  double best = std::numeric_limits<double>::infinity();
  for (int j = 0; j < map.slice.rows; ++j) {
    for (int i = 0; i < map.slice.columns; ++i) {
      if (pick(map.at(i, j))) best = std::min(best, std::hypot(map.slice.u(i) - u, map.slice.v(j) - v));
    }
  }
  return best;
}
}  // namespace

double distance_to_other_mode(const nonlinear::BasinMap& map, double u, double v, int mode) {
  return nearest_where(map, u, v, [mode](const nonlinear::BasinPoint& p) {
    return p.status == Status::converged && p.mode != mode;
  });
}

double distance_to_failure(const nonlinear::BasinMap& map, double u, double v) {
  return nearest_where(map, u, v, [](const nonlinear::BasinPoint& p) { return p.status != Status::converged; });
}

}  // namespace numlab::basins
