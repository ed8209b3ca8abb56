// Lab `linkage`: a linkage read from a description file (docs/linkage-files.md). The shipped
// jansen.toml carries the story: the model numlab derives from it, every solver over a crank cycle,
// the velocities and accelerations checked, the scene, and the seeds' hand-written models beside
// it. The shipped mustang.toml shows a dyad approaching its assembly limit, parallelogram.toml two
// branches crossing.

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <tuple>

#include "bench/timing.hpp"
#include "output/exit_codes.hpp"
#include "output/files.hpp"
#include "output/format.hpp"
#include "methods/data_dir.hpp"
#include "output/linkage_report.hpp"
#include "lessons/lab.hpp"
#include "lessons/linkage_cycle.hpp"
#include "lessons/linkage_sentences.hpp"
#include "numlab/mechanisms/closed_forms/whitworth.hpp"
#include "numlab/mechanisms/crank_angle.hpp"
#include "numlab/mechanisms/jansen10_closure.hpp"
#include "numlab/mechanisms/jansen_solvers.hpp"
#include "numlab/linalg/matrix_file.hpp"
#include "numlab/mechanisms/linkage/crank_analysis.hpp"
#include "numlab/mechanisms/linkage/link_motion.hpp"
#include "numlab/mechanisms/linkage/linkage_statics.hpp"
#include "numlab/mechanisms/linkage/linkage_structure.hpp"
#include "scenes/linkage_scene.hpp"

