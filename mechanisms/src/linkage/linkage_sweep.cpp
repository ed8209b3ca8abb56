#include "numlab/mechanisms/linkage/linkage_sweep.hpp"

#include "numlab/mechanisms/linkage/linkage_conditioning.hpp"
#include "numlab/mechanisms/linkage/linkage_fast_solver.hpp"
#include "branch_predictor.hpp"
#include "linkage_crossings.hpp"

#include <fmt/format.h>

#include <Eigen/LU>
#include <Eigen/SVD>
#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <limits>
#include <stdexcept>

namespace numlab::mechanisms {

namespace {

constexpr double not_computed = std::numeric_limits<double>::quiet_NaN();  // a figure left out
constexpr int max_halvings = LinkageSweepOptions{}.max_halvings;  // a continuation step is halved at most this often
constexpr double crank_walk_deg = 2.0;   // the walk from the reference pose to the sweep's start
constexpr int slider_walk_steps = 50;
constexpr double crank_limit_deg = 0.01; // assembly limits to this bracket
constexpr int max_bisections = 60;

bool converged(const LinkageSolution& s) { return s.outcome.status == Status::converged; }

// The first-order predictor of continuation: q + qdot (next - at), qdot from J qdot = -Phi_t.
Eigen::VectorXd predicted(const LinkageModel& model, double at, const Eigen::VectorXd& q, double next) {
  const Eigen::VectorXd velocity = linkage_velocity(model, at, q);
  return velocity.allFinite() ? Eigen::VectorXd(q + velocity * (next - at)) : q;
}

}  // namespace

// The types of the sweep's state between poses, in a named namespace: LinkageSweepStepper::State
// holds them (an anonymous namespace's types may not be its fields).
namespace detail {

// The pose solves of a continuation: the fast path (linkage_fast_solver.hpp) where it applies, else
// the generic solver; both solve in place. The prediction is the quadratic through the last solved
// poses where there are three (branch_predictor.hpp: it carries the branch through singular poses),
// else the first-order tangent; a solved pose further from the quadratic's prediction than its
// error allows has jumped to another branch and is not accepted.
class PoseSolver {
 public:
  PoseSolver(const LinkageSolver& solver, bool fast, int halving_limit = max_halvings)
      : solver_(solver), halving_limit_(halving_limit) {
    if (fast && LinkageFastSolver::applies(solver.options())) fast_.emplace(solver);
    const Eigen::Index n = solver.model().unknown_count();
    history_.reset(n);
    prediction_.resize(n);
    tolerance_ = solver.options().newton.residual_tolerance;
    length_ = solver.size();
  }
  const LinkageSolver& solver() const { return solver_; }
  int halving_limit() const { return halving_limit_; }  // how often a continuation step may be halved
  LinkageFastOutcome solve(double t, Eigen::VectorXd& q) {
    if (fast_) return fast_->solve(t, q);
    LinkageSolution solution = solver_.solve(t, q);
    q = std::move(solution.q);
    return {solution.outcome, solution.failed_block};
  }
  // Starts the history at (t, q) unless its newest pose is that one already.
  void follow(double t, const Eigen::VectorXd& q) {
    if (!history_.newest_at(t)) {
      history_.clear();
      history_.push(t, q);
    }
  }
  void record(double t, const Eigen::VectorXd& q) { history_.push(t, q); }
  // The history's poses, solved at `from`, re-labelled as at `to` (a crank a whole number of turns on).
  void relabel(double from, double to) {
    if (history_.newest_at(from)) history_.shift(to - from);
  }
  void forget() { history_.clear(); }
  // Where the branch of the pose (t, q) is expected at s: the quadratic through the history when
  // its newest pose is this one, else the tangent.
  Eigen::VectorXd guess(double t, const Eigen::VectorXd& q, double s) {
    Eigen::VectorXd g = q;
    double error = 0.0, motion = 0.0;
    if (history_.newest_at(t) && history_.predict(s, g, error, motion)) return g;
    return predicted(solver_.model(), t, q, s);
  }
  // The start for a solve at `next`, from the pose q at `at`, in place.
  void predict(double at, Eigen::VectorXd& q, double next) {
    line_error_ = -1.0;
    if (history_.newest_at(at) && history_.predict(next, q, line_error_, motion_)) {
      prediction_ = q;
      return;
    }
    line_error_ = -1.0;  // the tangent: no error estimate, no jump test
    if (fast_) fast_->predict(at, q, next);
    else q = predicted(solver_.model(), at, q, next);
  }
  // How far the solved q is from the quadratic's prediction, and how far it may be: eight times the
  // line's error estimate plus a twentieth of the step's motion (two branches that cross part at a
  // rate that differs by about their tangents' difference, a good part of the motion), and never
  // less than a millionth of the longest link (branches that close are one to rounding in every
  // figure the sweep reports), nor than ten residual tolerances (a loose tolerance leaves the poses
  // that far from the branch: --tol 1e-2 cannot tell branches apart more finely), nor than twice
  // sqrt(2 L tol): near a singular pose a residual of tol leaves a pose that far from the root.
  double jump(const Eigen::VectorXd& q) const {
    return line_error_ < 0.0 || q.size() == 0 ? 0.0 : (q - prediction_).lpNorm<Eigen::Infinity>();
  }
  double allowed_jump() const {
    return line_error_ < 0.0 ? 0.0
                             : 8.0 * line_error_ + 0.05 * motion_ + 1e-6 * length_ + 10.0 * tolerance_ +
                                   2.0 * std::sqrt(2.0 * length_ * tolerance_);
  }
  bool jumped(const Eigen::VectorXd& q) const { return line_error_ >= 0.0 && jump(q) > allowed_jump(); }
  // Whether a solved q (in place) stays on the branch. Near a singular pose the residual test leaves
  // a pose up to sqrt(2 L tol) from the root, and on a crossing the two branches are that close: a
  // pose further from the prediction than the strict allowance (without that term) is solved again
  // to rounding from the prediction, which is nearer the branch followed; it then has to pass the
  // whole allowance.
  bool settle(double t, Eigen::VectorXd& q) {
    if (line_error_ < 0.0) return true;
    const double strict = allowed_jump() - 2.0 * std::sqrt(2.0 * length_ * tolerance_);
    if (jump(q) <= strict) return true;
    const auto polished = detail::solve_to_rounding(solver_, t, prediction_);
    if (polished && (*polished - prediction_).lpNorm<Eigen::Infinity>() < jump(q)) q = *polished;
    return !jumped(q);
  }

