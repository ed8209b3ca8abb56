// Lab `mustang`: seed 003's roof linkage. The seed's method as written and where it fails, then
// the fixed method over the whole assembly range, the limits, the scenes and the solvers compared.

#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "bench/bench_mustang.hpp"
#include "output/exit_codes.hpp"
#include "output/files.hpp"
#include "output/format.hpp"
#include "lessons/lab.hpp"
#include "lessons/lab_sentences.hpp"
#include "scenes/mustang_scene.hpp"
#include "linkage_page/builtin_page_data.hpp"
#include "linkage_page/linkage_page_html.hpp"
#include "numlab/mechanisms/crank_angle.hpp"
#include "numlab/mechanisms/mustang_seed_method.hpp"
#include "numlab/mechanisms/mustang_sweep.hpp"
#include "numlab/nonlinear/dynamic_adapter.hpp"
#include "numlab/nonlinear/jacobian_check.hpp"

namespace numlab::cli {

namespace {

using namespace mechanisms;
using mechanisms::degrees;

std::string write_lab_file(LabSession& session, const std::string& name, const std::string& contents) {
  ensure_directory(session.folder());
  const std::string path = session.folder() + "/" + name;
  write_file_atomically(path, contents);
  return path;
}

// What became of one pose of the seed's method: a root on the seed's branch, a root elsewhere,
// no root although its test passed, or no stop.
std::string verdict(const SeedMethodPose& pose, double theta, const MustangLinkage& linkage) {
  if (pose.status != Status::converged) {
    for (int k = 0; k < 4; ++k) {
      if (pose.loops[static_cast<std::size_t>(k)].status != Status::converged) {
        return fmt::format("loop {} {}", k + 1, to_string(pose.loops[static_cast<std::size_t>(k)].status));
      }
    }
  }
  if (pose.residual_norm > 1e-2) return fmt::format("not a root (||f|| = {:.2g})", pose.residual_norm);
  const MustangClosedForm exact = linkage.closed_form(theta);
  if (exact.status != Status::converged) return "a root, but theta is outside the range";
  const MustangJoints joints = linkage.joints(theta, pose.x);
  double distance = 0.0;
  for (int j = 0; j < mustang_joint_count; ++j) distance = std::max(distance, (joints[j] - exact.joints[j]).norm());
  return distance < 1e-2 ? "on the branch (to the test's 1e-3)" : fmt::format("another branch ({:.2g} away)", distance);
}

// trace, if given, keeps every solve the sweep tried.
MustangSweep fixed_sweep(const std::string& solver, double start, double stop, double step,
                         SweepRecorder<MustangSweepStepper>* trace = nullptr) {
  nonlinear::NewtonOptions options;
  options.residual_tolerance = 1e-12;
  options.max_iterations = 50;
  const auto pose_solver = make_mustang_solver(solver, "gepp", options);
  return mustang_sweep(*pose_solver, start, stop, step, {}, trace);
}

// Step 1: the model's four loops, and its hand-derived Jacobian checked against finite differences.
void show_the_model(LabSession& session, const MustangStart& start) {
  if (!session.begin_step("The model",
                          "Seed 003's four loops, each a 2x2 system: (A, B) closes 1-2-4-3, (C, D) closes 0-2-6-5, "
                          "(E, F) closes 6-7-10-8 given C, (G, H) closes 8-10-11-9 given C and F. The three major links "
                          "are rigid bodies bent by 20 degrees. The model's assumptions are written next to the code "
                          "(mechanisms/mustang_closure.hpp, mustang_linkage.hpp). First, the hand-derived 8x8 Jacobian "
                          "against central finite differences at the seed's start:")) return;
  const MustangClosure closure(45.0 * degrees);
  const auto check = nonlinear::check_jacobian(nonlinear::AsDynamicSystem(closure), Eigen::VectorXd(start.x));
  session.say(fmt::format("{} (worst entry {}). It is block lower-triangular: each loop reads only the loops before it.",
                          check.agrees ? "It agrees" : "It DOES NOT agree", nonlinear::describe_worst_entry(check)));
}

// Step 2: the seed's method run as written on the seed's own grid, and where it stops.
void show_the_seed_method_as_written(LabSession& session, const MustangLinkage& linkage) {
  if (!session.begin_step("Seed 003's method as written",
                          "At every theta each loop restarts from [pi/18, pi/2]; Newton stops when |f_i + f_j| <= 0.001; "
                          "loop 3's second Jacobian row has both signs flipped and loop 4's dJ/dH reads D for H; |2 6| is "
                          "rounded to 4.698. The seed's loop has no iteration limit (its program hung); here it stops after "
                          "500 iterations. The seed's own grid: theta from pi/6 to pi/3 in steps of 0.05 rad.")) return;
  Table seed_table({"theta (deg)", "loop 1", "loop 2", "loop 3", "loop 4", "|f_i + f_j| (loop 4)", "||f||_inf", "verdict"});
  const SeedMethodOptions as_written;
  std::vector<LoopOutcome> loop3;  // how loop 3 ended at each theta
  for (double theta = std::numbers::pi / 6.0; theta <= std::numbers::pi / 3.0 + 1e-12; theta += 0.05) {
    const SeedMethodPose pose = seed_method_pose(theta, as_written);
    std::vector<std::string> row = {fmt::format("{:.2f}", theta / degrees)};
    for (const SeedLoopRun& run : pose.loops) {
      row.push_back(run.status == Status::converged ? fmt::format("{} its", run.iterations) : std::string(to_string(run.status)));
    }
    row.push_back(scientific(pose.loops[3].test_value));
    row.push_back(scientific(pose.residual_norm));
    row.push_back(verdict(pose, theta, linkage));
    seed_table.add_row(row);
    const SeedLoopRun& third = pose.loops[2];
    loop3.push_back({theta / degrees, third.status == Status::converged, third.iterations, third.residual_norm});
  }
  session.show(seed_table, "seed-method");
  session.say(loop_stops_sentence(3, loop3, as_written.max_iterations) +
              " With one Jacobian row negated, its step is J^-1 diag(1, -1) f instead of J^-1 f: not a Newton "
              "step. Where it runs out, its E and F are wherever the last step left them, so loop 4 solves for a "
              "linkage that does not close. Where a loop does stop, |f_i + f_j| can be small while f_i = -f_j is "
              "not: the test passes away from a root.");
}

// Step 3: the seed's errors fixed one after another, each variant counted over the assembly range.
void show_each_error_in_turn(LabSession& session, const MustangLinkage& linkage, const MustangStart& start) {
  if (!session.begin_step("Each error in turn",
                          "The same method over theta = -41 ... 56 deg (1 deg apart, inside the assembly range found "
                          "below), fixing one error after another. 'on branch' counts poses within 1e-2 of the closed "
                          "form on the seed's branch.")) return;
  struct Variant {
    const char* name;
    SeedMethodOptions options;
  };
  const Variant variants[] = {
      {"as written", {true, true, true, true, 1e-3, 500}},
      {"+ correct Jacobian", {true, true, false, true, 1e-3, 500}},
      {"+ max |f_i| test", {true, false, false, true, 1e-3, 500}},
      {"+ exact 4.698", {true, false, false, false, 1e-3, 500}},
      {"+ continuation (fixed)", {false, false, false, false, 1e-12, 50}},
  };
  Table variant_table({"method", "no stop / singular", "stopped, not a root", "root, other branch", "on branch"});
  for (const Variant& variant : variants) {
    int failed = 0, not_root = 0, other = 0, on_branch = 0;
    // Continuation marches out from the seed's start both ways; the others restart at every theta.
    for (const int direction : {+1, -1}) {
      MustangAngles x = start.x;
      for (double deg = direction > 0 ? 45.0 : 44.0; deg >= -41.0 && deg <= 56.0; deg += direction) {
        const SeedMethodPose pose = seed_method_pose(deg * degrees, variant.options, x);
        const std::string what = verdict(pose, deg * degrees, linkage);
        if (pose.status != Status::converged) ++failed;
        else if (what.starts_with("not a root")) ++not_root;
        else if (what.starts_with("another")) ++other;
        else ++on_branch;
        if (pose.status == Status::converged) x = pose.x;
      }
    }
    variant_table.add_row({variant.name, std::to_string(failed), std::to_string(not_root), std::to_string(other),
                           std::to_string(on_branch)});
  }
  session.show(variant_table, "seed-errors");
  session.say("Restarting from one fixed guess is what confines the seed to 30-60 degrees: far from the guess Newton "
              "reaches the other assembly of a loop (or none), and loop 4 is near its collinear kite around 43 "
              "degrees, where its Jacobian is singular. Continuation from the last pose keeps the branch.");
}

// Step 4: the fixed method (continuation) over the whole range with full and sequential Newton;
// full_trace keeps every solve of the full sweep. Returns the full sweep, whose verdict is the lab's.
MustangSweep show_the_fixed_method_over_the_range(LabSession& session, SweepRecorder<MustangSweepStepper>& full_trace) {
  if (!session.begin_step("The fixed method over the whole range",
                          "Continuation from the seed's start at 45 deg (every loop from [pi/18, pi/2], damped), a predictor "
                          "from the last two poses, and step halving that becomes a bisection on theta near a limit. "
                          "Sweep -90:90:0.5 with full and sequential Newton:")) return {};
  const MustangSweep full = fixed_sweep("full", -90.0, 90.0, 0.5, &full_trace);
  const MustangSweep sequential = fixed_sweep("sequential", -90.0, 90.0, 0.5);
  double agreement = 0.0;
  for (std::size_t i = 0; i < std::min(full.poses.size(), sequential.poses.size()); ++i) {
    agreement = std::max(agreement, (full.poses[i].angles - sequential.poses[i].angles).lpNorm<Eigen::Infinity>());
  }
  Table range({"solver", "poses", "lower limit (deg)", "loop", "upper limit (deg)", "loop", "closed-form distance", "lengths", "rigid bodies"});
  for (const auto* sweep : {&full, &sequential}) {
    range.add_row({sweep == &full ? "full" : "sequential", std::to_string(sweep->poses.size()),
                   fmt::format("{:.4f}", sweep->lower.last_assembled_deg), std::to_string(sweep->lower.loop),
                   fmt::format("{:.4f}", sweep->upper.last_assembled_deg), std::to_string(sweep->upper.loop),
                   scientific(sweep->worst_closed_form_distance), scientific(sweep->worst_length_error),
                   scientific(sweep->worst_rigid_error)});
  }
  session.show(range, "range");
  session.say(fmt::format("The linkage assembles from {:.2f} to {:.2f} deg. Below, {} cannot close (|P0 P6| falls below "
                          "|0 5| - |5 6|); above, {} cannot close (|P7 P8| falls below |7 10| - |10 8|). Sequential and "
                          "full Newton agree to {:.1g} at every pose; both stay on the closed form's branch, through "
                          "loop 4's singular crossing near 43.15 deg.",
                          full.lower.last_assembled_deg, full.upper.last_assembled_deg,
                          mustang_loop_names[static_cast<std::size_t>(std::max(full.lower.loop, 1) - 1)],
                          mustang_loop_names[static_cast<std::size_t>(std::max(full.upper.loop, 1) - 1)], agreement));
  return full;
}

// Step 5: every solve the sweep tried near the upper limit, where the step halves into a bisection.
void show_the_sweep_near_the_upper_limit(LabSession& session, const SweepRecorder<MustangSweepStepper>& full_trace) {
  if (!session.begin_step("Newton near the upper limit",
                          "Every solve the sweep tried above 55 deg: the step halves into a bisection, Newton needs more "
                          "iterations, and the Jacobian's condition grows as the loop's margin goes to zero (a fold: two "
                          "assemblies of loop 3 meet and J is singular there). Then one solve at a time, iteration by "
                          "iteration.")) return;
  Table near({"theta (deg)", "step", "iterations", "||f||_inf", "kappa(J)", "margin", "status", "kept"});
  for (const auto& attempt : full_trace.attempts()) {
    if (attempt.crank_deg < 55.0) continue;
    near.add_row({fmt::format("{:.5f}", attempt.crank_deg), fmt::format("{:+.5f}", attempt.step_deg),
                  std::to_string(attempt.outcome.iterations), scientific(attempt.outcome.residual_norm),
                  scientific(attempt.angles.allFinite() ? mustang_condition(attempt.crank_deg * degrees, attempt.angles) : std::nan("")),
                  scientific(attempt.angles.allFinite() ? mustang_smallest_margin(attempt.crank_deg * degrees, attempt.angles)
                                                        : std::nan("")), std::string(to_string(attempt.outcome.status)),
                  attempt.accepted ? "yes" : "no"});
  }
  session.show(near, "upper-limit-trace");
}

// Step 5, continued: Newton one solve at a time near the limit, iteration by iteration.
void show_newton_iterations_near_the_limit(LabSession& session, const MustangLinkage& linkage, const MustangStart& start) {
  // Newton iteration by iteration: each solve starts from the pose 0.05 deg before it.
  Table iterations({"theta (deg)", "k", "||f||_inf", "||f_k|| / ||f_k-1||^2", "kappa(J)"});
  for (const double theta : {50.0, 56.0, 56.4, 56.45}) {
    const MustangClosedForm before = linkage.closed_form((theta - 0.05) * degrees);
    const MustangClosure system(theta * degrees);
    nonlinear::NewtonOptions options;
    options.residual_tolerance = 1e-13;
    nonlinear::Newton<MustangClosure> newton(system, options);
    newton.start(MustangLinkage::angles_of(before.joints, start.x));
    double previous = newton.residual().lpNorm<Eigen::Infinity>();
    for (int k = 1; newton.running(); ++k) {
      newton.step();
      const double now = newton.residual().lpNorm<Eigen::Infinity>();
      iterations.add_row({fmt::format("{:g}", theta), std::to_string(k), scientific(now),
                          now <= 1e-13 ? std::string("- (rounding)") : scientific(now / (previous * previous)), scientific(mustang_condition(theta * degrees, newton.x()))});
      previous = now;
    }
  }
  session.show(iterations, "newton-near-limit");
  session.say("Far from the limit the residual squares each iteration with a small constant; near it the constant "
              "||f_k|| / ||f_k-1||^2 grows with kappa(J), the first steps gain less, and the basin in which Newton "
              "converges shrinks, which is why the sweep must halve its step there.");
}

// Step 6: the linkage drawn at 45 deg with its roof tip's path, and the sweep animated.
void show_the_scenes(LabSession& session) {
  if (!session.begin_step("The scenes", "The linkage at 45 deg with the path of the roof tip P12, and the sweep animated "
                                        "forth and back (open the SVG files in a browser).")) return;
  const MustangSweep scene = fixed_sweep("full", -41.0, 56.0, 1.0);
  std::size_t at45 = 0;
  while (at45 + 1 < scene.poses.size() && scene.poses[at45].crank_deg < 45.0) ++at45;
  const std::string still = write_lab_file(session, "mustang.svg", mustang_pose_svg(scene, at45));
  const std::string moving = write_lab_file(session, "mustang-animated.svg", mustang_animation_svg(scene, 8.0));
  session.figure(still, "the roof linkage at 45 deg, the three major links heavy, with the path of the roof tip P12");
  session.figure(moving, "the sweep over the assembly range, animated forth and back");
  const MustangSweep range = fixed_sweep("full", -90.0, 90.0, 0.5);
  write_lab_file(session, "mustang.html",
                 linkage_page_html(mustang_page_data(range, -90.0, 90.0, "lab mustang's sweep: full Newton, -90:90:0.5"),
                                   mustang_pose_svg(scene, at45), "the roof linkage at 45 deg (the page without scripts)"));
  session.say("mustang.html, beside this report, is the sweep to drag: a slider scrubs its poses between the two "
              "assembly limits (marked), redrawing the linkage with every joint's velocity and reading out each "
              "pose's numbers.");
}

// Step 7: every solver timed over the range, as ratios to full Newton.
void compare_every_solver(LabSession& session) {
  if (!session.begin_step("Every solver over the range", "One sweep -41:56:0.5 per solver (median of repeated runs, "
                                                         "tolerance 1e-10), as ratios to full Newton:")) return;
  const auto rows = bench_mustang(1e-10, true);
  Table compare({"solver", "time per sweep (s)", "x full", "iterations", "error"});
  for (const auto& row : rows) {
    compare.add_row({row.solver, scientific(row.time_s), fmt::format("{:.2f}", row.time_s / rows.front().time_s),
                     std::to_string(row.iterations), scientific(row.error)});
  }
  session.show(compare, "solvers");
  session.say("'error' is the worst joint distance from the closed form over the sweep. A quick timing (few runs): "
              "`numlab bench mustang` measures properly and includes all eight GSL types.");
}

}  // namespace

int run_mustang_lab(LabSession& session) {
  const MustangLinkage linkage;
  const MustangStart start = mustang_seed_start();
  show_the_model(session, start);
  show_the_seed_method_as_written(session, linkage);
  show_each_error_in_turn(session, linkage, start);
  SweepRecorder<MustangSweepStepper> full_trace;
  const MustangSweep full = show_the_fixed_method_over_the_range(session, full_trace);
  show_the_sweep_near_the_upper_limit(session, full_trace);
  show_newton_iterations_near_the_limit(session, linkage, start);
  show_the_scenes(session);
  compare_every_solver(session);
  return full.status == Status::cannot_assemble && full.branch_kept ? exit_success : exit_method_failed;
}

}  // namespace numlab::cli
