#include "commands/mustang_command.hpp"

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <numbers>
#include <optional>
#include <iostream>
#include <nlohmann/json.hpp>

#include "linkage_page/builtin_csv.hpp"
#include "linkage_page/builtin_page_data.hpp"
#include "linkage_page/linkage_page_html.hpp"
#include "commands/crank_sweep_tracer.hpp"
#include "numlab/mechanisms/crank_angle.hpp"
#include "scenes/mustang_scene.hpp"
#include "output/table.hpp"

namespace numlab::cli {

namespace {

using mechanisms::MustangLimit;
using mechanisms::MustangSweep;
using mechanisms::SweepAttempt;
using Tracer = CrankSweepTracer<mechanisms::MustangSweepStepper>;

using mechanisms::degrees;

// kappa_2 of J and the smallest loop margin where an attempt ended (NaN where it ended at no point).
double condition_of(const SweepAttempt& attempt) {
  return attempt.angles.allFinite() ? mechanisms::mustang_condition(attempt.crank_deg * degrees, attempt.angles)
                                    : std::nan("");
}
double margin_of(const SweepAttempt& attempt) {
  return attempt.angles.allFinite() ? mechanisms::mustang_smallest_margin(attempt.crank_deg * degrees, attempt.angles)
                                    : std::nan("");
}

std::string loop_name(int loop) {
  return loop >= 1 && loop <= 4 ? std::string(mechanisms::mustang_loop_names[static_cast<std::size_t>(loop - 1)])
                                : std::string("no loop");
}

// "loop 2 (C, D: ...) cannot close beyond -41.42 deg (fails at -41.43)" or the solver's failure.
std::string limit_text(const MustangLimit& limit) {
  if (!limit.reached) return "not reached in this sweep";
  if (limit.status == Status::cannot_assemble) {
    return fmt::format("{:.4f} deg assembles, {:.4f} deg does not: {} cannot close", limit.last_assembled_deg,
                       limit.failed_deg, loop_name(limit.loop));
  }
  return fmt::format("the solver stopped ({}) at {:.4f} deg, where the linkage does close; last pose {:.4f} deg",
                     to_string(limit.status), limit.failed_deg, limit.last_assembled_deg);
}

nlohmann::ordered_json limit_json(const MustangLimit& limit) {
  if (!limit.reached) return nullptr;
  return {{"status", std::string(to_string(limit.status))},
          {"last_assembled_deg", limit.last_assembled_deg},
          {"failed_deg", limit.failed_deg},
          {"loop", limit.loop == 0 ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(limit.loop)},
          {"loop_name", loop_name(limit.loop)},
          {"solver_failed_in_loop", limit.solver_loop == 0 ? nlohmann::ordered_json(nullptr)
                                                           : nlohmann::ordered_json(limit.solver_loop)}};
}

// Whether the sweep ran into the end of the assembly range in either direction.
bool reached_a_limit(const MustangSweep& sweep) {
  return (sweep.lower.reached && sweep.lower.status == Status::cannot_assemble) ||
         (sweep.upper.reached && sweep.upper.status == Status::cannot_assemble);
}

nlohmann::ordered_json assembly_range(const MustangSweep& sweep) {
  auto end = [](const MustangLimit& limit) {
    return limit.reached && limit.status == Status::cannot_assemble ? nlohmann::ordered_json(limit.last_assembled_deg)
                                                                    : nlohmann::ordered_json(nullptr);
  };
  return {end(sweep.lower), end(sweep.upper)};
}

nlohmann::ordered_json trace_json(const std::vector<SweepAttempt>& attempts) {
  nlohmann::ordered_json trace = nlohmann::ordered_json::array();
  for (const auto& attempt : attempts) {
    trace.push_back(attempt_json(attempt, {{"condition", number_or_null(condition_of(attempt))},
                                           {"margin", number_or_null(margin_of(attempt))}}));
  }
  return trace;
}

nlohmann::ordered_json json_of(const MustangRequest& request, const MustangSweep& sweep, const Tracer& tracer,
                               double time_s) {
  nlohmann::ordered_json out = {{"mechanism", "mustang"}, {"solver", request.solver}, {"poses", nlohmann::ordered_json::array()}};
  for (const auto& pose : sweep.poses) {
    nlohmann::ordered_json angles, joints;
    for (std::size_t k = 0; k < 8; ++k) angles[std::string(mechanisms::mustang_angle_names[k])] = pose.angles(static_cast<Eigen::Index>(k));
    for (std::size_t j = 0; j < pose.joints.size(); ++j) {
      joints[std::string(mechanisms::mustang_joint_names[j])] = {pose.joints[j].x(), pose.joints[j].y()};
    }
    out["poses"].push_back({{"crank_deg", pose.crank_deg},
                            {"angles", angles},
                            {"joints", joints},
                            {"iterations", pose.outcome.iterations},
                            {"residual_inf", pose.outcome.residual_norm},
                            {"status", std::string(to_string(pose.outcome.status))},
                            {"condition", number_or_null(pose.condition)},
                            {"closed_form_distance", number_or_null(pose.closed_form_distance)},
                            {"closed_form_bound", number_or_null(pose.closed_form_bound)}});
  }
  out["status"] = std::string(to_string(sweep.status));
  if (reached_a_limit(sweep)) out["assembly_range_deg"] = assembly_range(sweep);
  out["limits"] = {{"lower", limit_json(sweep.lower)}, {"upper", limit_json(sweep.upper)}};
  out["worst_closed_form_distance"] = number_or_null(sweep.worst_closed_form_distance);
  out["worst_closed_form_bound"] = number_or_null(sweep.worst_closed_form_bound);
  out["worst_length_error"] = number_or_null(sweep.worst_length_error);
  out["worst_rigid_body_error"] = number_or_null(sweep.worst_rigid_error);
  out["worst_fixed_point_error"] = number_or_null(sweep.worst_fixed_error);
  out["worst_angle_rate"] = number_or_null(sweep.worst_angle_rate);
  out["branch_kept"] = sweep.branch_kept;
  out["step_halvings"] = sweep.step_halvings;
  out["time_s"] = time_s;
  if (request.common.trace) out["trace"] = trace_json(tracer.attempts());
  return out;
}

// --trace: every solve the sweep tried, in the order tried (stderr).
void print_trace(std::ostream& out, const std::vector<SweepAttempt>& attempts) {
  Table table({"theta (deg)", "step", "iterations", "||f||_inf", "kappa(J)", "margin", "status", "kept"});
  for (const auto& attempt : attempts) {
    table.add_row({fmt::format("{:.5f}", attempt.crank_deg), fmt::format("{:+.5f}", attempt.step_deg),
                   std::to_string(attempt.outcome.iterations), scientific(attempt.outcome.residual_norm),
                   scientific(condition_of(attempt)), scientific(margin_of(attempt)),
                   std::string(to_string(attempt.outcome.status)),
                   attempt.accepted ? "yes" : "no"});
  }
  table.print(out);
  out << "margin: the smallest loop's distance from its limit (0 where a dyad's circles just touch)\n";
}

void print_text(std::ostream& out, const MustangRequest& request, const MustangSweep& sweep, double time_s) {
  out << "mechanism          mustang (seed 003's roof linkage, 8 equations in A ... H)\n"
      << fmt::format("solver             {}\n", request.solver)
      << fmt::format("status             {}\n", to_string(sweep.status))
      << fmt::format("poses              {}\n", sweep.poses.size());
  constexpr std::size_t shown = 8;
  Table table({"theta (deg)", "C", "D", "x_P12", "y_P12", "iterations", "||f||_inf", "kappa(J)", "status"});
  for (std::size_t i = 0; i < sweep.poses.size(); ++i) {
    if (sweep.poses.size() > shown && i == shown / 2) {
      table.add_row({fmt::format("... ({} more)", sweep.poses.size() - shown)});
      i = sweep.poses.size() - shown / 2;
    }
    const auto& pose = sweep.poses[i];
    table.add_row({fmt::format("{:g}", pose.crank_deg), fmt::format("{:.6f}", pose.angles(2)),
                   fmt::format("{:.6f}", pose.angles(3)), fmt::format("{:.6f}", pose.joints[12].x()),
                   fmt::format("{:.6f}", pose.joints[12].y()), std::to_string(pose.outcome.iterations),
                   scientific(pose.outcome.residual_norm), scientific(pose.condition),
                   std::string(to_string(pose.outcome.status))});
  }
  if (!sweep.poses.empty()) table.print(out);
  if (reached_a_limit(sweep)) {
    const auto range = assembly_range(sweep);
    auto end = [](const nlohmann::ordered_json& value) { return value.is_null() ? std::string("-") : fmt::format("{:.4f}", value.get<double>()); };
    out << fmt::format("assembly range     [{}, {}] deg (the last angles that assembled, to 0.01 deg)\n", end(range[0]), end(range[1]));
  }
  out << fmt::format("lower end          {}\n", limit_text(sweep.lower))
      << fmt::format("upper end          {}\n", limit_text(sweep.upper));
  if (!sweep.poses.empty()) {
    out << fmt::format("checks             worst joint distance from the closed form {:.2g} (bound {:.2g}); worst "
                     "link-length error {:.2g}; rigid bodies {:.2g}; fixed points {:.2g}; branch {}\n",
                     sweep.worst_closed_form_distance, sweep.worst_closed_form_bound, sweep.worst_length_error,
                     sweep.worst_rigid_error, sweep.worst_fixed_error,
                     sweep.branch_kept ? "kept" : "NOT VERIFIED (a pose is beyond its closed-form bound)");
  }
  out << fmt::format("time               {:.3g} s\n", time_s);
}

}  // namespace

int run_mustang(const MustangRequest& request) {
  nonlinear::NewtonOptions options;
  options.residual_tolerance = request.common.tolerance.value_or(1e-12);
  options.max_iterations = request.common.max_iterations.value_or(50);
  const auto solver = mechanisms::make_mustang_solver(request.solver, request.linear, options);
  // --trace keeps every attempt (printed as a table afterwards on stderr, or in the JSON); --step
  // also prints each attempt as it happens and pauses after it. The time leaves out the pauses.
  const CommonOptions& common = request.common;
  StepPause pause(common.step);
  Tracer tracer(common.step ? &std::cerr : nullptr, &pause);
  const auto begin = std::chrono::steady_clock::now();
  mechanisms::MustangSweepStepper stepper(*solver);
  if (common.trace) stepper.set_observer(&tracer);
  stepper.start(request.start, request.stop, request.step);
  while (stepper.step()) {  // one requested angle, its marching and halvings included
  }
  const MustangSweep& sweep = stepper.result();
  if (pause.stopped()) {
    return report_stopped(common, {{"mechanism", "mustang"}, {"solver", request.solver}}, trace_json(tracer.attempts()));
  }
  const double time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count() - pause.seconds_waited();

  if (!sweep.poses.empty()) {
    FileBatch files;  // all of them in place, or none (a full disk)
    if (!request.svg.empty()) files.add(request.svg, mustang_pose_svg(sweep, 0));
    if (!request.animate.empty()) files.add(request.animate, mustang_animation_svg(sweep, 0.08 * static_cast<double>(sweep.poses.size())));
    if (!request.html.empty()) {
      const auto data = mustang_page_data(sweep, request.start, request.stop, "numlab mechanism mustang --format csv");
      files.add(request.html, linkage_page_html(data, mustang_pose_svg(sweep, 0),
                                                "the linkage at the sweep's first pose (the page without scripts)"));
    }
    files.commit();
  }
  if (request.common.format == Format::json) {
    std::cout << json_of(request, sweep, tracer, time_s).dump(2) << '\n';
  } else {
    if (request.common.trace && !request.common.step) print_trace(std::cerr, tracer.attempts());
    if (request.common.format == Format::csv) {
      print_mustang_csv(std::cout, sweep);
    } else {
      print_text(std::cout, request, sweep, time_s);
    }
  }
  return exit_code_for(sweep.status);
}

}  // namespace numlab::cli