 private:
  const LinkageSolver& solver_;
  int halving_limit_;
  std::optional<LinkageFastSolver> fast_;
  detail::BranchPredictor history_;
  Eigen::VectorXd prediction_;
  double line_error_ = -1.0;  // < 0: the last prediction was the tangent's
  double motion_ = 0.0;
  double tolerance_ = 0.0;    // the residual test's, in length units
  double length_ = 0.0;       // the longest link
};

// A pose that jumped from its prediction even at the shortest sub-step: what the sweep reports.
struct Jump {
  double distance = 0.0;
  double allowed = 0.0;
};

// Where a continuation that failed got stuck: the last driver value it solved (and its pose), and
// the one its shortest sub-step could not reach. The two bracket an assembly limit to a 256th of a
// sub-step, and any later target past `failed_at` from the same start fails the same way.
struct Stuck {
  double from = 0.0;
  double reached = 0.0;
  Eigen::VectorXd q;
  double failed_at = 0.0;
  LinkageSolution failure;  // what the continuation returned (set by the sweep)
  // Whether a continuation from `start` to `to` has to pass failed_at (and would fail there again).
  bool blocks(double start, double to) const {
    return start == from && (failed_at - from) * (to - from) > 0.0 && std::abs(to - from) >= std::abs(failed_at - from);
  }
};

}  // namespace detail

namespace {

using detail::Jump;
using detail::PoseSolver;
using detail::Stuck;

// From q at driver `from` to driver `to` (model units) in steps no longer than `longest`, each
// solve started from the predictor; a step that fails, or lands on another branch, is halved. q
// becomes the last solution (failed or not); `trial` is scratch of q's size. A solution that still
// jumps at the last halving is returned with status no_progress, and `jump` (if given) says how far.
LinkageFastOutcome continue_in_place(PoseSolver& poses, double from, double to, Eigen::VectorXd& q, Eigen::VectorXd& trial,
                                     double longest, int* halvings = nullptr, Jump* jump = nullptr, Stuck* stuck = nullptr) {
  poses.follow(from, q);
  if (from == to) return poses.solve(to, q);  // measured, never assumed
  LinkageFastOutcome last;
  last.outcome.status = Status::converged;
  double at = from;
  double step = std::abs(to - at) <= longest ? to - at : std::copysign(longest, to - at);
  int halved = 0;
  int iterations = 0;  // over every sub-step
  while (at != to) {
    // The last sub-step ends on `to` itself (a remainder of rounding is no sub-step of its own).
    const double next = std::abs(to - at) <= std::abs(step) * (1.0 + 1e-9) ? to : at + step;
    trial = q;
    poses.predict(at, trial, next);
    LinkageFastOutcome outcome = poses.solve(next, trial);
    iterations += outcome.outcome.iterations;
    const bool jumped = outcome.outcome.status == Status::converged && !poses.settle(next, trial);
    if (outcome.outcome.status == Status::converged && !jumped) {
      detail::keep_smooth_sides(poses.solver(), at, q, next, trial);  // 5. the side near a meeting point
      q.swap(trial);
      poses.record(next, q);
      last = outcome;
      at = next;
      continue;
    }
    if (halved == poses.halving_limit()) {
      if (jumped) {
        outcome.outcome.status = Status::no_progress;
        outcome.outcome.reason = nonlinear::StopReason::no_progress;
        if (jump != nullptr) *jump = {poses.jump(trial), poses.allowed_jump()};
      }
      if (stuck != nullptr && !jumped) *stuck = {from, at, q, next, {}};
      q.swap(trial);
      poses.forget();
      outcome.outcome.iterations = iterations;
      return outcome;
    }
    step /= 2.0;
    ++halved;
  }
  if (halvings != nullptr) *halvings = halved;
  last.outcome.iterations = iterations;
  return last;
}

// A failure reported again for a pose that was not tried: the same status and residual, no work.
LinkageSolution repeated_failure(const LinkageSolution& failure) {
  LinkageSolution again = failure;
  again.outcome.iterations = 0;
  again.outcome.function_evaluations = 0;
  again.outcome.jacobian_evaluations = 0;
  return again;
}

// The same, as a LinkageSolution.
LinkageSolution continue_to(PoseSolver& poses, double from, double to, const Eigen::VectorXd& q, double longest,
                            int* halvings = nullptr, Jump* jump = nullptr, Stuck* stuck = nullptr) {
  LinkageSolution solution{q, {}, -1};
  Eigen::VectorXd trial(q.size());
  const LinkageFastOutcome outcome = continue_in_place(poses, from, to, solution.q, trial, longest, halvings, jump, stuck);
  solution.outcome = outcome.outcome;
  solution.failed_block = outcome.failed_block;
  return solution;
}

}  // namespace

Eigen::VectorXd linkage_velocity(const LinkageModel& model, double t, const Eigen::VectorXd& q) {
  if (q.size() > linkage_exact_conditioning_limit) {  // the sparse LU: about linear in the joints
    Eigen::VectorXd velocity, acceleration;
    sparse_linkage_kinematics(model, t, q, velocity, acceleration);
    return velocity;
  }
  Eigen::MatrixXd J;
  Eigen::VectorXd phi_t;
  model.jacobian(q, t, J);
  model.driver_derivative(q, t, phi_t);
  return Eigen::PartialPivLU<Eigen::MatrixXd>(J).solve(-phi_t);
}

void linkage_kinematics(const LinkageModel& model, double t, const Eigen::VectorXd& q, Eigen::VectorXd& velocity,
                        Eigen::VectorXd& acceleration) {
  if (q.size() > linkage_exact_conditioning_limit) {  // the same two solves on the sparse LU
    sparse_linkage_kinematics(model, t, q, velocity, acceleration);
    return;
  }
  Eigen::MatrixXd J;
  Eigen::VectorXd phi_t, gamma;
  model.jacobian(q, t, J);
  model.driver_derivative(q, t, phi_t);
  const Eigen::PartialPivLU<Eigen::MatrixXd> lu(J);
  velocity = lu.solve(-phi_t);                 // 1. J qdot = -Phi_t
  model.acceleration_rhs(q, velocity, t, gamma);
  acceleration = lu.solve(gamma);              // 2. J qddot = gamma
}

namespace {

bool all_blocks_closed(const LinkageSolver& solver) {
  return std::all_of(solver.blocks().begin(), solver.blocks().end(), [](const LinkageBlock& b) { return b.closed_form(); });
}

// How far from the closed form a pose with residual Phi may be: 10 ||J^-1|| r, r = ||Phi||_2 plus
// the rounding of q, from the first-order model J e = Phi; and where J is (nearly) singular, from
// the second-order one: along J's null direction the distance rows (|d|^2 - L^2) / (2L) grow as
// e^2 / (2L), so e <= sqrt(2 L r) with L the longest link. The smaller of the two.
double closed_form_bound(const LinkageSolver& solver, double t, const Eigen::VectorXd& q, double inverse_norm) {
  const LinkageModel& model = solver.model();
  Eigen::VectorXd f;
  model.residual(q, t, f);
  const double longest = solver.size();
  const double n = static_cast<double>(q.size());
  const double size = (q.size() == 0 ? 0.0 : q.lpNorm<Eigen::Infinity>()) + longest;
  const double r = f.norm() + n * std::numeric_limits<double>::epsilon() * size;
  return 10.0 * std::min(inverse_norm * r, std::sqrt(2.0 * longest * r));
}

// Velocity and acceleration of a converged pose: from J (J qdot = -Phi_t, J qddot = gamma) at the
// pose, first solved to rounding where J is ill-conditioned; where J is singular (a crossing), the
// 7-point stencils of positions solved along the pose's branch (guess).
void pose_kinematics(const LinkageSolver& solver, double t, const detail::BranchGuess& guess, LinkagePose& pose,
                     const LinkageConditioning& conditioning) {
  const LinkageModel& model = solver.model();
  Eigen::VectorXd q = pose.q;
  double condition = conditioning.condition;
  if (condition > detail::ill_condition) {
    if (auto polished = detail::solve_to_rounding(solver, t, q)) {
      q = std::move(*polished);
      condition = linkage_conditioning(model, t, q).condition;
    }
  }
  linkage_kinematics(model, t, q, pose.velocity, pose.acceleration);
  const bool singular = !(condition <= detail::singular_condition) || !pose.velocity.allFinite() || !pose.acceleration.allFinite();
  if (singular && guess) {
    const double h = model.crank_driven() ? 1e-2 : 1e-3 * solver.size();
    pose.kinematics_by_differences = detail::branch_kinematics(solver, t, h, guess, pose.velocity, pose.acceleration);
  }
}

LinkagePose make_pose(const LinkageSolver& solver, double user, double t, LinkageSolution solution,
                      const detail::BranchGuess& guess = {}) {
  const LinkageModel& model = solver.model();
  LinkagePose pose;
  pose.driver = user;
  pose.q = std::move(solution.q);
  pose.outcome = solution.outcome;
  pose.failed_block = solution.failed_block;
  pose.condition = not_computed;
  pose.closed_form_distance = not_computed;
  pose.closed_form_bound = not_computed;
  if (converged(solution)) {
    const LinkageConditioning conditioning = linkage_conditioning(model, t, pose.q);
    pose_kinematics(solver, t, guess, pose, conditioning);
    pose.condition = conditioning.condition;
    pose.signature = solver.signature(pose.q, t);
    pose.transmission_deg = solver.transmission_angles(pose.q);
    // The closed form, where every block has one, as an independent check of the solved pose; where
    // it does not exist (a pose past a limit that a loose tolerance let through), the distance is
    // infinite: a missing reference is never a pass.
    if (all_blocks_closed(solver)) {
      const LinkageSolution closed = solver.closed_form(t, pose.q);
      pose.closed_form_distance = std::numeric_limits<double>::infinity();
      if (closed.failed_block < 0) {
        pose.closed_form_distance = (pose.q - closed.q).lpNorm<Eigen::Infinity>();
        pose.closed_form_bound = closed_form_bound(solver, t, pose.q, conditioning.inverse_norm);
      }
    }
  } else if (pose.q.size() == model.unknown_count()) {
    // Where the solve stopped, it may have stopped short of t (a sub-step): the residual shown is
    // the one at t itself, never a sub-step's small one beside a failed status.
    Eigen::VectorXd f;
    model.residual(pose.q, t, f);
    pose.outcome.residual_norm = f.size() == 0 ? 0.0 : f.lpNorm<Eigen::Infinity>();
  }
  return pose;
}

// Why the mechanism does not assemble at t: the block that cannot close (-1: none named); or that it
// does assemble there (the closed form, else the sequential solver, closes every block at t).
struct FailureCause {
  int block = -1;
  bool assembles = false;
};
FailureCause failure_cause(const LinkageSolver& solver, double t, const Eigen::VectorXd& q) {
  const LinkageSolution closed = solver.closed_form(t, q);
  if (closed.failed_block >= 0 && solver.blocks()[static_cast<std::size_t>(closed.failed_block)].closed_form()) {
    return {closed.failed_block, false};
  }
  if (all_blocks_closed(solver)) return {-1, closed.failed_block < 0};
  LinkageSolverOptions options = solver.options();
  options.solver = "sequential";
  // The reference pose is solved again here; cheap next to a bisection.
  const LinkageSolver sequential(solver.model(), options);
  const LinkageSolution solved = sequential.solve(t, q);
  return {solved.failed_block, converged(solved)};
}

// Bisection between a driver value that assembles (good, with its q) and one that does not.
// The bracket's target: 0.01 deg of crank, or 1e-4 of `span` (the sweep's step there) of slider travel.
LinkageLimit bisect_limit(PoseSolver& poses, double good, Eigen::VectorXd q, double bad, bool upper, double span) {
  const LinkageSolver& solver = poses.solver();
  const LinkageModel& model = solver.model();
  const double target = model.crank_driven() ? crank_limit_deg * std::acos(-1.0) / 180.0 : 1e-4 * std::abs(span);
  for (int i = 0; i < max_bisections && std::abs(bad - good) > target; ++i) {
    const double middle = 0.5 * (good + bad);
    LinkageSolution trial = continue_to(poses, good, middle, q, std::abs(middle - good));
    if (converged(trial)) {
      good = middle;
      q = std::move(trial.q);
    } else {
      bad = middle;
    }
  }
  LinkageLimit limit;
  limit.driver = model.driver_to_user(good);
  limit.bracket = std::abs(model.driver_to_user(bad) - model.driver_to_user(good));
  limit.upper = upper;
  const FailureCause cause = failure_cause(solver, bad, q);
  limit.block = cause.block;
  limit.assembles_beyond = cause.assembles;
  const auto angles = solver.transmission_angles(q);
  limit.transmission_deg = limit.block >= 0 ? angles[static_cast<std::size_t>(limit.block)] : not_computed;
  return limit;
}

}  // namespace

namespace detail {

// The state of step 4 (the branch) between poses: per block, the side it last had where its side is
// defined (a dyad on its meeting point has none).
struct BranchWatch {
  std::vector<int> side;
  AtCrossing at_crossing = AtCrossing::smooth;
  std::vector<int> defined_at;  // per block, the sweep's pose where that side was read (-1: the reference)
};

}  // namespace detail

namespace {

using detail::BranchWatch;

std::string crossing_words(const LinkageSolver& solver, const LinkageCrossing& c) {
  const LinkageModel& model = solver.model();
  const std::size_t b = static_cast<std::size_t>(c.block);
  const std::string where = model.crank_driven() ? fmt::format("crank {:.3f} deg", c.driver) : fmt::format("slider {:.6g}", c.driver);
  const std::string what = fmt::format("block {} ({})", b + 1, describe_block(model, solver.blocks()[b]));
  if (c.tangency) return fmt::format("two branches touch at {} without crossing: {} stays {}", where, what,
                                     detail::side_word(solver, b, c.side_after));
  return fmt::format("two branches cross at {}; followed the {} branch; {} {}", where, c.switched ? "other" : "smooth", what,
                     c.side_before == c.side_after
                         ? fmt::format("stays {}", detail::side_word(solver, b, c.side_after))
                         : fmt::format("changes side from {} to {}", detail::side_word(solver, b, c.side_before),
                                       detail::side_word(solver, b, c.side_after)));
}

// At a crossing, the other branch at t: the dyad's joint mirrored, the blocks after it by their
// closed form nearest the pose, then solved. False when the solve does not keep the side wanted.
bool switch_branch(PoseSolver& poses, std::size_t b, double t, LinkagePose& pose, int wanted_side) {
  const LinkageSolver& solver = poses.solver();
  Eigen::VectorXd q = pose.q;
  if (!detail::mirror_dyad(solver, b, q)) return false;
  const LinkageSolution closed = solver.closed_form(t, q);
  if (closed.failed_block < 0) q = closed.q;
  const LinkageFastOutcome outcome = poses.solve(t, q);
  if (outcome.outcome.status != Status::converged || solver.signature(q, t)[b] != wanted_side) return false;
  pose.q = q;
  pose.outcome = outcome.outcome;
  return true;
}

// Two branches met at `meet` and the side is the same either side: a tangency (the margin touches
// zero like d^4), or a crossing past which the poses came too close to the meeting point to tell the
// branches apart and went on along the other branch (like d^2) - a failure unless asked for.
void record_touch(const LinkageSolver& solver, const BranchWatch& watch, LinkageSweep& sweep, std::size_t b, double t0,
                  const Eigen::VectorXd& q0, double t, double meet, int side) {
  const LinkageModel& model = solver.model();
  const double d = std::abs(t - meet) >= std::abs(meet - t0) ? t - meet : t0 - meet;
  const bool touches = !(detail::contact_order(solver, b, t0, q0, meet, d) < 3.0);
  LinkageCrossing touch{model.driver_to_user(meet), static_cast<int>(b), side, side, !touches, touches};
  sweep.crossings.push_back(touch);
  sweep.change_points.push_back(crossing_words(solver, touch));
  if (!touches && watch.at_crossing == AtCrossing::smooth) {  // the other branch, not asked for
    sweep.branch_kept = false;
    sweep.flips.push_back(fmt::format("block {} ({}) went on along the other branch at the crossing at {:.3f}: the poses "
                                      "came too close to it to tell the branches apart (a step that lands further from "
                                      "it follows the smooth branch)",
                                      b + 1, describe_block(model, solver.blocks()[b]), touch.driver));
  }
}

void note_touch(const LinkageSolver& solver, const BranchWatch& watch, LinkageSweep& sweep, std::size_t b, double t0,
                const Eigen::VectorXd& q0, double t) {
  const double meet = detail::change_point(solver, b, t0, q0, t);
  if (std::isfinite(meet)) record_touch(solver, watch, sweep, b, t0, q0, t, meet, watch.side[b]);
}

// 4. The branch at a converged pose: a block whose side differs from its last defined side has
// either passed a crossing (its two solutions meet between the poses: the smooth branch goes on on
// the other side) or jumped to another branch. Returns whether the pose was re-solved on the other
// branch (AtCrossing::switch_branch).
bool watch_branch(PoseSolver& poses, BranchWatch& watch, LinkageSweep& sweep, LinkagePose& pose, double t, bool in_sweep) {
  const LinkageSolver& solver = poses.solver();
  const LinkageModel& model = solver.model();
  bool switched = false;
  const int here = static_cast<int>(sweep.poses.size());
  std::vector<double> margins = solver.dyad_margins(pose.q);
  for (std::size_t b = 0; b < pose.signature.size(); ++b) {
    if (!detail::side_defined_at(solver, b, pose.q, margins[b])) continue;  // on the meeting point: decided at the next pose
    const int from = watch.defined_at[b];
    watch.defined_at[b] = here;
    // Where the side was last read: the poses between were on (or within the solve's accuracy of)
    // the meeting point.
    const double t0 = from < 0 ? solver.reference_driver() : model.driver_from_user(sweep.poses[static_cast<std::size_t>(from)].driver);
    const Eigen::VectorXd& q0 = from < 0 ? solver.reference() : sweep.poses[static_cast<std::size_t>(from)].q;
    if (pose.signature[b] == watch.side[b]) {
      // The same side after poses on the meeting point: the branches touched (step 5's business
      // when no pose lay on it).
      if (in_sweep && from >= 0 && from + 1 < here) note_touch(solver, watch, sweep, b, t0, q0, t);
      continue;
    }
    const double meet = detail::change_point(solver, b, t0, q0, t);
    if (!std::isfinite(meet)) {
      sweep.branch_kept = false;
      if (sweep.flips.size() < 20) {
        sweep.flips.push_back(fmt::format("block {} ({}) jumps to the other branch between {:g} and {:g}", b + 1,
                                          describe_block(model, solver.blocks()[b]), model.driver_to_user(t0),
                                          pose.driver));
      }
      watch.side[b] = pose.signature[b];
      continue;
    }
    if (!in_sweep) {  // a crossing on the walk from the reference pose to the sweep's start: not the sweep's
      watch.side[b] = pose.signature[b];
      continue;
    }
    LinkageCrossing crossing{model.driver_to_user(meet), static_cast<int>(b), watch.side[b], pose.signature[b], false, false};
    if (watch.at_crossing == AtCrossing::switch_branch && switch_branch(poses, b, t, pose, watch.side[b])) {
      crossing.switched = switched = true;
      crossing.side_after = watch.side[b];
      pose.signature = solver.signature(pose.q, t);
      margins = solver.dyad_margins(pose.q);  // the later dyads' centres moved with it
    }
    watch.side[b] = crossing.side_after;
    sweep.crossings.push_back(crossing);
    sweep.change_points.push_back(crossing_words(solver, crossing));
  }
  return switched;
}

// 5. A tangency: a dyad whose two solutions meet at the pose before this one (its margin, at a
// local minimum there, is zero to rounding between the poses either side) while its side is the
// same either side. The branches touch and part without crossing; the sweep goes on along its own.
void watch_tangency(const LinkageSolver& solver, const BranchWatch& watch, LinkageSweep& sweep, const LinkagePose& pose, double t) {
  const std::size_t k = sweep.poses.size();
  if (k < 2) return;
  const LinkagePose& middle = sweep.poses[k - 1];
  const LinkagePose& first = sweep.poses[k - 2];
  if (first.outcome.status != Status::converged || middle.outcome.status != Status::converged) return;
  const LinkageModel& model = solver.model();
  const std::vector<double> m0 = solver.dyad_margins(first.q), m1 = solver.dyad_margins(middle.q), m2 = solver.dyad_margins(pose.q);
  for (std::size_t b = 0; b < m1.size(); ++b) {
    if (!(m1[b] <= m0[b] && m1[b] <= m2[b])) continue;  // not a local minimum (NaN: not a dyad)
    if (!(m1[b] <= 1e-3 * solver.size())) continue;     // far from meeting (as in step 5)
    const bool noted = std::any_of(sweep.crossings.begin(), sweep.crossings.end(), [&](const LinkageCrossing& c) {
      return c.block == static_cast<int>(b) && (c.driver - first.driver) * (c.driver - pose.driver) <= 0.0;
    });
    if (noted) continue;  // a crossing or touch there already
    if (first.signature[b] != pose.signature[b] || !detail::side_defined(solver, b, first.q) ||
        !detail::side_defined(solver, b, middle.q) || !detail::side_defined(solver, b, pose.q)) {
      continue;  // a crossing, or poses on the meeting point: step 4's business
    }
    const double t0 = model.driver_from_user(first.driver);
    const double meet = detail::change_point(solver, b, t0, first.q, t);
    if (std::isfinite(meet)) record_touch(solver, watch, sweep, b, t0, first.q, t, meet, pose.signature[b]);
  }
}

// The crank's walk and sub-step length (model units): 2 degrees; a slider's: a 50th of the walk,
// but never shorter than the sweep's own step (a sweep that starts at the reference has no walk;
// sub-steps of 1e-12 would never reach its next pose).
double longest_sub_step(const LinkageModel& model, double walk, double step) {
  return model.crank_driven() ? model.driver_from_user(crank_walk_deg)
                              : std::max(std::abs(walk) / slider_walk_steps, std::abs(step));
}

double shortest_length(const LinkageModel& model) {
  double shortest = std::numeric_limits<double>::infinity();
  for (const Constraint& c : model.constraints()) {
    if (c.kind == ConstraintKind::distance || c.kind == ConstraintKind::crank) shortest = std::min(shortest, c.length);
  }
  return shortest;
}

// The rule of closed_form_bound.hpp: within the bound, and the bound below half the shortest length
// (beyond it the residual justifies nothing: another branch is about a link away). A pose of a model
// in closed form whose closed form does not exist there is not verified either.
bool pose_verified(const LinkageSolver& solver, const LinkagePose& pose, double shortest) {
  if (std::isnan(pose.closed_form_distance)) return !all_blocks_closed(solver);
  return pose.closed_form_distance <= pose.closed_form_bound && pose.closed_form_bound < 0.5 * shortest;
}

}  // namespace

namespace detail {

// Where a sweep stands between poses: the last pose that assembled, and where the continuation
// from it failed, if it did.
struct Continuation {
  PoseSolver& poses;
  double longest;  // the longest sub-step
  Eigen::VectorXd last_good;
  double last_good_t;
  std::optional<Stuck> stuck;

