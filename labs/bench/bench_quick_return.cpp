// `numlab bench quick-return` (bench_quick_return.hpp): whitworth.toml's derived model against a
// hand-written Newton on the Whitworth's own two unknowns and against its closed form.

#include "bench/bench_quick_return.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "bench/progress_line.hpp"
#include "bench/timing.hpp"
#include "methods/data_dir.hpp"
#include "numlab/mechanisms/closed_forms/from_description.hpp"
#include "numlab/mechanisms/linkage/linkage_sweep.hpp"
#include "output/exit_codes.hpp"
#include "output/format.hpp"
#include "output/table.hpp"

namespace numlab::cli {

namespace {

namespace cf = mechanisms::closed_forms;

// The cycle: 360 poses, 1 degree apart, from the file's reference angle (no walk-in).
constexpr int cycle_poses = 360;

// The hand-written solver: per pose the Whitworth's two unknowns, the slot's angle phi and the ram's
// x, by Newton from the polynomial through the last five poses (as solve_linkage_cycle predicts the
// file's), stopped at max |f| <= tol:
//  1. A = O2 + r e(t), a = A - O4 (the crank is explicit);
//  2. f1 = e(phi) × a                                  (A on the slot's line)
//     f2 = ((x - B_x)^2 + (h - B_y)^2 - l^2) / (2 l),  B = O4 + R e(phi)   (the rod's length)
//  3. J is lower triangular: J11 = -e(phi) . a, J21 = R ((x - B_x) sin phi - (h - B_y) cos phi) / l,
//     J22 = (x - B_x) / l; dphi = -f1 / J11, dx = -(f2 + J21 dphi) / J22;
//  4. the joints A, B = O4 + R e(phi), C = (x, h) stored, six numbers a pose.
struct HandCycle {
  Eigen::Matrix<double, 6, cycle_poses> joints;
  int iterations = 0;
  bool converged = true;
};

void hand_written_cycle(const cf::Whitworth& m, double start_rad, double tolerance, HandCycle& out) {
  const double step = cf::pi / 180.0;
  // The reference pose from the closed form, as the file's solver starts from its solved reference pose.
  const cf::WhitworthPose first = cf::whitworth(m, start_rad);
  // The last five poses, newest first, and the extrapolation weights of the polynomial through n of them.
  double phi[5], ram[5];
  std::fill(phi, phi + 5, first.slot.angle);
  std::fill(ram, ram + 5, first.C.p.x());
  static constexpr double weights[5][5] = {
      {1, 0, 0, 0, 0}, {2, -1, 0, 0, 0}, {3, -3, 1, 0, 0}, {4, -6, 4, -1, 0}, {5, -10, 10, -5, 1}};
  out.iterations = 0;
  out.converged = true;
  for (int k = 0; k < cycle_poses; ++k) {
    // 1. The crank.
    const double t = start_rad + step * k;
    const Eigen::Vector2d A = m.O2 + m.crank * cf::unit(t), a = A - m.O4;
    // The prediction from the poses so far (the reference pose alone at first).
    const double* w = weights[std::clamp(k, 1, 5) - 1];
    double p = 0.0, x = 0.0;
    for (int j = 0; j < 5; ++j) p += w[j] * phi[j], x += w[j] * ram[j];
    bool done = false;
    for (int iteration = 0; iteration <= 20; ++iteration) {
      // 2. The residuals.
      const double c = std::cos(p), s = std::sin(p);
      const double bx = m.O4.x() + m.slot * c, by = m.O4.y() + m.slot * s;
      const double dx_c = x - bx, dy_c = m.ram_height - by;
      const double f1 = c * a.y() - s * a.x();
      const double f2 = (dx_c * dx_c + dy_c * dy_c - m.rod * m.rod) / (2.0 * m.rod);
      if (std::max(std::abs(f1), std::abs(f2)) <= tolerance) {
        done = true;
        break;
      }
      // 3. The Newton step, by forward substitution.
      const double j11 = -(c * a.x() + s * a.y());
      const double j21 = m.slot * (dx_c * s - dy_c * c) / m.rod, j22 = dx_c / m.rod;
      const double dphi = -f1 / j11;
      p += dphi;
      x += -(f2 + j21 * dphi) / j22;
      ++out.iterations;
    }
    out.converged = out.converged && done;
    // 4. The joints.
    out.joints.col(k) << A, m.O4 + m.slot * cf::unit(p), x, m.ram_height;
    for (int j = 4; j > 0; --j) phi[j] = phi[j - 1], ram[j] = ram[j - 1];
    phi[0] = p, ram[0] = x;
  }
}

double worst_distance(const cf::Whitworth& m, double start_rad, const auto& joints_of_pose) {
  double worst = 0.0;
  for (int k = 0; k < cycle_poses; ++k) {
    const cf::WhitworthPose exact = cf::whitworth(m, start_rad + k * cf::pi / 180.0);
    const Eigen::Matrix<double, 6, 1> got = joints_of_pose(k);
    worst = std::max({worst, (got.segment<2>(0) - exact.A.p).norm(), (got.segment<2>(2) - exact.B.p).norm(),
                      (got.segment<2>(4) - exact.C.p).norm()});
  }
  return worst;
}

double time_of(const std::vector<QuickReturnBenchRow>& rows, const std::string& solver) {
  for (const auto& row : rows) {
    if (row.solver == solver) return row.time_s;
  }
  return std::nan("");
}

}  // namespace

std::vector<QuickReturnBenchRow> bench_quick_return(double tolerance, bool quick) {
  const mechanisms::LinkageModel model(mechanisms::read_linkage_description(models_dir() + "/whitworth.toml"));
  const cf::Whitworth m = cf::whitworth_of(model.description());
  const double start = model.description().driver.reference, start_rad = start * cf::pi / 180.0;
  const double size = std::max({m.crank, m.slot, m.rod});  // the file's tolerance is relative to its longest link
  const TimingPlan plan = quick ? TimingPlan{3, 10, 0.0} : TimingPlan{7, 1000, 0.3};
  const int a = model.description().joint_index("A"), b = model.description().joint_index("B"),
            c = model.description().joint_index("C");
  std::vector<QuickReturnBenchRow> rows;
  for (const std::string solver : {"full", "sequential", "analytic"}) {
    show_progress("bench quick-return: whitworth.toml, " + solver);
    mechanisms::LinkageSolverOptions options{solver, "gepp", {}};
    options.newton.residual_tolerance = tolerance;
    options.newton.max_iterations = 100;
    const mechanisms::LinkageSolver linkage(model, options);
    const auto cycle = [&] { return mechanisms::solve_linkage_cycle(linkage, start, start + cycle_poses - 1.0, 1.0); };
    const mechanisms::LinkageCycle solved = cycle();
    double error = std::numeric_limits<double>::infinity();
    if (solved.status == Status::converged) {
      error = worst_distance(m, start_rad, [&](int k) {
        const auto joints = model.positions(solved.q.col(k));
        Eigen::Matrix<double, 6, 1> got;
        got << joints[static_cast<std::size_t>(a)], joints[static_cast<std::size_t>(b)], joints[static_cast<std::size_t>(c)];
        return got;
      });
    }
    rows.push_back({"whitworth.toml, " + solver, median_time(cycle, plan), error, solved.iterations});
  }
  show_progress("bench quick-return: hand-written Newton");
  HandCycle hand;
  const auto hand_cycle = [&] { hand_written_cycle(m, start_rad, tolerance * size, hand); };
  hand_cycle();
  const double hand_error = hand.converged ? worst_distance(m, start_rad, [&](int k) { return Eigen::Matrix<double, 6, 1>(hand.joints.col(k)); })
                                           : std::numeric_limits<double>::infinity();
  const double hand_time = median_time(hand_cycle, plan);
  rows.push_back({"hand-written Newton", hand_time, hand_error, hand.iterations});
  show_progress("bench quick-return: closed form");
  Eigen::Matrix<double, 6, cycle_poses> exact;
  const auto closed_cycle = [&] {
    for (int k = 0; k < cycle_poses; ++k) {
      const cf::WhitworthPose pose = cf::whitworth(m, start_rad + k * cf::pi / 180.0);
      exact.col(k) << pose.A.p, pose.B.p, pose.C.p;
    }
  };
  rows.push_back({"closed form", median_time(closed_cycle, plan), 0.0, 0});
  show_progress("");
  return rows;
}

int run_quick_return_bench(const BenchOptions& common, bool quick) {
  const double tolerance = common.tolerance.value_or(1e-10);
  const std::vector<QuickReturnBenchRow> rows = bench_quick_return(tolerance, quick);
  const double hand = time_of(rows, "hand-written Newton"), file = time_of(rows, "whitworth.toml, analytic");
  const double full = time_of(rows, "whitworth.toml, full");
  if (common.format == Format::json) {
    nlohmann::ordered_json out = {{"benchmark", "quick-return"}, {"poses", cycle_poses}, {"tolerance", tolerance},
                                  {"rows", nlohmann::ordered_json::array()}};
    for (const auto& row : rows) {
      out["rows"].push_back({{"solver", row.solver},
                             {"time_s", row.time_s},
                             {"ratio_to_hand_written", row.time_s / hand},
                             {"error", number_or_null(row.error)},
                             {"iterations", row.iterations}});
    }
    out["file_within_2x"] = file / hand <= 2.0;       // the file's blocks in closed form (--solver analytic)
    out["full_newton_within_2x"] = full / hand <= 2.0;  // Newton on all 6 joint coordinates (--solver full)
    std::cout << out.dump(2) << '\n';
  } else {
    std::cout << fmt::format("The Whitworth quick-return (whitworth.toml), median time per {}-pose crank cycle from its\n"
                             "reference angle, Newton tolerance {:g} x its longest link; error = worst joint distance\n"
                             "from the closed form (numlab/mechanisms/closed_forms/whitworth.hpp). The hand-written Newton\n"
                             "solves the slot's angle and the ram's x (2 unknowns), the file's model 6 joint coordinates.\n\n",
                             cycle_poses, tolerance);
    Table table({"solver", "time per cycle", "per pose", "x hand-written", "iterations", "error"});
    for (const auto& row : rows) {
      table.add_row({row.solver, fmt::format("{:.3g} s", row.time_s), fmt::format("{:.3g} us", row.time_s / cycle_poses * 1e6),
                     fmt::format("{:.2f}", row.time_s / hand), std::to_string(row.iterations), scientific(row.error)});
    }
    table.print(std::cout);
    std::cout << fmt::format("\nTarget (the file within 2x of the hand-written solver):\n"
                             "  whitworth.toml (derived, analytic: its 3 blocks in closed form) vs hand-written Newton:  {:.2f}x   ({})\n"
                             "  whitworth.toml (derived, full: Newton on 6 coordinates) vs hand-written Newton:         {:.2f}x   ({})\n",
                             file / hand, file / hand <= 2.0 ? "met" : "NOT met", full / hand, full / hand <= 2.0 ? "met" : "NOT met");
  }
  bool converged = true;
  for (const auto& row : rows) converged = converged && std::isfinite(row.error);
  return converged ? exit_success : exit_method_failed;
}

}  // namespace numlab::cli
