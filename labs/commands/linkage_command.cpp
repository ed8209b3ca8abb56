#include "commands/linkage_command.hpp"
#include "output/step_pause.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <limits>
#include <nlohmann/json.hpp>

#include "parsing/argument_parsing.hpp"
#include "methods/data_dir.hpp"
#include "output/driving_chart.hpp"
#include "output/linkage_report.hpp"
#include "numlab/mechanisms/linkage/driver_path.hpp"
#include "numlab/mechanisms/linkage/crank_analysis.hpp"
#include "numlab/mechanisms/linkage/link_motion.hpp"
#include "numlab/mechanisms/linkage/linkage_authoring_checks.hpp"
#include "numlab/printable_text.hpp"
#include "numlab/mechanisms/linkage/linkage_structure.hpp"
#include "numlab/nonlinear/jacobian_check.hpp"
#include "output/table.hpp"
#include "scenes/linkage_scene.hpp"
#include "linkage_page/file_page_data.hpp"
#include "linkage_page/linkage_page_html.hpp"

namespace numlab::cli {

namespace fs = std::filesystem;
using namespace mechanisms;

std::string linkage_file_for(const std::string& name) {
  std::error_code error;
  if (fs::is_regular_file(name, error)) return name;
  const bool plain_name = !name.empty() && name.size() <= 64 &&
                          std::all_of(name.begin(), name.end(), [](char c) {
                            return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '-' || c == '_' || c == '.';
                          });
  if (!plain_name) return {};
  std::string dir;
  try {
    dir = models_dir();
  } catch (const std::invalid_argument&) {
    return {};
  }
  const fs::path shipped = fs::path(dir) / (name.ends_with(".toml") ? name : name + ".toml");
  return fs::is_regular_file(shipped, error) ? shipped.string() : std::string();
}

namespace {

// --trace and --step: one row per pose on stderr as it is solved, then a pause.
class PoseTracer final : public StepObserver<LinkageSweepStepper, LinkagePose> {
 public:
  PoseTracer(const LinkageModel& model, bool print, StepPause& pause) : model_(model), print_(print), pause_(pause) {}
  StepControl on_step(const LinkageSweepStepper&, const LinkagePose& pose) override {
    if (pause_.stopped()) return StepControl::stop;
    rows_.push_back(pose_trace_json(pose));
    if (print_) {
      if (rows_.size() == 1) {
        std::cerr << fmt::format("{:>12}  {:>10}  {:>10}  {:>10}  {:<15}\n", model_.crank_driven() ? "crank (deg)" : "travel",
                                 "iterations", "||Phi||_inf", "kappa(J)", "status");
      }
      std::cerr << fmt::format("{:>12.6g}  {:>10}  {:>10}  {:>10}  {:<15}\n", pose.driver, pose.outcome.iterations,
                               scientific(pose.outcome.residual_norm), scientific(pose.condition),
                               to_string(pose.outcome.status));
    }
    return pause_.after_step();
  }
  const nlohmann::ordered_json& rows() const { return rows_; }