  // The pose at t, by continuation from the last good one; or, when t lies past where that already
  // failed, the same failure again without a solve (repeated).
  LinkageSolution solve(double t, int& halvings, Jump& jump, bool& repeated) {
    repeated = stuck && stuck->blocks(last_good_t, t);
    if (repeated) return repeated_failure(stuck->failure);
    Stuck now;
    now.failed_at = not_computed;
    LinkageSolution solution = continue_to(poses, last_good_t, t, last_good, longest, &halvings, &jump, &now);
    if (!converged(solution) && !std::isnan(now.failed_at)) {
      now.failure = solution;
      stuck = std::move(now);
    }
    return solution;
  }
  void assembled(double t, const Eigen::VectorXd& q) {
    last_good = q;
    last_good_t = t;
    stuck.reset();
  }
};

}  // namespace detail

namespace {

using detail::Continuation;

// 3. A change between assembling and not, from the pose before to this one, is a limit: bracketed
// (from where the continuation got stuck, when it has that bracket) and named.
void note_limit(Continuation& c, LinkageSweep& sweep, const LinkagePose& pose, double t) {
  if (sweep.poses.empty() || pose.jumped || sweep.poses.back().jumped) return;
  const LinkagePose& before = sweep.poses.back();
  const bool was_ok = before.outcome.status == Status::converged, ok = pose.outcome.status == Status::converged;
  if (was_ok && !ok) {
    const double span = t - c.last_good_t;
    const bool bracketed = c.stuck && c.stuck->from == c.last_good_t;
    sweep.limits.push_back(bracketed ? bisect_limit(c.poses, c.stuck->reached, c.stuck->q, c.stuck->failed_at, true, span)
                                     : bisect_limit(c.poses, c.last_good_t, c.last_good, t, true, span));
  }
  if (!was_ok && ok) {
    const double t_before = c.poses.solver().model().driver_from_user(before.driver);
    sweep.limits.push_back(bisect_limit(c.poses, t, pose.q, t_before, false, t - t_before));
  }
}

void note_jump(LinkageSweep& sweep, double user, const Jump& jump) {
  sweep.branch_kept = false;
  sweep.jumps.push_back(fmt::format("the pose at {:g} lands {:.3g} from where its branch leads (the predictor allows "
                                    "{:.3g}): it left its branch",
                                    user, jump.distance, jump.allowed));
}

}  // namespace

// What the stepper keeps between poses: the pose solves, where the continuation stands, the branch
// watch, and the walk's pose at the start (the first pose).
struct LinkageSweepStepper::State {
  State(const LinkageSolver& solver, bool fast, int halving_limit, double longest, AtCrossing at_crossing)
      : poses(solver, fast, halving_limit),
        continuation{poses, longest, solver.reference(), solver.reference_driver(), {}},
        watch{solver.reference_signature(), at_crossing, std::vector<int>(solver.blocks().size(), -1)},
        shortest(shortest_length(solver.model())) {}
  LinkagePose next_pose(LinkageSweep& sweep, double user, bool first);

