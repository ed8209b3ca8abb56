#include "commands/mechanism_command.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <iostream>
#include <limits>
#include <numbers>
#include <optional>
#include <utility>
#include <vector>
#include <nlohmann/json.hpp>

#include "parsing/argument_parsing.hpp"
#include "numlab/mechanisms/jansen_solvers.hpp"
#include "numlab/nonlinear/linear_step.hpp"
#include "scenes/jansen_scene.hpp"
#include "commands/linkage_command.hpp"
#include "commands/mustang_command.hpp"
#include "numlab/mechanisms/linkage/linkage_solver.hpp"
#include "numlab/printable_text.hpp"
#include "parsing/speed_argument.hpp"
#include "commands/crank_sweep_tracer.hpp"
#include "linkage_page/builtin_csv.hpp"
#include "linkage_page/builtin_page_data.hpp"
#include "linkage_page/linkage_page_html.hpp"
#include "output/chart.hpp"
#include "output/table.hpp"

namespace numlab::cli {

namespace {

using mechanisms::JansenModel;
using Tracer = CrankSweepTracer<mechanisms::JansenSweepStepper>;

nlohmann::ordered_json json_of(const std::string& name, const std::string& solver, JansenModel model,
                               const mechanisms::JansenSweep& sweep, const Tracer* tracer, double time_s) {
  const auto names = mechanisms::jansen_angle_names(model);
  nlohmann::ordered_json out = {{"mechanism", name}, {"solver", solver}, {"poses", nlohmann::ordered_json::array()}};
  for (const auto& pose : sweep.poses) {
    nlohmann::ordered_json angles, joints;
    for (std::size_t k = 0; k < names.size(); ++k) angles[names[k]] = pose.angles(static_cast<Eigen::Index>(k));
    for (std::size_t j = 0; j < pose.joints.size(); ++j) {
      joints[std::string(mechanisms::jansen_joint_names[j])] = {pose.joints[j].x(), pose.joints[j].y()};
    }
    out["poses"].push_back({{"crank_deg", pose.crank_deg},
                            {"angles", angles},
                            {"joints", joints},
                            {"foot_speed", number_or_null(jansen_foot_speed(model, pose))},
                            {"iterations", pose.outcome.iterations},
                            {"residual_inf", pose.outcome.residual_norm},
                            {"status", std::string(to_string(pose.outcome.status))},
                            {"closed_form_distance", number_or_null(pose.closed_form_distance)},
                            {"closed_form_bound", number_or_null(pose.closed_form_bound)}});
  }
  out["status"] = std::string(to_string(sweep.status));
  out["worst_closed_form_distance"] = number_or_null(sweep.worst_closed_form_distance);
  out["worst_closed_form_bound"] = number_or_null(sweep.worst_closed_form_bound);
  out["closed_form_verified"] = sweep.closed_form_verified;
  out["worst_length_error"] = number_or_null(sweep.worst_length_error);
  out["branch_kept"] = sweep.orientation_kept;
  out["step_halvings"] = sweep.step_halvings;
  out["time_s"] = time_s;
  if (tracer != nullptr) {
    out["trace"] = nlohmann::ordered_json::array();
    for (const auto& attempt : tracer->attempts()) out["trace"].push_back(attempt_json(attempt));
  }
  return out;
}

// The branch check in words: kept, flipped, or not verified when a pose is farther from the closed
// form than its residual and conditioning justify (mechanisms/closed_form_bound.hpp).
std::string branch_verdict(const mechanisms::JansenSweep& sweep) {
  if (!sweep.closed_form_verified) return "NOT VERIFIED (a pose is beyond its closed-form bound)";
  return sweep.orientation_kept ? "kept" : "FLIPPED";
}

void print_text(std::ostream& out, const std::string& name, const std::string& solver, JansenModel model,
                const mechanisms::JansenSweep& sweep, double time_s) {
  out << fmt::format("mechanism          {} ({})\n", name,
                     model == JansenModel::eight_equations ? "seed 000's 8 equations" : "seed 001's 10 equations")
      << fmt::format("solver             {}\n", solver)
      << fmt::format("status             {}\n", to_string(sweep.status))
      << fmt::format("poses              {}\n", sweep.poses.size());
  constexpr std::size_t shown = 8;
  Table table({"crank (deg)", "x_F", "y_F", "foot speed", "iterations", "||f||_inf", "status"});
  for (std::size_t i = 0; i < sweep.poses.size(); ++i) {
    if (sweep.poses.size() > shown && i == shown / 2) {
      table.add_row({fmt::format("... ({} more)", sweep.poses.size() - shown)});
      i = sweep.poses.size() - shown / 2;
    }
    const auto& pose = sweep.poses[i];
    const auto& foot = pose.joints[static_cast<std::size_t>(mechanisms::JansenJoint::F)];
    table.add_row({fmt::format("{:g}", pose.crank_deg), fmt::format("{:.6f}", foot.x()), fmt::format("{:.6f}", foot.y()),
                   fmt::format("{:.4f}", jansen_foot_speed(model, pose)), std::to_string(pose.outcome.iterations), scientific(pose.outcome.residual_norm),
                   std::string(to_string(pose.outcome.status))});
  }
  table.print(out);
  out << fmt::format("checks             worst joint distance from the closed form {:.2g} (bound {:.2g}); worst "
                     "link-length error {:.2g}; branch {}\n",
                     sweep.worst_closed_form_distance, sweep.worst_closed_form_bound, sweep.worst_length_error,
                     branch_verdict(sweep))
      << fmt::format("time               {:.3g} s\n", time_s)
      << "foot speed is |dF/d theta_i|: length units per radian of crank\n";
}

}  // namespace

// The beest puts its legs half a turn apart on one solved cycle: the sweep must be one whole turn
// (START:START+360-STEP:STEP) with an even number of poses.
void require_full_turn(const SweepRange& range) {
  const double turn = std::abs(range.stop - range.start) + std::abs(range.step);
  const double poses = 360.0 / std::abs(range.step);
  const bool whole = std::abs(turn - 360.0) <= 1e-9 * 360.0;
  const bool even = std::abs(poses - std::round(poses)) <= 1e-9 && static_cast<long long>(std::round(poses)) % 2 == 0;
  if (!whole || !even) {
    throw std::invalid_argument("--beest needs one whole turn with an even number of poses, e.g. --sweep 0:358:2");
  }
}

SweepRange parse_sweep(const std::string& text) {
  const DegreeRange range = parse_degree_range(text, "--sweep");
  return {range.start, range.stop, range.step};
}

MechanismCommand::MechanismCommand(CLI::App& app) {
  command_ = app.add_subcommand("mechanism", "Solve a linkage at one crank angle or over a sweep");
  command_->add_option("name", name_,
                       "jansen (seed 000, 8 equations), jansen10 (seed 001, 10 equations), mustang (seed 003), "
                       "a shipped model (numlab models) or a linkage description file")
      ->required();
  auto* crank = command_->add_option("--crank", crank_, "One crank angle (degrees)")
                    ->check(CLI::Validator([](std::string& text) { return finite_number_problem(text); }, "DEG"));
  auto* sweep = command_->add_option("--sweep", sweep_, "START:STOP:STEP in degrees");
  crank->excludes(sweep);
  auto* drivers = command_->add_option("--drivers", drivers_, "A description file with two drivers: move both along the "
                                                              "path in this CSV file (a header, then first,second per row) "
                                                              "instead of --sweep");
  drivers->excludes(crank)->excludes(sweep);
  command_->add_option("--solver", solver_, "full, sequential, analytic or gsl-<type>")
      ->check(CLI::IsMember(mechanisms::linkage_solver_names()));
  command_->add_option("--linear", linear_, "Inner solver of full Newton")
      ->check(CLI::IsMember({"gepp", "gauss-seidel", "gsl-lu", "eigen-lu"}));
  command_->add_option("--svg", svg_, "Draw the first pose and the foot path to this SVG file");
  command_->add_option("--animate", animate_, "Write an animated SVG of the sweep to this file");
  command_->add_option("--html", html_, "Write a page with the scene and a crank slider that scrubs the sweep's poses "
                                        "(needs --sweep)");
  command_->add_option("--beest", beest_, "Draw seed 000's four-legged beest from the sweep (a full turn)");
  command_->add_flag("--beest-animated{4.0}", beest_seconds_, "Animate the beest");
  command_->add_flag("--explain", explain_, "A description file: print the derived model (unknowns, equations, "
                                            "sparsity, blocks) and stop");
  command_->add_flag("--check-jacobian", check_jacobian_, "A description file: compare the exact Jacobian with "
                                                          "finite differences at every solved pose");
  command_->add_flag("--arrows", arrows_, "A description file: --svg draws each joint's velocity as an arrow");
  command_->add_flag("--strict", strict_, "A description file: an authoring warning (a joint solved far from its "
                                          "rough position, a link length or body shape that disagrees with it) "
                                          "is an error");
  command_->add_option("--at-crossing", at_crossing_, "A description file: where two assembly branches cross, "
                                                      "follow the smooth one (default) or switch to the other")
      ->check(CLI::IsMember({"smooth", "switch"}));
  command_->add_flag("--analyse", analyse_, "A description file: a four-bar's Grashof class, toggles and time ratio "
                                            "(a slider-crank's dead centres and time ratio), and stop");
  command_->add_option("--output", output_, "A description file: the output link, body or slider joint whose velocity "
                                            "ratio and mechanical advantage the CSV and JSON give (default: the file's output)");
  command_->add_option("--speed", speed_, "A description file: the crank's constant speed, e.g. 120rpm or 12.5rad/s: "
                                          "link rates per second too");
  command_->add_option("--draw-at", draw_at_, "A description file: the pose --svg draws, a driver value of the sweep "
                                              "(default: the best-conditioned pose)")
      ->check(CLI::Validator([](std::string& text) { return finite_number_problem(text); }, "VALUE"));
  command_->add_option("--path", paths_, "A description file: the moving joints whose paths --svg and --animate "
                                         "highlight (repeat or comma-separate; default: the file's trace)")
      ->delimiter(',');
  command_->add_option("--chart", chart_, "A description file: chart the driving torque and the mechanical advantage "
                                          "over the sweep (FILE.svg or FILE.png, drawn by gnuplot)");
  add_common_options(*command_, common_);
}

namespace {

bool built_in(const std::string& name) { return name == "jansen" || name == "jansen10" || name == "mustang"; }

}  // namespace

namespace {

// The Jansen sweep's report in the format asked for.
void print_jansen_report(const CommonOptions& common, const std::string& name, const std::string& solver,
                         JansenModel model, const mechanisms::JansenSweep& sweep, const Tracer& tracer, double time_s) {
  if (common.format == Format::json) {
    std::cout << json_of(name, solver, model, sweep, common.trace ? &tracer : nullptr, time_s).dump(2) << '\n';
  } else if (common.format == Format::csv) {
    print_jansen_csv(std::cout, model, sweep);
  } else {
    print_text(std::cout, name, solver, model, sweep, time_s);
  }
}

}  // namespace

int MechanismCommand::run() const {
  // 1. Every flag and every output file checked before any work (docs/cli.md, "Which flags apply where").
  const CommonOptions common = checked_common_options(common_, "mechanism");
  const std::string file = linkage_file();
  const bool from_file = !file.empty();
  check_flags(common, from_file);
  if (explain_) return explain(common, file);
  if (analyse_) return analyse(common, file);
  if (!crank_ && sweep_.empty() && drivers_.empty()) {
    throw std::invalid_argument("give --crank DEG, --sweep START:STOP:STEP or --drivers PATH.csv");
  }
  if (crank_ && !std::isfinite(*crank_)) throw std::invalid_argument("--crank must be a finite number of degrees");
  const SweepRange range = crank_ ? SweepRange{*crank_, *crank_, 1.0} : drivers_.empty() ? parse_sweep(sweep_) : SweepRange{0.0, 0.0, 1.0};
  if (!beest_.empty()) require_full_turn(range);
  const OutputPaths paths = checked_outputs(common, file);
  // 2. One dispatch: every linkage is swept through the same interface.
  const SweepLinkage sweep = from_file ? &MechanismCommand::sweep_file
                             : name_ == "mustang" ? &MechanismCommand::sweep_mustang
                                                  : &MechanismCommand::sweep_jansen;
  return (this->*sweep)(common, range, paths, file);
}

// The description file NAME stands for; empty for the built-in jansen, jansen10 and mustang.
std::string MechanismCommand::linkage_file() const {
  const std::string file = built_in(name_) ? std::string() : linkage_file_for(name_);
  if (!built_in(name_) && file.empty()) {
    throw std::invalid_argument("mechanism name '" + printable(std::string_view(name_).substr(0, 40)) + (name_.size() > 40 ? "...'" : "'") +
                                ": not jansen, jansen10, mustang, a shipped model (numlab models) or a file");
  }
  return file;
}

// Each flag given only where it applies, each file flag with a name.
void MechanismCommand::check_flags(const CommonOptions& common, bool from_file) const {
  for (const auto* flag : {"--explain", "--check-jacobian", "--arrows", "--strict", "--at-crossing", "--analyse", "--output", "--speed",
                           "--draw-at", "--path", "--chart", "--drivers"}) {
    require_applies(given(*command_, flag), from_file, flag, "a linkage description file or shipped model");
  }
  for (const auto* flag : {"--draw-at", "--speed"}) {
    require_applies(given(*command_, flag), drivers_.empty(), flag, "--crank or --sweep (not a --drivers path)");
  }
  for (const auto* flag : {"--trace", "--step"}) {
    require_applies(given(common, flag), drivers_.empty(), flag, "--crank or --sweep (not a --drivers path)");
  }
  require_applies(given(*command_, "--draw-at"), !svg_.empty(), "--draw-at", "--svg FILE");
  require_applies(given(*command_, "--path"), !svg_.empty() || !animate_.empty(), "--path", "--svg FILE or --animate FILE");
  require_applies(given(*command_, "--chart"), !sweep_.empty(), "--chart", "--sweep (it charts the sweep)");
  if (given(*command_, "--chart") && chart_.empty()) throw std::invalid_argument("--chart needs a file name");
  require_applies(given(*command_, "--arrows"), svg_.empty() == false, "--arrows", "--svg FILE");
  require_applies(given(*command_, "--beest"), !from_file, "--beest", "numlab mechanism jansen and jansen10");
  require_applies(given(*command_, "--linear"), solver_ == "full", "--linear", "--solver full");
  require_applies(given(common, "--tol"), solver_ != "analytic", "--tol", "the iterative solvers (not analytic)");
  require_applies(given(common, "--max-iter"), solver_ != "analytic", "--max-iter", "the iterative solvers (not analytic)");
  require_applies(given(*command_, "--beest-animated"), !beest_.empty(), "--beest-animated", "--beest FILE");
  require_applies(given(common, "--out"), !svg_.empty() || !animate_.empty() || !beest_.empty() || !html_.empty() || !chart_.empty(),
                  "--out", "--svg, --animate, --beest, --html or --chart (the folder for the files they name)");
  require_applies(given(*command_, "--html"), !sweep_.empty(), "--html", "--sweep START:STOP:STEP (a page scrubs a sweep; "
                                                                        "one pose is --svg's)");
  for (const auto& [flag, value] : {std::pair{"--svg", &svg_}, std::pair{"--animate", &animate_}, std::pair{"--beest", &beest_},
                                    std::pair{"--html", &html_}}) {
    if (given(*command_, flag) && value->empty()) throw std::invalid_argument(std::string(flag) + " needs a file name");
  }
  if (explain_ && analyse_) throw std::invalid_argument("--explain and --analyse each print a report and stop: give one");
  if (given(*command_, "--speed")) (void)parse_speed(speed_);  // checked before any work
  if (given(*command_, "--beest-animated") && !(beest_seconds_ > 0.0 && std::isfinite(beest_seconds_))) {
    throw std::invalid_argument("--beest-animated: the stride time must be a positive number of seconds");
  }
}

// --explain: the derived model of a description file, no solve.
int MechanismCommand::explain(const CommonOptions& common, const std::string& file) const {
  for (const auto* flag : {"--crank", "--sweep", "--solver", "--linear", "--svg", "--animate", "--check-jacobian", "--strict",
                           "--at-crossing", "--output", "--speed", "--html", "--draw-at", "--path", "--chart", "--drivers"}) {
    require_applies(given(*command_, flag), false, flag, "a solve, not --explain");
  }
  for (const auto* flag : {"--trace", "--step", "--tol", "--max-iter", "--out"}) {
    require_applies(given(common, flag), false, flag, "a solve, not --explain");
  }
  if (common.format == Format::csv) throw std::invalid_argument("--explain prints text or JSON, not CSV");
  LinkageRun run;
  run.file = file;
  run.explain = true;
  run.common = common;
  return run_linkage(run);
}

// --analyse: a four-bar's or slider-crank's analysis from the model, no sweep asked for.
int MechanismCommand::analyse(const CommonOptions& common, const std::string& file) const {
  for (const auto* flag : {"--crank", "--sweep", "--solver", "--linear", "--svg", "--animate", "--check-jacobian", "--at-crossing",
                           "--speed", "--html", "--draw-at", "--path", "--chart", "--drivers"}) {
    require_applies(given(*command_, flag), false, flag, "a solve, not --analyse");
  }
  for (const auto* flag : {"--trace", "--step", "--tol", "--max-iter", "--out"}) {
    require_applies(given(common, flag), false, flag, "a solve, not --analyse");
  }
  if (common.format == Format::csv) throw std::invalid_argument("--analyse prints text or JSON, not CSV");
  LinkageRun run;
  run.file = file;
  run.analyse = true;
  run.output = output_;
  run.strict = strict_;
  run.common = common;
  return run_linkage(run);
}

// The output files inside --out, checked writable (and not the description file) before any work.
MechanismCommand::OutputPaths MechanismCommand::checked_outputs(const CommonOptions& common, const std::string& file) const {
  const OutputPaths paths{output_path(common, svg_), output_path(common, animate_), output_path(common, beest_),
                          output_path(common, html_), output_path(common, chart_)};
  std::vector<PlannedFile> outputs;
  for (const auto& [path, flag] : {std::pair{paths.svg, "--svg"}, std::pair{paths.animate, "--animate"}, std::pair{paths.beest, "--beest"},
                                   std::pair{paths.html, "--html"}}) {
    if (!path.empty()) outputs.push_back({path, flag});
  }
  if (!paths.chart.empty()) {
    const auto chart = planned_files(chart_files(paths.chart), "--chart");
    outputs.insert(outputs.end(), chart.begin(), chart.end());
  }
  check_outputs(outputs, !file.empty() ? std::vector<std::string>{file} : std::vector<std::string>{});
  return paths;
}

// A description file or shipped model, solved by the linkage command (which reads --crank or --sweep itself).
int MechanismCommand::sweep_file(const CommonOptions& common, const SweepRange&, const OutputPaths& paths,
                                 const std::string& file) const {
  LinkageRun run;
  run.file = file;
  run.driver = crank_;
  run.sweep = sweep_;
  run.drivers = drivers_;
  run.solver = solver_;
  run.linear = linear_;
  run.linear_given = given(*command_, "--linear");
  run.check_jacobian = check_jacobian_;
  run.arrows = arrows_;
  run.strict = strict_;
  run.switch_at_crossing = at_crossing_ == "switch";
  run.output = output_;
  if (given(*command_, "--speed")) run.speed_rad_s = parse_speed(speed_);
  run.common = common;
  run.svg = paths.svg;
  run.animate = paths.animate;
  run.html = paths.html;
  run.draw_at = draw_at_;
  run.paths = paths_;
  run.chart = paths.chart;
  run.name = name_;
  return run_linkage(run);
}

// Seed 003's Mustang roof linkage: sweep, write the files, print the report.
int MechanismCommand::sweep_mustang(const CommonOptions& common, const SweepRange& range, const OutputPaths& paths,
                                    const std::string&) const {
  if (!beest_.empty()) throw std::invalid_argument("--beest draws the Jansen leg's beest, not the mustang");
  return run_mustang({range.start, range.stop, range.step, solver_, linear_, common, paths.svg, paths.animate, paths.html});
}

// The Jansen leg (8 or 10 equations): sweep, write the files, print the report.
int MechanismCommand::sweep_jansen(const CommonOptions& common, const SweepRange& range, const OutputPaths& paths,
                                   const std::string&) const {
  const JansenModel model = name_ == "jansen" ? JansenModel::eight_equations : JansenModel::ten_equations;

  nonlinear::NewtonOptions options;
  if (common.tolerance) options.residual_tolerance = *common.tolerance;
  if (common.max_iterations) options.max_iterations = *common.max_iterations;
  const auto solver = mechanisms::make_jansen_solver(model, solver_, linear_, options);
  // --trace: every pose attempt, printed as it happens (stderr) or kept for the JSON;
  // --step shows each one on stderr in every format and pauses after it. The time leaves out the pauses.
  StepPause pause(common.step);
  Tracer tracer(common.trace && (common.step || common.format != Format::json) ? &std::cerr : nullptr, &pause);
  const auto begin = std::chrono::steady_clock::now();
  mechanisms::JansenSweepStepper stepper(model, *solver);
  if (common.trace) stepper.set_observer(&tracer);
  stepper.start(range.start, range.stop, range.step);
  while (stepper.step()) {  // one pose (the walk-in's included)
  }
  const mechanisms::JansenSweep sweep = mechanisms::checked_sweep(model, stepper.result());
  if (pause.stopped()) {
    nlohmann::ordered_json attempts = nlohmann::ordered_json::array();
    for (const auto& attempt : tracer.attempts()) attempts.push_back(attempt_json(attempt));
    return report_stopped(common, {{"mechanism", name_}, {"solver", solver_}}, attempts);
  }
  const double time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count() - pause.seconds_waited();

  // Files, then the report.
  if (!sweep.poses.empty()) {
    FileBatch files;  // all of them in place, or none (a full disk)
    if (!paths.svg.empty()) files.add(paths.svg, jansen_pose_svg(sweep, 0));
    if (!paths.animate.empty()) files.add(paths.animate, jansen_animation_svg(sweep, 4.0));
    if (!paths.beest.empty()) files.add(paths.beest, beest_svg(sweep, beest_seconds_));
    if (!paths.html.empty()) {
      const auto data = jansen_page_data(name_, model, sweep, "numlab mechanism " + name_ + " --format csv");
      files.add(paths.html, linkage_page_html(data, jansen_pose_svg(sweep, 0),
                                              "the leg at the sweep's first pose (the page without scripts)"));
    }
    files.commit();
  }
  print_jansen_report(common, name_, solver_, model, sweep, tracer, time_s);
  return exit_code_for(sweep.status);
}

}  // namespace numlab::cli
