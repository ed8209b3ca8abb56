// Labs `jansen`, `jansen-sequential` and `beest`: the Jansen leg solved, compared, charted and drawn.

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "bench/bench_jansen.hpp"
#include "output/chart.hpp"
#include "output/exit_codes.hpp"
#include "output/files.hpp"
#include "output/format.hpp"
#include "scenes/jansen_scene.hpp"
#include "linkage_page/builtin_page_data.hpp"
#include "linkage_page/linkage_page_html.hpp"
#include "lessons/lab.hpp"
#include "lessons/lab_sentences.hpp"
#include "methods/nonlinear_methods.hpp"
#include "numlab/mechanisms/jansen10_closure.hpp"
#include "numlab/nonlinear/dynamic_adapter.hpp"
#include "numlab/nonlinear/jacobian_check.hpp"
#include "output/trace_printers.hpp"

namespace numlab::cli {

namespace {

using mechanisms::JansenClosure;
using mechanisms::JansenModel;

mechanisms::JansenSweep full_cycle(JansenModel model, const std::string& solver, double tolerance) {
  nonlinear::NewtonOptions options;
  options.residual_tolerance = tolerance;
  options.max_iterations = 100;
  const auto pose_solver = mechanisms::make_jansen_solver(model, solver, "gepp", options);
  return mechanisms::crank_sweep(model, *pose_solver, 0.0, 359.0, 1.0);
}

std::string saved_file(LabSession& session, const std::string& name, const std::string& contents) {
  ensure_directory(session.folder());
  const std::string path = session.folder() + "/" + name;
  write_file_atomically(path, contents);
  return path;
}


// The cycle table of step 3 and what its numbers teach, each sentence made from its rows.
void show_cycle_comparison(LabSession& session, const std::vector<JansenBenchRow>& rows) {
  const auto cost = [&](const std::string& solver, const std::string& name) {
    const auto row = std::find_if(rows.begin(), rows.end(), [&](const JansenBenchRow& r) { return r.solver == solver; });
    if (row == rows.end()) throw std::logic_error("bench_jansen gave no row " + solver);
    return SolverCost{name, row->time_s, row->iterations};
  };
  const SolverCost analytic = cost("analytic", "the closed form");
  // 1. The table: time per cycle and per pose, as a multiple of the closed form's, and the error.
  Table table({"solver", "time per cycle", "per pose", "x closed form", "iterations", "error"});
  double worst = 0.0;
  for (const auto& row : rows) {
    table.add_row({jansen_bench_label(row.solver), fmt::format("{:.3g} s", row.time_s),
                   fmt::format("{:.3g} us", row.time_s / 360 * 1e6), fmt::format("{:.2f}", row.time_s / analytic.time_s),
                   std::to_string(row.iterations), scientific(row.error)});
    worst = std::max(worst, row.error);
  }
  session.show(table, "cycle-comparison");
  // 2. What the ratios teach.
  const SolverCost full = cost("full", "full Newton"), sequential = cost("sequential", "sequential Newton");
  const double std_sin = cost("full-std-sin", "").time_s;
  session.say(fmt::format("Every solver's worst joint error is at most {:.2g}: {}.", worst,
                          worst < 1e-6 ? "all stay on the seed's branch" : "some leave the seed's branch"));
  session.say(block_newton_sentence(sequential, full, 8));
  session.say(same_method_sentence({"full Newton (hand-written GEPP)", full.time_s, full.iterations},
                                   cost("gsl-newton", "GSL's newton on the same f and J")));
  session.say(closed_form_sentence(full, analytic, 360));
  session.say(fmt::format("Full Newton calling std::sin is {} full Newton on the sine table: that is what the table "
                          "saves.", speed_ratio_phrase(std_sin, full.time_s)));
}

// Step 1 of lab jansen: Newton with its trace on seed 000's model at the seed's crank angle, the
// pose checked against the circle-intersection solution.
void solve_at_the_seed_angle(LabSession& session, const mechanisms::JansenLeg& leg) {
  if (!session.begin_step("Seed 000's model at the seed's own angle",
                          "Eight loop-closure equations in theta1 ... theta8 at crank angle theta_i = 1.57 rad, solved by "
                          "Newton (hand-written GEPP inside) from seed 000's Table 3 estimates.")) return;
  const JansenClosure closure(JansenClosure::seed_crank_angle);
  const nonlinear::AsDynamicSystem dynamic(closure);
  NonlinearSettings settings;
  settings.options.residual_tolerance = 1e-10;
  NewtonTracer tracer(&session.out(), nullptr);
  const NonlinearRun run =
      run_nonlinear_method("newton", dynamic, Eigen::VectorXd(JansenClosure::seed_estimates()), settings, &tracer);
  session.out() << "  " << run.termination << "\n\n";
  session.stepper("newton", "Newton on seed 000's eight equations", tracer);
  const auto joints = leg.joints(JansenClosure::seed_crank_angle, JansenClosure::Vector(run.x));
  const auto exact = leg.closed_form_joints(JansenClosure::seed_crank_angle);
  double distance = 0.0;
  for (int j = 0; j < mechanisms::jansen_joint_count; ++j) distance = std::max(distance, (joints[j] - (*exact)[j]).norm());
  const auto& foot = joints[static_cast<std::size_t>(mechanisms::JansenJoint::F)];
  session.say(fmt::format("Foot F = ({:.6f}, {:.6f}). Every joint is within {:.2g} of the circle-intersection "
                          "solution, and every link length holds to {:.2g}.",
                          foot.x(), foot.y(), distance, leg.worst_length_error(joints)));
}

// Step 2: the hand-derived Jacobian against central finite differences at the seed's estimates.
void check_the_jacobian(LabSession& session) {
  if (!session.begin_step("Is the Jacobian right?", "The hand-derived 8x8 Jacobian against central finite differences:")) return;
  const JansenClosure closure(JansenClosure::seed_crank_angle);
  const nonlinear::AsDynamicSystem dynamic(closure);
  const auto check = nonlinear::check_jacobian(dynamic, Eigen::VectorXd(JansenClosure::seed_estimates()));
  session.say(fmt::format("{} (worst entry {}).", check.agrees ? "It agrees" : "It DOES NOT agree",
                          nonlinear::describe_worst_entry(check)));
}

// Step 3: one crank cycle by every solver, timed and checked against the closed form.
void compare_every_solver_over_a_cycle(LabSession& session) {
  if (!session.begin_step("One crank cycle, every solver, against the closed form",
                          "360 poses, 1 degree apart, Newton tolerance 1e-10, each pose warm-started by extrapolating the "
                          "two before it. 'error' is the worst distance of any joint from the circle-intersection "
                          "solution over the cycle; times are medians of repeated runs. Every closure but one takes "
                          "its sines and cosines from a table (std::cos and std::sin at the nodes k/64, then a short "
                          "series); 'full, std::sin' is full Newton on the closure as written, calling the library: the "
                          "difference between it and 'full' is what the table saves.")) return;
  const auto rows = bench_jansen(JansenModel::eight_equations, 1e-10, false);
  show_cycle_comparison(session, rows);
}

// The stance: the flat bottom of the foot path, within 1 length unit of its lowest point; its poses
// and the foot's speeds summed on it and over the rest of the cycle (the swing).
struct Stance {
  int poses = 0;
  double speed_sum = 0.0, swing_speed_sum = 0.0;
};

Stance stance_of(const mechanisms::JansenLeg& leg, const mechanisms::JansenSweep& cycle) {
  const std::size_t F = static_cast<std::size_t>(mechanisms::JansenJoint::F);
  double lowest = 1e300;
  for (const auto& pose : cycle.poses) lowest = std::min(lowest, pose.joints[F].y());
  Stance stance;
  for (const auto& pose : cycle.poses) {
    const double speed = leg.rates(pose.crank_deg * std::numbers::pi / 180.0, JansenClosure::Vector(pose.angles)).foot_speed;
    if (pose.joints[F].y() <= lowest + 1.0) {
      stance.speed_sum += speed;
      ++stance.poses;
    } else {
      stance.swing_speed_sum += speed;
    }
  }
  return stance;
}

// Step 4: the foot's speed from one more solve with the Jacobian, against finite differences.
void show_the_foot_speed(LabSession& session, const mechanisms::JansenLeg& leg, const mechanisms::JansenSweep& cycle) {
  if (!session.begin_step("How fast does the foot move?",
                          "Differentiating the closure f(theta; theta_i) = 0 with respect to the crank angle gives "
                          "J dtheta/dtheta_i = -df/dtheta_i: one more 8x8 solve with the Jacobian already at hand gives "
                          "every angular rate, and the foot velocity follows from F = P1 + l7 u(theta7) + l9 u(theta8 + c). "
                          "Speeds are per radian of crank; the check is a central difference of the closed-form foot.")) return;
  Table speeds({"crank (deg)", "foot speed", "finite difference", "relative difference"});
  double slowest = 1e300, fastest = 0.0, worst_difference = 0.0;
  for (const auto& pose : cycle.poses) {
    const double crank = pose.crank_deg * std::numbers::pi / 180.0, h = 1e-5;
    const auto rates = leg.rates(crank, JansenClosure::Vector(pose.angles));
    const auto ahead = leg.closed_form_joints(crank + h), behind = leg.closed_form_joints(crank - h);
    const std::size_t F = static_cast<std::size_t>(mechanisms::JansenJoint::F);
    const double difference = (((*ahead)[F] - (*behind)[F]) / (2.0 * h)).norm();
    const double relative = std::abs(rates.foot_speed - difference) / difference;
    slowest = std::min(slowest, rates.foot_speed);
    fastest = std::max(fastest, rates.foot_speed);
    worst_difference = std::max(worst_difference, relative);
    if (static_cast<int>(pose.crank_deg) % 45 == 0) {
      speeds.add_row({fmt::format("{:g}", pose.crank_deg), fmt::format("{:.4f}", rates.foot_speed),
                      fmt::format("{:.4f}", difference), scientific(relative)});
    }
  }
  session.show(speeds, "foot-speed");
  const Stance stance = stance_of(leg, cycle);
  const int swing = static_cast<int>(cycle.poses.size()) - stance.poses;
  session.say(fmt::format(
      "Over the cycle the foot's speed ranges from {:.2f} to {:.2f} per radian of crank. On the flat bottom of its "
      "path (within 1 unit of the lowest point: {} of {} poses) its mean speed is {:.1f}; over the rest of the "
      "cycle it is {:.1f}. The rates agree with finite differences to {:.1g} (relative) at every pose.",
      slowest, fastest, stance.poses, cycle.poses.size(), stance.speed_sum / stance.poses, stance.swing_speed_sum / swing,
      worst_difference));
}

// Step 5: the leg drawn at crank angle 0 with its foot path, and the cycle animated.
void show_the_scene(LabSession& session, const mechanisms::JansenSweep& cycle) {
  if (!session.begin_step("The scene", "The leg at crank angle 0 with the whole foot path, and an animation of the cycle "
                                       "(open either in a browser).")) return;
  const std::string still = saved_file(session, "leg.svg", jansen_pose_svg(cycle, 0));
  const std::string animated = saved_file(session, "leg-animated.svg", jansen_animation_svg(cycle, 4.0));
  session.figure(still, "the leg at crank angle 0, with the foot's path over the cycle");
  session.figure(animated, "one crank cycle, animated (4 s per turn)");
  saved_file(session, "leg.html",
             linkage_page_html(jansen_page_data("jansen", JansenModel::eight_equations, cycle,
                                                "lab jansen's cycle: full Newton, tolerance 1e-10, 0:359:1"),
                               jansen_pose_svg(cycle, 0), "the leg at crank angle 0 (the page without scripts)"));
  session.say("leg.html, beside this report, is the cycle to drag: a crank slider scrubs its 360 poses, redrawing "
              "the leg with every joint's velocity, and reads out each pose's numbers (iterations, kappa(J), the "
              "transmission angles).");
}

// Step 1 of lab jansen-sequential: the block lower-triangular Jacobian, in words.
void explain_why_both_find_the_same_pose(LabSession& session) {
  if (!session.begin_step("Why sequential and full Newton find the same pose",
                          "Seed 000 solves the eight equations as four 2x2 systems, in order, and argues that the result must "
                          "differ from the full 8x8 solution because the sequential blocks ignore the derivatives with "
                          "respect to earlier unknowns. That is not so. The Jacobian is block lower-triangular: equations "
                          "1-2 contain only theta1, theta2; 3-4 add theta3, theta4; 5-6 only theta6, theta7; 7-8 add "
                          "theta5, theta8. Solving the blocks in that order solves the whole system exactly; a root of one "
                          "is a root of the other. What differs is only where each method stops iterating.")) return;
}

// Seed 000's Figure 4 drawn from its CSV rows, in the lab's folder.
ChartFiles draw_figure4(LabSession& session, const std::string& csv) {
  ensure_directory(session.folder());
  const ChartFiles files = chart_files(session.folder() + "/figure4.svg");
  std::string script = "# Seed 000's Figure 4, redrawn: RMSE of the foot, sequential vs full, against the tolerance.\n";
  script += gnuplot_output_lines(files);
  script += "set datafile separator ','\nset logscale xy\nset grid\nset key top left box opaque\n"
            "set xlabel 'Newton tolerance on ||f||_{inf}'\nset ylabel 'distance (length units)'\nset format x '10^{%T}'\n"
            "set format y '10^{%T}'\nset title 'Sequential vs full Newton over one crank cycle'\n";
  script += fmt::format("plot '{0}' using 1:2 skip 1 with linespoints lw 2 pt 7 title 'RMSE, foot: sequential vs full', "
                        "'{0}' using 1:3 skip 1 with linespoints lw 2 pt 5 title 'full: worst joint error vs closed form', "
                        "'{0}' using 1:4 skip 1 with linespoints lw 2 pt 9 title 'sequential: worst joint error vs closed form', "
                        "x with lines dt 2 lc rgb 'gray40' title 'y = tolerance'\n",
                        files.data);
  draw_chart(files, csv, script);
  return files;
}

// Step 2: seed 000's Figure 4, the feet of full and sequential Newton apart for each tolerance.
void redraw_figure4(LabSession& session) {
  if (!session.begin_step("Seed 000's Figure 4, done right",
                          "For each Newton tolerance: one cycle by full Newton, one by sequential Newton, and the RMSE of "
                          "the distance between their feet over the 360 poses (seed 000 eq 27). Beside it, each method's "
                          "own worst error against the closed form.")) return;
  Table table({"tolerance", "RMSE full vs sequential", "full: worst error", "sequential: worst error"});
  std::vector<double> rmses, full_errors, sequential_errors;
  std::string csv = "tolerance,rmse_full_vs_sequential,full_error,sequential_error\n";
  for (int exponent = -2; exponent >= -12; --exponent) {
    const double tolerance = std::pow(10.0, exponent);
    const auto full = full_cycle(JansenModel::eight_equations, "full", tolerance);
    const auto sequential = full_cycle(JansenModel::eight_equations, "sequential", tolerance);
    double sum = 0.0;
    for (std::size_t i = 0; i < full.poses.size(); ++i) {
      const std::size_t F = static_cast<std::size_t>(mechanisms::JansenJoint::F);
      sum += (full.poses[i].joints[F] - sequential.poses[i].joints[F]).squaredNorm();
    }
    const double rmse = std::sqrt(sum / static_cast<double>(full.poses.size()));
    table.add_row({scientific(tolerance), scientific(rmse), scientific(full.worst_closed_form_distance),
                   scientific(sequential.worst_closed_form_distance)});
    rmses.push_back(rmse);
    full_errors.push_back(full.worst_closed_form_distance);
    sequential_errors.push_back(sequential.worst_closed_form_distance);
    csv += fmt::format("{:g},{:.6g},{:.6g},{:.6g}\n", tolerance, std::max(rmse, 1e-17),
                       std::max(full.worst_closed_form_distance, 1e-17),
                       std::max(sequential.worst_closed_form_distance, 1e-17));
  }
  session.show(table, "figure4");
  const ChartFiles files = draw_figure4(session, csv);
  session.figure(files.chart, "seed 000's Figure 4 redrawn: foot RMSE, sequential vs full, against the tolerance");
  session.say(fmt::format("Chart: {} (data {}, script {}). As the tolerance falls from 1e-2 to 1e-12, the RMSE {}, "
                          "as seed 000 found; full Newton's own worst error {}, and sequential Newton's {}: both "
                          "converge to the same root, and their difference is where each stops.",
                          files.chart, files.data, files.script, trend_phrase(rmses), trend_phrase(full_errors),
                          trend_phrase(sequential_errors)));
}

// Step 3: the time per cycle of each model and solver, and what the 10-equation model costs.
void show_what_each_costs(LabSession& session) {
  if (!session.begin_step("What each costs, and what over-modelling costs",
                          "The time per cycle at tolerance 1e-10 (medians of repeated runs). Seed 001 models the same leg "
                          "with 10 equations: two more unknowns and a closure pair for the triangle D-E-F, which is rigid "
                          "and so needs none: F follows from D and E by a fixed rotation (seed 000 eq 20).")) return;
  Table costs({"model / solver", "time per cycle", "iterations", "worst error"});
  double full_time[2] = {0.0, 0.0}, full_error[2] = {0.0, 0.0};  // 8 and 10 equations
  for (const JansenModel model : {JansenModel::eight_equations, JansenModel::ten_equations}) {
    const auto rows = bench_jansen(model, 1e-10, true);
    for (const auto& row : rows) {
      if (row.solver != "full" && row.solver != "sequential") continue;
      if (row.solver == "full") {
        full_time[model == JansenModel::eight_equations ? 0 : 1] = row.time_s;
        full_error[model == JansenModel::eight_equations ? 0 : 1] = row.error;
      }
      costs.add_row({fmt::format("{} / {}", model == JansenModel::eight_equations ? "8 equations" : "10 equations",
                                 row.solver),
                     fmt::format("{:.3g} s", row.time_s), std::to_string(row.iterations), scientific(row.error)});
    }
  }
  session.show(costs, "costs");
  session.say(fmt::format(
      "Both models trace the same foot path: full Newton's worst error against the same closed form is {:.3g} "
      "with 8 equations and {:.3g} with 10. The 10-equation model pays for its extra unknowns in every evaluation "
      "and every solve: its full Newton takes {:.1f}x the 8-equation model's time. (Its sequential row also carries the cost of the general machinery it runs on: "
      "blocks derived from the Jacobian's pattern and solved on dynamic-size vectors, where the 8-equation model "
      "has its four dyads written out.) Model no more than the scene needs.",
      full_error[0], full_error[1], full_time[1] / full_time[0]));
}

}  // namespace

int run_jansen_lab(LabSession& session) {
  const mechanisms::JansenLeg leg;
  solve_at_the_seed_angle(session, leg);
  check_the_jacobian(session);
  compare_every_solver_over_a_cycle(session);
  const auto cycle = full_cycle(JansenModel::eight_equations, "full", 1e-10);
  show_the_foot_speed(session, leg, cycle);
  show_the_scene(session, cycle);
  return 0;
}

int run_jansen_sequential_lab(LabSession& session) {
  explain_why_both_find_the_same_pose(session);
  redraw_figure4(session);
  show_what_each_costs(session);
  return 0;
}

int run_beest_lab(LabSession& session) {
  if (!session.begin_step("Four legs from one solved cycle",
                          "Seed 000's beest walks on four legs. It needs no second solve: each pair shares a crank, its "
                          "second leg runs half a turn (180 poses) behind the first, and the hind pair is the front pair "
                          "mirrored. One cycle of 360 poses is solved, then read four times.")) return {};
  const auto cycle = full_cycle(JansenModel::eight_equations, "full", 1e-10);
  const std::string still = saved_file(session, "beest.svg", beest_svg(cycle, 0.0));
  const std::string animated = saved_file(session, "beest-animated.svg", beest_svg(cycle, 4.0));
  int iterations = 0;
  for (const auto& pose : cycle.poses) iterations += pose.outcome.iterations;
  session.say(fmt::format("Solved: {} poses ({} Newton iterations, worst joint error {:.2g}).", cycle.poses.size(),
                          iterations, cycle.worst_closed_form_distance));
  session.figure(still, "the beest at crank angle 0");
  session.figure(animated, "the beest walking, animated (4 s per turn)");
  return 0;
}

}  // namespace numlab::cli