  PoseSolver poses;
  Continuation continuation;
  BranchWatch watch;
  LinkageSolution at;
  double shortest;
};

// 2. The pose at `user` from the one before, through sub-steps each from the predictor; a failed
// pose is retried from the last good one by halving. Then its limit (3.), branch and check (4.).
LinkagePose LinkageSweepStepper::State::next_pose(LinkageSweep& sweep, double user, bool first) {
  const LinkageSolver& solver = poses.solver();
  const LinkageModel& model = solver.model();
  const double t = model.driver_from_user(user);
  int halvings = 0;
  Jump jump;
  bool repeated = false;
  LinkageSolution solution = first ? std::move(at) : continuation.solve(t, halvings, jump, repeated);
  const detail::BranchGuess guess = [&, q = solution.q](double s) { return poses.guess(t, q, s); };
  LinkagePose pose = make_pose(solver, user, t, std::move(solution), guess);
  pose.step_halvings = halvings;
  if (repeated) pose.not_tried_past = model.driver_to_user(continuation.stuck->failed_at);
  // A "jump" at the shortest sub-step towards a t where nothing assembles is the fold itself: near
  // it the branch and its twin meet and the prediction fails. It is a limit (3.), not a branch left.
  pose.jumped = jump.distance > 0.0 && failure_cause(solver, t, pose.q).assembles;
  if (pose.jumped) note_jump(sweep, user, jump);
  note_limit(continuation, sweep, pose, t);  // 3.
  if (pose.outcome.status == Status::converged) {
    // 4. The branch (compared with the reference pose across the walk for the first pose).
    if (watch_branch(poses, watch, sweep, pose, t, !sweep.poses.empty())) {
      pose = make_pose(solver, user, t, LinkageSolution{pose.q, pose.outcome, -1});  // the tangent's guess: J is regular past the crossing
      poses.forget();
    }
    watch_tangency(solver, watch, sweep, pose, t);
    if (!pose_verified(solver, pose, shortest)) sweep.closed_form_verified = false;
    pose.branch_kept = sweep.branch_kept;
    continuation.assembled(t, pose.q);
  } else if (sweep.status == Status::converged) {
    sweep.status = pose.outcome.status;
  }
  return pose;
}

LinkageSweepStepper::LinkageSweepStepper(const LinkageSolver& solver, AtCrossing at_crossing,
                                         const LinkageSweepOptions& options)
    : solver_(solver), at_crossing_(at_crossing), options_(options) {}

LinkageSweepStepper::~LinkageSweepStepper() = default;

void LinkageSweepStepper::start(double start, double stop, double step) {
  if (!std::isfinite(start) || !std::isfinite(stop) || !std::isfinite(step) || step == 0.0 ||
      (stop - start) * step < 0.0) {
    throw std::invalid_argument("the sweep's step must be finite, nonzero and point from start to stop");
  }
  if (options_.max_halvings < 0 || options_.max_halvings > 60) {
    throw std::invalid_argument("the sweep's max_halvings must be 0 ... 60");
  }
  const LinkageModel& model = solver_.model();
  start_ = start;
  step_ = step;
  count_ = static_cast<std::size_t>(std::floor((stop - start) / step + 1e-9)) + 1;
  next_ = 0;
  poses_ = 0;
  sweep_ = LinkageSweep{};
  sweep_.status = Status::converged;  // until a pose fails
  status_ = Status::running;
  active_ = true;
  stopped_ = false;
  // 1. Walk from the reference pose to the start: the shorter way round for a crank. The fast path
  // solves the poses, unless an observer traces them.
  const double reference = solver_.reference_driver();
  const double t_start = model.driver_from_user(start);
  double walk_to = t_start;
  if (model.crank_driven()) walk_to = reference + std::remainder(t_start - reference, 2.0 * std::acos(-1.0));
  const double longest = longest_sub_step(model, walk_to - reference, model.driver_from_user(start + step) - t_start);
  state_ = std::make_unique<State>(solver_, observer_ == nullptr, options_.max_halvings, longest, at_crossing_);
  State& state = *state_;
  int walk_halvings = 0;
  Jump walk_jump;
  bool unused = false;
  state.at = state.continuation.solve(walk_to, walk_halvings, walk_jump, unused);
  state.poses.relabel(walk_to, t_start);  // the walk's last poses predict the sweep's first (a sweep may start on a crossing)
  if (converged(state.at)) state.continuation.assembled(t_start, state.at.q);
  x_ = state.at.q;
}

bool LinkageSweepStepper::step() {
  if (!running()) return false;
  // 2.-4. The next requested pose.
  const double user = start_ + static_cast<double>(next_) * step_;
  sweep_.poses.push_back(state_->next_pose(sweep_, user, next_ == 0));
  ++poses_;
  x_ = sweep_.poses.back().q;
  if (observer_ != nullptr && observer_->on_step(*this, sweep_.poses.back()) == StepControl::stop) {
    sweep_.status = Status::running;  // stopped before a verdict
    sweep_.stopped = stopped_ = true;
    active_ = false;
    return false;
  }
  if (++next_ == count_) {  // the last pose: the verdict
    status_ = sweep_.status;
    active_ = false;
  }
  return active_;
}

LinkageSweep LinkageSweepStepper::solve(double start, double stop, double step) {
  this->start(start, stop, step);
  while (this->step()) {
  }
  return std::move(sweep_);
}

namespace {

// A std::function observer (the command line's tracer) as the stepper's observer.
class FunctionObserver final : public StepObserver<LinkageSweepStepper, LinkagePose> {
 public:
  explicit FunctionObserver(const LinkagePoseObserver& observer) : observer_(observer) {}
  StepControl on_step(const LinkageSweepStepper&, const LinkagePose& pose) override { return observer_(pose); }