 private:
  const LinkageModel& model_;
  bool print_;
  StepPause& pause_;
  nlohmann::ordered_json rows_ = nlohmann::ordered_json::array();
};

// --check-jacobian: the exact J against finite differences at every solved pose; the worst.
JacobianReport check_jacobians(const LinkageModel& model, const LinkageSweep& sweep) {
  JacobianReport report;
  for (const LinkagePose& pose : sweep.poses) {
    if (pose.outcome.status != Status::converged) continue;
    const LinkageSystem system(model, model.driver_from_user(pose.driver));
    const auto check = nonlinear::check_jacobian(system, pose.q);
    ++report.poses;
    if (report.poses == 1 || check.worst_error > report.worst.worst_error) {
      report.worst = check;
      report.driver = pose.driver;
    }
  }
  return report;
}

// The velocity and acceleration checks at up to eight converged poses spread over the sweep; the
// first pose whose kinematics disagree with differences of solved positions beyond the tolerance
// is named (a pose on a crossing is not checked: J gives no velocity there, the sweep took its
// kinematics from such differences already).
// `path_model`: a --drivers path's model, whose second driver is held at each pose's value first.
DerivativeReport check_poses(const LinkageSolver& solver, const LinkageSweep& sweep, LinkageModel* path_model) {
  DerivativeReport report;
  std::vector<const LinkagePose*> converged;
  for (const auto& pose : sweep.poses) {
    if (pose.outcome.status == Status::converged) converged.push_back(&pose);
  }
  const std::size_t wanted = std::min<std::size_t>(8, converged.size());
  for (std::size_t k = 0; k < wanted; ++k) {
    const LinkagePose& pose = *converged[k * converged.size() / wanted];
    if (path_model != nullptr) path_model->hold_second_driver(pose.second_driver);
    const auto check = check_derivatives(solver, solver.model().driver_from_user(pose.driver), pose.q);
    if (!check.solved) {
      ++report.unsolved;
      continue;
    }
    if (check.singular) {
      ++(check.near_meeting_point ? report.singular : report.ill_conditioned);
      continue;
    }
    ++report.poses;
    const double velocity = check.velocity_relative(), acceleration = check.acceleration_relative();
    report.velocity = std::max(report.velocity, velocity);
    report.acceleration = std::max(report.acceleration, acceleration);
    if (report.failure.empty() && !check.agrees()) {
      report.failure = fmt::format("at {:g} the velocity and acceleration from J disagree with differences of solved "
                                   "positions: {:.1e} and {:.1e} (relative; kappa(J) {:.3g} allows {:.1e} and {:.1e})",
                                   pose.driver, velocity, acceleration, check.condition, check.velocity_allowed(),
                                   check.acceleration_allowed());
    }
  }
  return report;
}

// A sweep succeeds when every pose converged, on the reference branch (crossings allowed, no
// jump), within the distance of the closed form that its residual allows (where the model has
// one), and with kinematics that agree with differences of its positions.
Status overall_status(const LinkageSweep& sweep, const DerivativeReport& derivatives) {
  if (sweep.status != Status::converged) return sweep.status;
  return sweep.branch_kept && sweep.closed_form_verified && derivatives.failure.empty() ? Status::converged
                                                                                        : Status::no_progress;
}

// The authoring checks at the reference pose (docs/linkage-files.md, "Authoring checks"): each
// warning as "FILE:LINE: text" on stderr, or with --strict the first one as bad input.
std::vector<std::string> authoring_check_lines(const LinkageSolver& solver, bool strict) {
  const LinkageModel& model = solver.model();
  const std::string& file = model.description().file;
  const auto warnings = authoring_warnings(model, polished_reference(model, solver.reference()));
  if (strict && !warnings.empty()) throw LinkageFileError(file, warnings.front().place, warnings.front().text);
  std::vector<std::string> lines;
  for (const AuthoringWarning& warning : warnings) {
    lines.push_back(warning_line(file, warning));
    std::cerr << "numlab: warning: " << lines.back() << '\n';
  }
  return lines;
}

// --output NAME, else the file's `output = "NAME"`, else none. An unknown --output is bad input.
std::optional<LinkageOutput> chosen_output(const LinkageDescription& d, const std::string& flag) {
  const std::string& name = flag.empty() ? d.output : flag;
  if (name.empty()) return std::nullopt;
  auto output = find_output(d, name);
  if (!output) {
    throw std::invalid_argument("--output '" + printable(std::string_view(name).substr(0, 40)) + "': not a link, body or slider joint of " +
                                d.name + "; name one of the " + output_choices(d));
  }
  return output;
}

// What the scenes highlight: --path's joints (each a moving joint, else bad input), else the file's
// trace, else nothing chosen (every path drawn).
LinkageSceneOptions scene_options(const LinkageModel& model, const LinkageRun& run) {
  const LinkageDescription& d = model.description();
  LinkageSceneOptions options;
  options.velocity_arrows = run.arrows;
  std::string moving;
  for (const int j : model.moving()) moving += (moving.empty() ? "" : ", ") + d.joints[static_cast<std::size_t>(j)].name;
  for (const std::string& name : run.paths) {
    const int joint = d.joint_index(name);
    const std::string shown = printable(std::string_view(name).substr(0, 40));
    if (joint < 0) throw std::invalid_argument("--path '" + shown + "': not a joint of " + d.name + "; name a moving joint (" + moving + ")");
    if (d.joints[static_cast<std::size_t>(joint)].ground) {
      throw std::invalid_argument("--path " + shown + ": a ground joint has no path; name a moving joint (" + moving + ")");
    }
    if (std::find(options.paths.begin(), options.paths.end(), joint) == options.paths.end()) options.paths.push_back(joint);
  }
  options.paths_from = "--path";
  if (options.paths.empty() && !d.trace.empty()) options.paths = d.trace, options.paths_from = "the file's trace";
  return options;
}

// The pose --svg draws: --draw-at's, which must be a pose of the sweep that assembled (else bad
// input), or the best-conditioned pose (linkage_scene.hpp). The reason goes to the caption.
std::size_t drawn_pose(const LinkageModel& model, const LinkageSweep& sweep, const LinkageRun& run, std::string& reason) {
  if (!run.draw_at) {
    const std::size_t best = *best_conditioned_pose(model, sweep);
    reason = fmt::format("the sweep's best-conditioned pose, kappa(J) {:.3g}", sweep.poses[best].condition);
    return best;
  }
  const auto pose = pose_at(sweep, *run.draw_at);
  const auto& poses = sweep.poses;
  if (!pose) {
    throw std::invalid_argument(fmt::format("--draw-at {:g}: not a pose of the sweep, whose poses run from {:g} to {:g}{}",
                                            *run.draw_at, poses.front().driver, poses.back().driver,
                                            poses.size() > 1 ? fmt::format(" in steps of {:g}", poses[1].driver - poses[0].driver) : ""));
  }
  if (poses[*pose].outcome.status != Status::converged) {
    throw std::invalid_argument(fmt::format("--draw-at {:g}: the linkage did not assemble there ({})", *run.draw_at,
                                            to_string(poses[*pose].outcome.status)));
  }
  reason = "--draw-at";
  return *pose;
}

}  // namespace

int run_linkage(const LinkageRun& run) {
  // 1. The description, the derived model (mobility and structure checked), and the solver with
  // its reference pose: each is bad input when it fails.
  LinkageModel model(read_linkage_description(run.file));  // not const: a --drivers path moves the second driver
  check_driver_angles(model.description());
  if (run.explain) {
    print_explanation(std::cout, model, run.common.format);
    return exit_success;
  }
  const std::optional<LinkageOutput> output = chosen_output(model.description(), run.output);
  LinkageSceneOptions scene = scene_options(model, run);
  if (!run.chart.empty()) {
    if (const std::string problem = driving_chart_problem(model, output); !problem.empty()) throw std::invalid_argument(problem);
  }
  if (run.speed_rad_s && !model.crank_driven()) {
    throw std::invalid_argument("--speed gives a crank's speed; " + model.description().name + " is driven by a slider");
  }
  LinkageSolverOptions options;
  options.solver = run.solver;
  options.linear = run.linear;
  if (run.common.tolerance) options.newton.residual_tolerance = *run.common.tolerance;
  if (run.common.max_iterations) options.newton.max_iterations = *run.common.max_iterations;
  const LinkageSolver solver(model, options);
  std::vector<std::string> warnings = authoring_check_lines(solver, run.strict);
  if (run.analyse) {
    print_crank_analysis(std::cout, model, analyse_crank_mechanism(solver, output ? output->name : ""), run.file,
                         run.common.format);
    return exit_success;
  }
  if (!run.drivers.empty() && !model.has_second_driver()) {
    throw std::invalid_argument("--drivers moves two drivers; " + model.description().name + " has one (use --sweep)");
  }
  const bool on_path = !run.drivers.empty();
  const std::vector<DriverPathPoint> path = on_path ? read_driver_path(run.drivers) : std::vector<DriverPathPoint>{};
  const DegreeRange range = run.driver ? DegreeRange{*run.driver, *run.driver, 1.0}
                            : on_path  ? DegreeRange{0.0, 0.0, 1.0}
                                       : parse_degree_range(run.sweep, "--sweep");

  // 2. The sweep, traced and paused as asked; the time leaves out the pauses.
  StepPause pause(run.common.step);
  PoseTracer tracer(model, run.common.trace && (run.common.step || run.common.format != Format::json), pause);
  const auto begin = std::chrono::steady_clock::now();
  LinkageSweepStepper stepper(solver, run.switch_at_crossing ? AtCrossing::switch_branch : AtCrossing::smooth);
  if (run.common.trace) stepper.set_observer(&tracer);  // untraced, the poses take the fast path
  LinkageSweep path_sweep;
  if (on_path) {
    path_sweep = solve_driver_path(model, solver, path);
  } else {
    stepper.start(range.start, range.stop, range.step);
    while (stepper.step()) {  // one requested pose
    }
  }
  const LinkageSweep& sweep = on_path ? path_sweep : stepper.result();
  if (stepper.stopped()) {
    return report_stopped(run.common, {{"mechanism", model.description().name}, {"solver", run.solver}}, tracer.rows());
  }
  const double time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count() - pause.seconds_waited();

  // 3. The checks that read the sweep, the files, then the report.
  LinkageReport report{model, solver, sweep, time_s, check_poses(solver, sweep, on_path ? &model : nullptr), std::nullopt, Status::converged,
                       std::move(warnings), output, run.speed_rad_s};
  if (run.check_jacobian) report.jacobian = check_jacobians(model, sweep);
  report.status = overall_status(sweep, report.derivatives);
  const bool drawable = std::any_of(sweep.poses.begin(), sweep.poses.end(),
                                    [](const LinkagePose& p) { return p.outcome.status == Status::converged; });
  FileBatch files;  // the drawings and the page: all of them in place, or none (a full disk)
  if (drawable) {
    const std::size_t pose = drawn_pose(model, sweep, run, scene.pose_reason);
    if (!run.svg.empty()) files.add(run.svg, linkage_pose_svg(model, sweep, pose, scene));
    if (!run.animate.empty()) files.add(run.animate, linkage_animation_svg(model, sweep, 4.0, scene));
    if (!run.html.empty()) {  // the page's picture without scripts: --svg's, with the velocity arrows
      LinkageSceneOptions still = scene;
      still.velocity_arrows = true;
      files.add(run.html, linkage_page_html(file_page_data(report, run.name.empty() ? run.file : run.name),
                                            linkage_pose_svg(model, sweep, pose, still),
                                            "one pose drawn by numlab (the page without scripts)"));
    }
  } else if (!run.svg.empty() || !run.animate.empty() || !run.html.empty()) {
    std::cerr << "numlab: no pose assembled, so no scene was drawn\n";
    if (!run.html.empty()) {
      files.add(run.html, linkage_page_html(file_page_data(report, run.name.empty() ? run.file : run.name), "",
                                            "no pose assembled"));
    }
  }
  if (!run.chart.empty()) draw_driving_chart(chart_files(run.chart), model, sweep, output);
  files.commit();
  if (run.common.format == Format::json) {
    std::cout << linkage_json(report, run.common.trace ? &tracer.rows() : nullptr).dump(2) << '\n';
  } else if (run.common.format == Format::csv) {
    print_linkage_csv(std::cout, report);
  } else {
    print_linkage_text(std::cout, report, run.file);
  }
  if (run.check_jacobian && report.jacobian && !report.jacobian->worst.agrees) return exit_method_failed;
  return exit_code_for(report.status);
}

}  // namespace numlab::cli