namespace numlab::cli {

namespace {

using namespace mechanisms;
using mechanisms::degrees;
constexpr double cycle_tolerance = 1e-10;      // every cycle's Newton tolerance (as `numlab bench jansen`)
constexpr int cycle_poses = 360;               // one turn, 1 degree apart
const TimingPlan lab_timing{5, 200, 0.03};     // at least 5 runs and 30 ms per median; `numlab bench` measures longer

std::string lab_file(LabSession& session, const std::string& name, const std::string& contents) {
  ensure_directory(session.folder());
  const std::string path = session.folder() + "/" + name;
  write_file_atomically(path, contents);
  return path;
}

const std::string& joint_name(const LinkageModel& model, int joint) {
  return model.description().joints[static_cast<std::size_t>(joint)].name;
}

std::string joint_list(const LinkageModel& model, const std::vector<int>& joints) {
  std::vector<std::string> names;
  for (int j : joints) names.push_back(joint_name(model, j));
  return fmt::format("{}", fmt::join(names, ", "));
}

// Joint `name`'s 2-vector out of a vector of unknowns (positions, velocities or accelerations).
// A dyad's side in words: left or right of the line between its centres (circle-circle), ahead of or
// behind the foot of its centre along its line (circle-line).
std::string side_name(const LinkageSolver& solver, std::size_t block, int side) {
  if (solver.blocks()[block].kind == BlockKind::circle_line) return side > 0 ? "ahead" : "behind";
  return side > 0 ? "left" : "right";
}

Eigen::Vector2d joint_part(const LinkageModel& model, const Eigen::VectorXd& v, const std::string& name) {
  const int column = model.column_of(model.description().joint_index(name));
  return {v(column), v(column + 1)};
}

// The largest distance of any joint of jansen.toml's pose q from seed 000's closed form (its joints
// are named O, P1, A ... F as in the hand-written leg).
double distance_from_seed_closed_form(const LinkageModel& model, double crank_deg, const Eigen::VectorXd& q) {
  static const JansenLeg leg;
  const auto exact = leg.closed_form_joints(crank_deg * degrees);
  if (!exact) return INFINITY;
  const JointPositions joints = model.positions(q);
  double worst = 0.0;
  for (int k = 0; k < jansen_joint_count; ++k) {
    const int index = model.description().joint_index(jansen_joint_names[static_cast<std::size_t>(k)]);
    worst = std::max(worst, (joints[static_cast<std::size_t>(index)] - (*exact)[static_cast<std::size_t>(k)]).norm());
  }
  return worst;
}

LinkageSolver make_solver(const LinkageModel& model, const std::string& solver) {
  LinkageSolverOptions options;
  options.solver = solver;
  options.newton.residual_tolerance = cycle_tolerance;
  options.tolerance_relative_to_size = false;  // the seeds' models' absolute tolerance
  options.newton.max_iterations = 100;
  return LinkageSolver(model, options);
}

// One solver over the cycle: the median time of solve_linkage_cycle, its iterations, its worst
// distance from seed 000's closed form.
struct CycleRow {
  std::string solver;
  double time_s = 0.0;
  int iterations = 0;
  double error = 0.0;
  Status status = Status::converged;
};
CycleRow time_cycle(const LinkageModel& model, const std::string& name, double start_deg) {
  const LinkageSolver solver = make_solver(model, name);
  const LinkageCycle cycle = solve_linkage_cycle(solver, start_deg, 1.0, cycle_poses);
  CycleRow row{name, 0.0, cycle.iterations, 0.0, cycle.status};
  for (int k = 0; k < cycle.solved; ++k) {
    row.error = std::max(row.error, distance_from_seed_closed_form(model, cycle.driver[static_cast<std::size_t>(k)],
                                                                   cycle.q.col(k)));
  }
  if (cycle.solved < cycle_poses) row.error = INFINITY;
  row.time_s = median_time([&] { return solve_linkage_cycle(solver, start_deg, 1.0, cycle_poses); }, lab_timing);
  return row;
}

const CycleRow& row_of(const std::vector<CycleRow>& rows, const std::string& solver) {
  return *std::find_if(rows.begin(), rows.end(), [&](const CycleRow& r) { return r.solver == solver; });
}

// A seed's hand-written model over the same cycle by full Newton (GEPP), as `numlab bench jansen`
// times it: mechanisms::solve_crank_sweep alone; the errors from crank_sweep afterwards, untimed.
struct HandCodedCycle {
  double time_s = 0.0;
  int iterations = 0;
  double error = 0.0;
};
HandCodedCycle time_hand_coded_cycle(JansenModel model) {
  nonlinear::NewtonOptions options;
  options.residual_tolerance = cycle_tolerance;
  options.max_iterations = 100;
  const auto solver = make_jansen_solver(model, "full", "gepp", options);
  const double start = JansenClosure::seed_crank_angle / degrees, stop = start + cycle_poses - 1;
  const JansenSweepAngles solved = solve_crank_sweep(model, *solver, start, stop, 1.0);
  HandCodedCycle cycle;
  for (const auto& outcome : solved.outcomes) cycle.iterations += outcome.iterations;
  const JansenSweep checked = crank_sweep(model, *solver, start, stop, 1.0);
  cycle.error = checked.status == Status::converged ? checked.worst_closed_form_distance : INFINITY;
  cycle.time_s = median_time([&] { return solve_crank_sweep(model, *solver, start, stop, 1.0); }, lab_timing);
  return cycle;
}

// Step 1.
void show_derived_model(LabSession& session, const LinkageModel& model, const std::string& file) {
  print_explanation(session.out(), model, Format::text);
  session.out() << '\n';
  const auto blocks = linkage_blocks(model);
  Table table({"block", "joints", "from", "kind", "size"});
  DerivedModelSummary summary{file, static_cast<int>(model.moving().size()), model.unknown_count(),
                              model.equation_count(), gruebler_kutzbach(model.description()).mobility, {}};
  for (std::size_t b = 0; b < blocks.size(); ++b) {
    const auto size = blocks[b].rows_and_columns.unknowns.size();
    table.add_row({std::to_string(b + 1), joint_list(model, blocks[b].joints), joint_list(model, blocks[b].known_joints),
                   std::string(to_string(blocks[b].kind)), fmt::format("{}x{}", size, size)});
    summary.block_kinds.emplace_back(to_string(blocks[b].kind));
  }
  session.show(table, "blocks");
  Table counts({"file", "moving joints", "unknowns", "equations", "mobility"});
  counts.add_row({file, std::to_string(summary.moving_joints), std::to_string(summary.unknowns),
                  std::to_string(summary.equations), std::to_string(summary.mobility)});
  session.show(counts, "model");
  session.say(derived_model_sentence(summary));
}

// Step 2.
std::vector<CycleRow> show_solvers_compared(LabSession& session, const LinkageModel& model, double start_deg) {
  std::vector<CycleRow> rows;
  for (const std::string solver : {"full", "sequential", "analytic", "gsl-newton"}) rows.push_back(time_cycle(model, solver, start_deg));
  const double analytic = row_of(rows, "analytic").time_s;
  Table table({"solver", "time per cycle", "per pose", "x closed form", "iterations", "distance from seed 000"});
  double worst = 0.0;
  for (const CycleRow& row : rows) {
    table.add_row({row.solver, fmt::format("{:.3g} s", row.time_s), fmt::format("{:.3g} us", row.time_s / cycle_poses * 1e6),
                   fmt::format("{:.2f}", row.time_s / analytic), std::to_string(row.iterations), scientific(row.error)});
    worst = std::max(worst, row.error);
  }
  session.show(table, "cycle-comparison");
  const auto cost = [&](const std::string& solver, const std::string& name) {
    const CycleRow& row = row_of(rows, solver);
    return SolverCost{name, row.time_s, row.iterations};
  };
  const SolverCost full = cost("full", "full Newton");
  session.say(fmt::format("Every solver's worst joint distance from seed 000's closed form is at most {:.2g}: {}.",
                          worst, worst < 1e-6 ? "all four find the seed's leg on the seed's branch" : "a solver leaves the seed's branch"));
  session.say(sequential_against_full_sentence(cost("sequential", "sequential Newton"), full, model.unknown_count()));
  session.say(same_method_sentence({"full Newton (hand-written GEPP)", full.time_s, full.iterations},
                                   cost("gsl-newton", "GSL's newton on the same Phi and J")));
  session.say(closed_form_sentence(full, cost("analytic", "the closed form"), cycle_poses));
  return rows;
}

// Step 3: the derivatives at eight poses of the sweep, against finite differences and seed 000.
bool show_derivative_check(LabSession& session, const LinkageSolver& solver, const LinkageSweep& sweep) {
  const LinkageModel& model = solver.model();
  const JansenLeg leg;
  Table table({"crank (deg)", "|v_F| (per rad)", "seed 000's |v_F|", "velocity vs central difference", "|a_F| (per rad^2)",
               "acceleration vs 7-point stencil"});
  std::vector<DerivativeRow> rows;
  bool solved = true;
  for (const LinkagePose& pose : sweep.poses) {
    if (std::fmod(pose.driver, 45.0) != 0.0 || pose.outcome.status != Status::converged) continue;
    const double t = model.driver_from_user(pose.driver);
    const DerivativeCheck check = check_derivatives(solver, t, pose.q);
    solved = solved && check.solved;
    const auto exact = leg.closed_form_joints(t);
    const Eigen::VectorXd angles = jansen_angles_of(JansenModel::eight_equations, *exact,
                                                    Eigen::VectorXd(JansenClosure::seed_estimates()));
    const double seed_speed = leg.rates(t, JansenAngles(angles)).foot_speed;
    const DerivativeRow row{pose.driver, check.velocity_difference / std::max(1.0, check.velocity_scale),
                            check.acceleration_difference / std::max(1.0, check.acceleration_scale),
                            joint_part(model, pose.velocity, "F").norm(), seed_speed};
    rows.push_back(row);
    table.add_row({fmt::format("{:g}", row.crank_deg), fmt::format("{:.6f}", row.foot_speed), fmt::format("{:.6f}", seed_speed),
                   scientific(row.velocity_difference), fmt::format("{:.4f}", joint_part(model, pose.acceleration, "F").norm()),
                   scientific(row.acceleration_difference)});
  }
  session.show(table, "derivatives");
  session.say(derivative_check_sentence(rows, "The foot F"));
  return solved;
}

// Step 4: mustang.toml towards its upper limit.
bool show_limit_approach(LabSession& session) {
  const LinkageModel model(read_linkage_description(models_dir() + "/mustang.toml"));
  const LinkageSolver solver = make_solver(model, "full");
  const LinkageSweep coarse = linkage_sweep(solver, 50.0, 57.0, 0.5);
  const auto upper = std::find_if(coarse.limits.begin(), coarse.limits.end(), [](const LinkageLimit& l) { return l.upper; });
  if (upper == coarse.limits.end() || upper->block < 0) {
    session.say("The sweep 50:57:0.5 found no upper limit with a block named: nothing to approach.");
    return false;
  }
  const LinkageBlock& block = solver.blocks()[static_cast<std::size_t>(upper->block)];
  const std::string joint = joint_name(model, block.joints.front());
  LimitApproach approach{upper->driver, upper->bracket,
                         fmt::format("block {} ({})", upper->block + 1, describe_block(model, block)), joint, {}};
  session.out() << fmt::format("  sweep 50:57:0.5 deg: {} poses, upper limit {:.4f} deg (bracket {:.2g} deg), block {}\n\n",
                               coarse.poses.size(), upper->driver, upper->bracket, upper->block + 1);
  Table table({"before the limit (deg)", "crank (deg)", "mu_" + joint + " (deg)", "dyad margin", "kappa(J)",
               "|v_" + joint + "| (per rad)"});
  bool solved = true;
  for (const double before : {5.0, 2.0, 1.0, 0.5, 0.2, 0.1, 0.05, 0.02, 0.01, 0.0}) {
    const double crank = upper->driver - before;
    const LinkageSweep one = linkage_sweep(solver, crank, crank, 1.0);
    const LinkagePose& pose = one.poses.front();
    if (pose.outcome.status != Status::converged) {
      solved = false;
      continue;
    }
    const std::size_t b = static_cast<std::size_t>(upper->block);
    const LimitApproachRow row{before, pose.transmission_deg[b], pose.condition, joint_part(model, pose.velocity, joint).norm()};
    approach.rows.push_back(row);
    table.add_row({fmt::format("{:g}", before), fmt::format("{:.4f}", crank), fmt::format("{:.3g}", row.mu_deg),
                   scientific(solver.dyad_margins(pose.q)[b]), scientific(row.kappa), fmt::format("{:.4g}", row.speed)});
  }
  session.show(table, "limit-approach");
  session.say(limit_approach_sentence(approach, 1.0, 0.1));
  // The linkage 0.01 deg below the limit, after a turn of 56 deg towards it.
  const double last = upper->driver - 0.01;
  const LinkageSweep towards = linkage_sweep(solver, last - 56.0, last, 1.0);
  if (towards.poses.back().outcome.status == Status::converged) {
    const std::string path = lab_file(session, "mustang-toml-near-limit.svg",
                                      linkage_pose_svg(model, towards, towards.poses.size() - 1, true));
    session.figure(path, fmt::format("mustang.toml at {:.4f} deg, 0.01 deg below its limit: the links at {} nearly in "
                                     "line, the joints' paths over the {:g} deg before, velocities as arrows",
                                     last, joint, last - towards.poses.front().driver));
  }
  return solved && towards.status == Status::converged;
}

// Step 5: parallelogram.toml through its crossing at crank 0, on the smooth branch and on the other.
bool show_crossing(LabSession& session) {
  const LinkageModel model(read_linkage_description(models_dir() + "/parallelogram.toml"));
  const LinkageSolver solver(model, LinkageSolverOptions{});
  constexpr double from = -10.0, to = 10.0, step = 2.0;
  const LinkageSweep smooth = linkage_sweep(solver, from, to, step);
  // The other branch on each side: sweeps that switch at the crossing, one from either end.
  const LinkageSweep up = linkage_sweep(solver, from, to, step, {}, AtCrossing::switch_branch);
  const LinkageSweep down = linkage_sweep(solver, to, from, -step, {}, AtCrossing::switch_branch);
  if (smooth.status != Status::converged || up.status != Status::converged || down.status != Status::converged ||
      smooth.crossings.size() != 1) {
    session.say("The sweeps through the parallelogram's crossing did not all converge: nothing to compare.");
    return false;
  }
  const std::size_t b = static_cast<std::size_t>(smooth.crossings.front().block);
  const std::string joint = joint_name(model, solver.blocks()[b].joints.front());
  const auto velocity_of = [&](const LinkagePose& pose) { return joint_part(model, pose.velocity, joint); };
  Table table({"crank (deg)", "x_" + joint, "y_" + joint, "side", "kappa(J)", "v_" + joint + " (per rad)",
               "other branch v_" + joint});
  const std::size_t n = smooth.poses.size();
  for (std::size_t k = 0; k < n; ++k) {
    const LinkagePose& pose = smooth.poses[k];
    const LinkagePose& other = pose.driver < 0.0 ? down.poses[n - 1 - k] : up.poses[k];  // the switched sweeps' poses
    const Eigen::Vector2d p = joint_part(model, pose.q, joint), v = velocity_of(pose), w = velocity_of(other);
    const std::string side = pose.driver == 0.0 ? "on the crossing" : side_name(solver, b, pose.signature[b]);
    table.add_row({fmt::format("{:g}", pose.driver), fmt::format("{:.6f}", p.x()), fmt::format("{:.6f}", p.y()), side,
                   scientific(pose.condition), fmt::format("({:.4f}, {:.4f})", v.x(), v.y()),
                   pose.driver == 0.0 ? "-" : fmt::format("({:.4f}, {:.4f})", w.x(), w.y())});
  }
  session.show(table, "crossing");
  const std::size_t at = n / 2;  // crank 0
  const LinkageCrossing& crossing = smooth.crossings.front();
  const CrossingPassage passage{crossing.driver, smooth.poses[at].condition, smooth.poses[0].condition, joint,
                                side_name(solver, b, crossing.side_before), side_name(solver, b, crossing.side_after),
                                velocity_of(smooth.poses[at - 1]), velocity_of(smooth.poses[at + 1]),
                                velocity_of(up.poses[at + 1]), step};
  session.say(crossing_sentence(passage));
  const std::string path = lab_file(session, "parallelogram-crossing.svg", linkage_animation_svg(model, up, 2.0));
  session.figure(path, "parallelogram.toml from -10 to 10 deg with --at-crossing switch: at crank 0 it turns into the "
                       "anti-parallelogram (animated)");
  return true;
}

// Step 7: seed 001's 10 angles, seed 000's 8 angles and jansen.toml's joint coordinates.

void show_over_modelling(LabSession& session, const LinkageModel& model, const CycleRow& derived_full) {
  const JansenLeg leg;
  const double seed_angle = JansenClosure::seed_crank_angle;
  const auto exact = leg.closed_form_joints(seed_angle);
  const auto nonzeros = [](const auto& J) { return static_cast<int>((J.array() != 0.0).count()); };
  // Every Jacobian at seed 000's pose (crank 1.57 rad).
  const Jansen10Closure ten(seed_angle);
  Jansen10Closure::Matrix J10;
  ten.jacobian(Jansen10Closure::Vector(jansen_angles_of(JansenModel::ten_equations, *exact,
                                                         jansen_seed_estimates(JansenModel::ten_equations, leg))),
               J10);
  const JansenClosure eight(seed_angle);
  JansenClosure::Matrix J8;
  eight.jacobian(JansenClosure::Vector(jansen_angles_of(JansenModel::eight_equations, *exact,
                                                        Eigen::VectorXd(JansenClosure::seed_estimates()))),
                 J8);
  JointPositions joints = model.rough_positions();
  for (int k = 0; k < jansen_joint_count; ++k) {
    joints[static_cast<std::size_t>(model.description().joint_index(jansen_joint_names[static_cast<std::size_t>(k)]))] =
        (*exact)[static_cast<std::size_t>(k)];
  }
  Eigen::MatrixXd J;
  model.jacobian(model.unknowns(joints), seed_angle, J);

  std::vector<ModelCost> rows;
  for (const JansenModel hand : {JansenModel::ten_equations, JansenModel::eight_equations}) {
    const bool is_ten = hand == JansenModel::ten_equations;
    const HandCodedCycle cycle = time_hand_coded_cycle(hand);
    rows.push_back({is_ten ? "seed 001, 10 angles" : "seed 000, 8 angles", is_ten ? 10 : 8,
                    is_ten ? nonzeros(J10) : nonzeros(J8), cycle.time_s, cycle.iterations, cycle.error});
  }
  rows.push_back({"jansen.toml, joint coordinates", model.unknown_count(), nonzeros(J), derived_full.time_s,
                  derived_full.iterations, derived_full.error});
  Table table({"model", "unknowns", "equations", "Jacobian nonzeros", "time per cycle", "iterations",
               "distance from seed 000"});
  for (const ModelCost& row : rows) {
    table.add_row({row.name, std::to_string(row.unknowns), std::to_string(row.unknowns),
                   fmt::format("{} of {}", row.nonzeros, row.unknowns * row.unknowns), fmt::format("{:.3g} s", row.time_s),
                   std::to_string(row.iterations), scientific(row.error)});
  }
  session.show(table, "over-modelling");
  session.say(over_modelling_sentence(rows));
}

}  // namespace

// Step 8: four-bar.toml under a torque on its rocker and a mass at B: the driver torque from the
// Lagrange multipliers against virtual work and against the slope of the loads' potential.
double load_potential(const LinkageModel& model, const Eigen::VectorXd& q, const std::vector<LinkLine>& lines,
                      const Eigen::VectorXd& q_reference) {
  const auto joints = joint_motions(model, q, {}, {});
  const auto reference = joint_motions(model, q_reference, {}, {});
  double V = 0.0;
  for (const LoadSpec& load : model.description().loads) {
    if (load.kind == LoadKind::force) V -= load.force.dot(joints[static_cast<std::size_t>(load.joint)].p);
    if (load.kind == LoadKind::mass) V += load.mass * model.description().gravity * joints[static_cast<std::size_t>(load.joint)].p.y();
    if (load.kind == LoadKind::torque) {  // -T theta, theta measured from the reference pose's (no wrap)
      const LinkLine& line = lines[static_cast<std::size_t>(load.line)];
      const auto angle = [&](const std::vector<JointMotion>& j) {
        return angular_motion(j[static_cast<std::size_t>(line.from)], j[static_cast<std::size_t>(line.to)]).angle;
      };
      V -= load.torque * std::remainder(angle(joints) - angle(reference), 2.0 * std::numbers::pi);
    }
  }
  return V;
}

bool show_driving_torque(LabSession& session) {
  const std::string loads = "\n[[load]]\nlink = \"Q-B\"\ntorque = -10.0\n\n[[load]]\njoint = \"B\"\nmass = 2.0\n";
  const LinkageModel model(parse_linkage_description(linalg::read_text_file(models_dir() + "/four-bar.toml") + loads,
                                                     "four-bar.toml with loads"));
  const LinkageSolver solver = make_solver(model, "full");
  const LinkageSweep sweep = linkage_sweep(solver, 0.0, 359.0, 1.0);
  const auto lines = link_lines(model.description());
  LinkageStaticsSolver statics(model);
  std::vector<Eigen::Vector2d> applied(model.description().joints.size());
  Table table({"crank (deg)", "tau by multipliers", "by virtual work", "difference", "by dV/dtheta", "difference"});
  std::vector<DrivingTorqueRow> rows;
  bool solved = true;
  for (const LinkagePose& pose : sweep.poses) {
    if (std::fmod(pose.driver, 45.0) != 0.0 || pose.outcome.status != Status::converged) continue;
    const LinkageStatics& s = statics.solve(pose);
    // Virtual work: the loads as forces at the joints (the torque as a couple), times the joints' velocities.
    applied_joint_forces(model, pose.q, applied);
    const auto joints = joint_motions(model, pose.q, pose.velocity, pose.acceleration);
    double power = 0.0, scale = 0.0;
    for (std::size_t j = 0; j < applied.size(); ++j) power += applied[j].dot(joints[j].v), scale += std::abs(applied[j].dot(joints[j].v));
    // The potential's slope: positions solved at theta +- h.
    const double t = model.driver_from_user(pose.driver), h = 1e-4;
    const LinkageSolution plus = solver.solve(t + h, pose.q + h * pose.velocity);
    const LinkageSolution minus = solver.solve(t - h, pose.q - h * pose.velocity);
    solved = solved && s.status == StaticsStatus::equilibrium && plus.outcome.status == Status::converged &&
             minus.outcome.status == Status::converged;
    const double slope = (load_potential(model, plus.q, lines, pose.q) - load_potential(model, minus.q, lines, pose.q)) / (2.0 * h);
    const DrivingTorqueRow row{pose.driver, s.driver, -power, slope, scale};
    rows.push_back(row);
    table.add_row({fmt::format("{:g}", row.crank_deg), fmt::format("{:.10g}", row.multipliers), fmt::format("{:.10g}", row.virtual_work),
                   scientific(std::abs(row.multipliers - row.virtual_work) / scale), fmt::format("{:.10g}", row.potential),
                   scientific(std::abs(row.multipliers - row.potential) / scale)});
  }
  session.show(table, "driving-torque");
  session.say(driving_torque_sentence(rows));
  return solved && !rows.empty();
}

// Step 9: whitworth.toml's ram toggles and time ratio by --analyse's root finding, beside the closed
// form of closed_forms/whitworth.hpp (the ram's line through O4: A crossing O4's level).
bool show_quick_return(LabSession& session) {
  const LinkageModel model(read_linkage_description(models_dir() + "/whitworth.toml"));
  const LinkageSolver solver(model, LinkageSolverOptions{});
  const CrankAnalysis found = analyse_crank_mechanism(solver);  // the file's output: the ram C
  if (!found.crank_turns_fully || found.output_toggles.size() != 2) {
    session.say("whitworth.toml: the analysis found no two toggles of a full turn: " + found.classification + ".");
    return false;
  }
  // 1. The closed form from the file's own numbers.
  const auto& d = model.description();
  if (d.joint_index("O2") < 0 || d.joint_index("O4") < 0) {
    session.say("whitworth.toml has no pivots O2 and O4: no closed form to compare with.");
    return false;
  }
  const auto at = [&](const char* name) { return d.joints[static_cast<std::size_t>(d.joint_index(name))].position; };
  closed_forms::Whitworth whitworth;
  whitworth.O2 = at("O2"), whitworth.O4 = at("O4"), whitworth.crank = found.crank, whitworth.ram_height = at("O4").y();
  const closed_forms::QuickReturn exact = closed_forms::whitworth_quick_return(whitworth);
  // 2. Each toggle found beside the closed form's nearer one.
  Table toggles({"toggle", "crank by Brent (deg)", "closed form (deg)", "difference (deg)", found.output + "'s travel"});
  QuickReturnSummary summary{found.output, found.slow_stroke_deg, found.quick_stroke_deg, found.time_ratio, exact.time_ratio,
                             0.0, 0.0, 0.0, "sin theta = (y_O4 - y_O2) / r"};
  for (std::size_t k = 0; k < 2; ++k) {
    const Toggle& t = found.output_toggles[k];
    const auto gap = [&](double rad) { return std::abs(std::remainder(t.crank_deg - rad / degrees, 360.0)); };
    const double closed = std::remainder(gap(exact.toggle_1) < gap(exact.toggle_2) ? exact.toggle_1 : exact.toggle_2, 2.0 * std::numbers::pi) / degrees;
    const double difference = std::min(gap(exact.toggle_1), gap(exact.toggle_2));
    summary.toggle_difference = std::max(summary.toggle_difference, difference);
    toggles.add_row({std::to_string(k + 1), fmt::format("{:.9f}", t.crank_deg), fmt::format("{:.9f}", closed < 0.0 ? closed + 360.0 : closed),
                     scientific(difference), fmt::format("{:.6g}", t.output_value)});
  }
  session.show(toggles, "quick-return-toggles");
  // 3. The strokes and the time ratio.
  const std::size_t start = static_cast<std::size_t>(found.slow_stroke_start);
  summary.slow_from = found.output_toggles[start].output_value, summary.slow_to = found.output_toggles[1 - start].output_value;
  const double turn = std::abs(std::remainder(exact.toggle_2 - exact.toggle_1, 2.0 * std::numbers::pi)) / degrees;  // the shorter way
  Table strokes({"quantity", "by Brent", "closed form", "difference"});
  for (const auto& [name, value, closed] : {std::tuple{"slow stroke (deg of crank)", found.slow_stroke_deg, 360.0 - turn},
                                            std::tuple{"quick stroke (deg of crank)", found.quick_stroke_deg, turn},
                                            std::tuple{"time ratio", found.time_ratio, exact.time_ratio}}) {
    strokes.add_row({name, fmt::format("{:.9f}", value), fmt::format("{:.9f}", closed), scientific(std::abs(value - closed))});
  }
  session.show(strokes, "quick-return-strokes");
  session.say(quick_return_sentence(summary));
  // 4. The mechanism at the slow stroke's start, the ram's path over a turn.
  const double from = found.output_toggles[start].crank_deg;
  const LinkageSweep sweep = linkage_sweep(solver, from, from + 359.0, 1.0);
  if (sweep.status == Status::converged) {
    const std::string path = lab_file(session, "whitworth-toml.svg", linkage_pose_svg(model, sweep, 0, true));
    session.figure(path, fmt::format("whitworth.toml at crank {:.4f} deg, where the slow stroke starts: {} at {:.6g}, joint "
                                     "paths over the turn dashed",
                                     from, found.output, summary.slow_from));
  }
  return summary.toggle_difference < 1e-6 && std::abs(found.time_ratio - exact.time_ratio) < 1e-8 &&
         sweep.status == Status::converged;
}

int run_linkage_lab(LabSession& session) {
  const std::string file = "jansen.toml";
  const LinkageModel model(read_linkage_description(models_dir() + "/" + file));
  // The seeds' cycles start at their crank angle 1.57 rad; this one does too.
  const double start_deg = JansenClosure::seed_crank_angle / degrees;

  if (!session.begin_step("The model numlab derives from the file",
                          "jansen.toml describes seed 000's leg as ground joints, moving joints, five links and two rigid "
                          "triangles. numlab derives joint coordinates from it: the x and y of every moving joint are the "
                          "unknowns, each link gives one equation, each triangle one plus two for its third joint, and the "
                          "crank two. The Jacobian's pattern ('x': the row reads that unknown) orders the equations into "
                          "blocks that can be solved one after another (numlab mechanism jansen.toml --explain):")) return {};
  show_derived_model(session, model, file);

  if (!session.begin_step("Full, sequential, closed form and GSL over a crank cycle",
                          "360 poses, 1 degree apart from the seeds' crank angle 1.57 rad, Newton tolerance 1e-10; each "
                          "pose starts from the polynomial through the poses before it (as the seeds' models do in numlab "
                          "bench jansen). Full Newton solves all 12 equations at once (GEPP inside); sequential places "
                          "the crank and the body points by their formulas and solves each dyad by Newton with the 2x2 "
                          "closed-form inverse; the closed form "
                          "intersects circles block by block; GSL's newton is the same method, GSL's code. Times are "
                          "medians of a few repeated runs; 'distance from seed 000' is the worst distance of any joint "
                          "from the hand-written leg's circle intersections over the cycle.")) return {};
  const std::vector<CycleRow> cycle_rows = show_solvers_compared(session, model, start_deg);

  if (!session.begin_step("Velocity and acceleration, checked",
                          "Differentiating Phi(q(t); t) = 0 once and twice gives J qdot = -Phi_t and J qddot = gamma, two "
                          "linear solves with the Jacobian already at hand. At every 45 degrees of a turn they are compared "
                          "with finite differences of positions solved again by Newton (central, h = 1e-5 rad, for the "
                          "velocity; the 7-point stencil, h = 0.01 rad, for the acceleration), and the foot's speed with "
                          "the speed seed 000's own 8x8 rates give (its angles' J, a model written by hand).")) return {};
  const LinkageSolver full = make_solver(model, "full");
  const LinkageSweep sweep = linkage_sweep(full, 0.0, 359.0, 1.0);
  const bool derivatives_solved = show_derivative_check(session, full, sweep);

  if (!session.begin_step("A transmission angle approaching a limit",
                          "mustang.toml, seed 003's roof linkage, assembles only up to about 56.45 degrees of its input. A "
                          "sweep finds where it stops and bisects to 0.01 deg; the dyad that cannot close beyond it is "
                          "named. Then poses closer and closer to the limit: the dyad's transmission angle (between its two "
                          "links at its joint, 90 at best), its margin (how far its links are from lining up), kappa_2(J) of "
                          "the whole 20x20 model and the joint's speed per radian of input.")) return {};
  const bool limit_found = show_limit_approach(session);

  if (!session.begin_step("Two branches cross: the parallelogram four-bar",
                          "parallelogram.toml (crank = rocker, coupler = ground) lies flat at crank 0: every joint on the "
                          "ground line, J singular, and there its branch crosses the anti-parallelogram's. A sweep from "
                          "-10 to 10 deg lands on the crossing. Each pose is predicted by the quadratic through the poses "
                          "before it, which carries the smooth branch through; on the crossing itself J gives no velocity, so "
                          "the sweep takes it from positions solved along the branch. The last column is the other branch, "
                          "from sweeps with --at-crossing switch.")) return {};
  const bool crossing_followed = show_crossing(session);

  if (!session.begin_step("The scene",
                          "The leg at crank angle 0 with every moving joint's path over the turn and its velocity per "
                          "radian of crank as an arrow, and the turn animated (open the SVG files in a browser).")) return {};
  const std::string still = lab_file(session, "jansen-toml.svg", linkage_pose_svg(model, sweep, 0, true));
  const std::string animated = lab_file(session, "jansen-toml-animated.svg", linkage_animation_svg(model, sweep, 4.0));
  session.figure(still, "jansen.toml at crank angle 0: joint paths dashed, velocities as arrows");
  session.figure(animated, "one crank turn of jansen.toml, animated (4 s per turn)");

  if (!session.begin_step("Over-modelling: the same leg three ways",
                          "Seed 001 writes the leg as 10 loop-closure angles (a closure pair for the triangle D-E-F, which "
                          "is rigid), seed 000 as 8, and the file gives 12 joint coordinates. Each by full Newton (GEPP) over "
                          "the same cycle at the same tolerance, each timed as numlab bench jansen times the seeds' "
                          "models (the pose solves alone). 'Jacobian nonzeros' counts the entries of J that are not zero at seed 000's pose.")) return {};
  show_over_modelling(session, model, row_of(cycle_rows, "full"));

  if (!session.begin_step("The driving torque: Lagrange multipliers against virtual work",
                          "four-bar.toml with a torque of -10 on its rocker and 2 kg at B ([[load]] tables). The torque "
                          "the crank must apply to hold each pose still comes from one more linear solve with the "
                          "Jacobian already at hand: J^T lambda = Q, Q the loads as forces on the joints, and the driver's "
                          "load is lambda . Phi_t. Virtual work says the same from the velocities (tau + sum F . v_J = 0 "
                          "per radian), and so does the slope of the loads' potential V = -sum F . r_J - T theta, "
                          "differenced from positions solved at theta +- 1e-4 rad.")) return {};
  const bool torque_agrees = show_driving_torque(session);

  if (!session.begin_step("A quick-return: the ram's toggles and time ratio by root finding",
                          "whitworth.toml, a shaper's Whitworth drive: the crank O2-A is longer than the distance from "
                          "O2 to the slotted link's pivot O4, so the slotted link turns fully, slowly while A is on the "
                          "longer arc of the crank circle, beyond O4's level, and fast on the shorter, and a rod drives the "
                          "ram C. The ram stands still where its "
                          "velocity ratio dx_C/dtheta changes sign: numlab mechanism whitworth --analyse sweeps the crank "
                          "a turn in 1-degree steps, brackets each sign change and refines it by Brent's method (GSL) on "
                          "the ratio at poses solved to rounding, to 1e-10 rad. The closed form: with the ram's line "
                          "through O4, C stands still exactly when the slot lies along that line, when A crosses O4's "
                          "level.")) return {};
  const bool quick_return_found = show_quick_return(session);

  const bool cycles_converged = std::all_of(cycle_rows.begin(), cycle_rows.end(),
                                            [](const CycleRow& r) { return r.status == Status::converged; });
  return cycles_converged && sweep.status == Status::converged && derivatives_solved && limit_found && crossing_followed &&
                 torque_agrees && quick_return_found
             ? exit_success
             : exit_method_failed;
}

}  // namespace numlab::cli