 private:
  const LinkagePoseObserver& observer_;
};

}  // namespace

LinkageSweep linkage_sweep(const LinkageSolver& solver, double start, double stop, double step,
                           const LinkagePoseObserver& observer, AtCrossing at_crossing) {
  LinkageSweepStepper stepper(solver, at_crossing);
  FunctionObserver adapter(observer);
  if (observer) stepper.set_observer(&adapter);
  return stepper.solve(start, stop, step);
}

namespace {

// The next of equally spaced poses from the last m <= 5 of the `done` columns of poses (the
// polynomial of degree m - 1 through them): sum over k = 1..m of (-1)^(k+1) C(m, k) poses(done - k).
void extrapolate(const Eigen::MatrixXd& poses, Eigen::Index done, Eigen::VectorXd& next) {
  const Eigen::Index m = std::min<Eigen::Index>(done, 5);
  next.setZero();
  double binomial = 1.0;  // C(m, k), from C(m, 0)
  for (Eigen::Index k = 1; k <= m; ++k) {
    binomial = binomial * static_cast<double>(m - k + 1) / static_cast<double>(k);
    next += (k % 2 == 1 ? binomial : -binomial) * poses.col(done - k);
  }
}

}  // namespace

LinkageCycle solve_linkage_cycle(const LinkageSolver& solver, double start, double stop, double step) {
  const LinkageModel& model = solver.model();
  const std::size_t count = static_cast<std::size_t>(std::floor((stop - start) / step + 1e-9)) + 1;
  LinkageCycle cycle;
  cycle.status = Status::converged;  // until a pose fails
  cycle.q.resize(solver.model().unknown_count(), static_cast<Eigen::Index>(count));
  PoseSolver poses(solver, true);
  const double reference = solver.reference_driver();
  double at = model.driver_from_user(start);
  const double walk_to = model.crank_driven() ? reference + std::remainder(at - reference, 2.0 * std::acos(-1.0)) : at;
  const double longest = model.crank_driven() ? model.driver_from_user(crank_walk_deg)
                                              : std::max(std::abs(walk_to - reference) / slider_walk_steps, 1e-12);
  Eigen::VectorXd q = solver.reference(), trial(q.size());
  LinkageFastOutcome pose = continue_in_place(poses, reference, walk_to, q, trial, longest);
  for (std::size_t k = 0; k < count; ++k) {
    const double t = model.driver_from_user(start + static_cast<double>(k) * step);
    if (k > 0) {
      // The prediction of `numlab bench jansen`'s hand-coded sweeps: the polynomial through the
      // last poses (up to five), extrapolated; if its solve fails, continuation from the last pose.
      extrapolate(cycle.q, static_cast<Eigen::Index>(k), trial);
      pose = poses.solve(t, trial);
      if (pose.outcome.status == Status::converged) q.swap(trial);
      else pose = continue_in_place(poses, at, t, q, trial, std::abs(t - at));
    }
    at = t;
    cycle.iterations += pose.outcome.iterations;
    if (pose.outcome.status != Status::converged && cycle.status == Status::converged) cycle.status = pose.outcome.status;
    cycle.q.col(static_cast<Eigen::Index>(k)) = q;
  }
  return cycle;
}

}  // namespace numlab::mechanisms
