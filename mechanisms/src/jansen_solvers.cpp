#include "numlab/mechanisms/jansen_solvers.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "numlab/force_inline.hpp"
#include "numlab/mechanisms/anchored_sincos.hpp"
#include "numlab/mechanisms/closed_form_bound.hpp"
#include "numlab/mechanisms/crank_angle.hpp"
#include "numlab/mechanisms/dyad_newton.hpp"
#include "numlab/mechanisms/full_newton_pose_solver.hpp"
#include "numlab/mechanisms/gsl_pose_solver.hpp"
#include "numlab/mechanisms/jansen10_closure.hpp"
#include "numlab/nonlinear/block_order.hpp"
#include "numlab/nonlinear/dynamic_adapter.hpp"
#include "numlab/nonlinear/gsl_multiroot.hpp"
#include "numlab/nonlinear/sequential_newton.hpp"
#include "numlab/mechanisms/plane_angles.hpp"

namespace numlab::mechanisms {

namespace {

// Seed 000's sequential solve: the dyads (theta1, theta2), (theta3, theta4), (theta6, theta7),
// (theta5, theta8), each by its own Newton with the closed-form 2x2 inverse (dyad_newton.hpp). A
// later block's known part uses the directions of the blocks already solved, as they left them.
// The fast path of TextbookSequentialJansen (jansen_sequential.hpp).
class SequentialEight final : public JansenPoseSolver {
 public:
  explicit SequentialEight(const nonlinear::NewtonOptions& options)
      : blocks_{DyadNewton(options), DyadNewton(options), DyadNewton(options), DyadNewton(options)} {}
  PoseOutcome solve(double crank_angle, Eigen::VectorXd& theta) override {
    const JansenLengths L;
    Eigen::Matrix<double, 1, 1> crank_cos, crank_sin;
    crank_sines_.evaluate(Eigen::Matrix<double, 1, 1>(crank_angle), crank_cos, crank_sin);
    const Eigen::Vector2d crank(L.a + L.crank * crank_sin(0), L.b + L.crank * crank_cos(0));  // (y, x)
    PoseOutcome total;
    // A block's known part waits for the blocks before it; its sines and cosines at the start do
    // not. So every block is placed at its start first, and these independent evaluations overlap.
    for (int b = 0; b < 4; ++b) blocks_[b].place(theta(unknowns[b][0]), theta(unknowns[b][1]));
    auto block = [&](int b, const Eigen::Vector2d& known, double p, double q) {
      DyadNewton& newton = blocks_[b];
      newton.set_block(known(0), known(1), p, q);
      const Status status = newton.solve_placed();
      theta(unknowns[b][0]) = newton.alpha();
      theta(unknowns[b][1]) = newton.beta();
      total.iterations += newton.iterations();
      // Block lower-triangular: a block's equations never see later unknowns, so its final
      // residual is its part of the whole system's, and the maximum over blocks is ||f||_inf.
      total.residual_norm = std::max(total.residual_norm, newton.residual_norm());
      if (status != Status::converged) total.status = status;
      return status == Status::converged;
    };
    // u(theta1), u(theta3), u(theta7) in (y, x) order, from the blocks that solved them.
    auto direction = [&](int b, int which) { return blocks_[b].direction(which); };
    const bool ok = block(0, crank, L.l1, L.l2) &&
                    block(1, crank + L.l1 * direction(0, 0), L.l3, L.l4) &&
                    block(2, crank, L.l6, L.l7) &&
                    block(3, crank + L.l1 * direction(0, 0) + L.l3 * direction(1, 0) - L.l7 * direction(2, 1), L.l5, L.l8);
    if (ok) total.status = Status::converged;  // else a failed block has set it; the blocks after it were not tried
    return total;
  }

 private:
  // Each block's unknowns (alpha, beta): (theta1, theta2), (theta3, theta4), (theta6, theta7), (theta5, theta8).
  static constexpr int unknowns[4][2] = {{0, 1}, {2, 3}, {5, 6}, {4, 7}};
  AnchoredSinCos<1> crank_sines_;
  DyadNewton blocks_[4];
};

// Generic sequential Newton over blocks derived from the pattern (used for the 10-equation model).
template <typename Closure>
class SequentialDerived final : public JansenPoseSolver {
 public:
  SequentialDerived(const nonlinear::NewtonOptions& options, const Eigen::VectorXd& typical)
      : options_(options), closure_(0.0), dynamic_(closure_) {
    blocks_ = nonlinear::block_triangular_order(nonlinear::jacobian_pattern(dynamic_, typical));
  }
  PoseOutcome solve(double crank_angle, Eigen::VectorXd& angles) override {
    closure_.set_crank_angle(crank_angle);
    const auto result = nonlinear::sequential_newton(dynamic_, blocks_, angles, {options_, nonlinear::LinearMethod::inverse2x2});
    angles = result.x;
    return {result.status, result.iterations, result.residual_norm};
  }

 private:
  nonlinear::NewtonOptions options_;
  Closure closure_;
  nonlinear::AsDynamicSystem<Closure> dynamic_;
  std::vector<nonlinear::Block> blocks_;
};

// The closed form, producing the same outputs (the angles) as the iterative solvers.
class Analytic final : public JansenPoseSolver {
 public:
  explicit Analytic(JansenModel model) : model_(model) {}
  PoseOutcome solve(double crank_angle, Eigen::VectorXd& angles) override {
    const auto joints = leg_.closed_form_joints(crank_angle);
    if (!joints) return {Status::cannot_assemble, 0, 0.0};
    angles = jansen_angles_of(model_, *joints, angles);
    return {Status::converged, 0, 0.0};
  }

 private:
  JansenModel model_;
  JansenLeg leg_;
};

// Predictor for pose `next` of a sweep with equal steps: the polynomial through the last m solved
// poses (columns next-m ... next-1, m = 5 at most: degree 4), extrapolated one step. Setting its
// m-th difference to zero gives x_next = sum_{j=1..m} (-1)^(j+1) C(m, j) x_{next-j}; the error is
// O(step^m), so the corrector usually needs a single Newton step.
void predict_next_pose(const Eigen::MatrixXd& poses, int next, Eigen::VectorXd& prediction) {
  auto pose = [&](int back) { return poses.col(next - back); };
  switch (std::min(next, 5)) {
    case 1: prediction = pose(1); break;
    case 2: prediction = 2 * pose(1) - pose(2); break;
    case 3: prediction = 3 * pose(1) - 3 * pose(2) + pose(3); break;
    case 4: prediction = 4 * pose(1) - 6 * pose(2) + 4 * pose(3) - pose(4); break;
    default: prediction = 5 * pose(1) - 10 * pose(2) + 10 * pose(3) - 5 * pose(4) + pose(5); break;
  }
}

}  // namespace

std::vector<std::string> jansen_angle_names(JansenModel model) {
  std::vector<std::string> names;
  const int first = model == JansenModel::eight_equations ? 1 : 3;
  const int count = model == JansenModel::eight_equations ? 8 : 10;
  for (int k = 0; k < count; ++k) names.push_back("theta" + std::to_string(first + k));
  return names;
}

JansenJoints jansen_joints(JansenModel model, const JansenLeg& leg, double crank_angle, const Eigen::VectorXd& x) {
  if (model == JansenModel::eight_equations) return leg.joints(crank_angle, JansenAngles(x));
  // Seed 001's directions (see jansen10_closure.hpp).
  const JansenLengths& L = leg.lengths();
  JansenJoints p;
  p[at(JansenJoint::O)] = Eigen::Vector2d::Zero();
  p[at(JansenJoint::P1)] = Eigen::Vector2d(-L.b, -L.a);
  p[at(JansenJoint::A)] = L.crank * unit(crank_angle);
  p[at(JansenJoint::B)] = p[at(JansenJoint::A)] + L.l1 * unit(x(0));
  p[at(JansenJoint::C)] = p[at(JansenJoint::B)] + L.l3 * unit(x(2));
  p[at(JansenJoint::D)] = p[at(JansenJoint::P1)] + L.l7 * unit(x(5));
  p[at(JansenJoint::E)] = p[at(JansenJoint::D)] - L.l8 * unit(x(6));
  p[at(JansenJoint::F)] = p[at(JansenJoint::D)] + 49.0 * unit(x(8));
  return p;
}

Eigen::VectorXd jansen_angles_of(JansenModel model, const JansenJoints& p, const Eigen::VectorXd& near) {
  if (model == JansenModel::eight_equations) return JansenLeg::angles_of(p, JansenAngles(near));
  using J = JansenJoint;
  const std::pair<J, J> ends[10] = {{J::A, J::B}, {J::B, J::P1}, {J::B, J::C}, {J::C, J::P1}, {J::C, J::E},
                                    {J::P1, J::D}, {J::E, J::D}, {J::D, J::A}, {J::D, J::F}, {J::F, J::E}};
  Eigen::VectorXd theta(10);
  constexpr double turn = 2.0 * std::numbers::pi;
  for (int k = 0; k < 10; ++k) {
    const double angle = direction(p[at(ends[k].first)], p[at(ends[k].second)]);
    theta(k) = angle + turn * std::round((near(k) - angle) / turn);
  }
  return theta;
}

Eigen::VectorXd jansen_seed_estimates(JansenModel model, const JansenLeg& leg) {
  const Eigen::VectorXd eight = JansenClosure::seed_estimates();
  if (model == JansenModel::eight_equations) return eight;
  // The joints seed 000's (approximate) estimates describe, read as seed 001's ten directions.
  const JansenJoints joints = leg.joints(JansenClosure::seed_crank_angle, JansenAngles(eight));
  return jansen_angles_of(model, joints, Eigen::VectorXd::Zero(10));
}

const std::vector<std::string>& jansen_solver_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> all = {"full", "sequential", "analytic"};
    for (const std::string& type : nonlinear::gsl_multiroot_types()) all.push_back("gsl-" + type);
    return all;
  }();
  return names;
}

std::unique_ptr<JansenPoseSolver> make_jansen_solver(JansenModel model, const std::string& solver,
                                                     const std::string& linear, const nonlinear::NewtonOptions& options) {
  const bool eight = model == JansenModel::eight_equations;
  if (solver == "full") {
    return eight ? make_full_newton<JansenClosureOf<TableSines>, Eigen::VectorXd>(linear, options)
                 : make_full_newton<Jansen10ClosureOf<TableSines>, Eigen::VectorXd>(linear, options);
  }
  if (solver == "sequential") {
    if (eight) return std::make_unique<SequentialEight>(options);
    return std::make_unique<SequentialDerived<Jansen10ClosureOf<TableSines>>>(options,
                                                                              jansen_seed_estimates(model, JansenLeg()));
  }
  if (solver == "analytic") return std::make_unique<Analytic>(model);
  if (solver.starts_with("gsl-")) {
    const std::string type = solver.substr(4);
    const auto& types = nonlinear::gsl_multiroot_types();
    if (std::find(types.begin(), types.end(), type) == types.end()) {
      throw std::invalid_argument("unknown solver '" + solver + "'");
    }
    if (eight) return std::make_unique<GslPoseSolver<JansenClosureOf<TableSines>, Eigen::VectorXd>>(type, options);
    return std::make_unique<GslPoseSolver<Jansen10ClosureOf<TableSines>, Eigen::VectorXd>>(type, options);
  }
  throw std::invalid_argument("unknown solver '" + solver + "' (expected full, sequential, analytic or gsl-<type>)");
}

void JansenSweepStepper::start(double start_deg, double stop_deg, double step_deg) {
  count_ = sweep_pose_count(start_deg, stop_deg, step_deg);
  sweep_ = JansenSweepAngles{};
  start_deg_ = start_deg;
  step_deg_ = step_deg;
  next_ = 0;
  poses_ = 0;
  angles_ = jansen_seed_estimates(model_, JansenLeg());
  trial_ = angles_;  // buffer reused from pose to pose (no allocation per pose)
  current_deg_ = JansenClosure::seed_crank_angle / degrees;
  walk_to_deg_ = nearest_turn(start_deg, current_deg_);  // the same pose as start_deg, at most 180 deg away
  phase_ = Phase::seed;
  status_ = Status::running;
  stop_requested_ = false;
  stopped_ = false;
}

bool JansenSweepStepper::step() {
  if (!running()) return false;  // finished, or stopped by the observer
  switch (phase_) {
    case Phase::requested: solve_requested_pose(); break;
    case Phase::walk_in: walk_in_one_pose(); break;
    case Phase::seed: solve_seed_pose(); break;
    case Phase::finished: break;
  }
  if (stop_requested_ && running()) stopped_ = true;  // the observer ended the run: no verdict
  return running();
}

JansenSweepAngles JansenSweepStepper::solve(double start_deg, double stop_deg, double step_deg) {
  start(start_deg, stop_deg, step_deg);
  while (step()) {
  }
  return std::move(sweep_);
}

bool JansenSweepStepper::finish(Status status) {
  sweep_.status = status;
  status_ = status;
  phase_ = Phase::finished;
  return false;
}

// One solve, shown to the observer if there is one.
NUMLAB_FORCE_INLINE PoseOutcome JansenSweepStepper::solve_pose(double deg, double step_deg, Eigen::VectorXd& x) {
  const PoseOutcome outcome = solver_.solve(crank_radians(deg), x);
  if (observer_ != nullptr) [[unlikely]] notify(deg, step_deg, outcome, x);
  return outcome;
}

void JansenSweepStepper::notify(double deg, double step_deg, const PoseOutcome& outcome, const Eigen::VectorXd& x) {
  if (stop_requested_) return;  // told to stop earlier in this step: the step ends unobserved
  const SweepPoseRecord record{deg, step_deg, outcome, outcome.status == Status::converged, x};
  if (observer_->on_step(*this, record) == StepControl::stop) stop_requested_ = true;
}

// Moves from current_deg_ to target_deg: tries the whole step; when a solve fails, halves the
// step and tries again from the last pose that solved (at most max_halvings halvings in all).
PoseOutcome JansenSweepStepper::advance_to(double target_deg) {
  double reached = current_deg_, step = target_deg - current_deg_;
  int halvings = 0;
  while (true) {
    const bool whole_way = step == target_deg - reached;
    const double next = whole_way ? target_deg : reached + step;
    trial_ = angles_;
    const PoseOutcome outcome = solve_pose(next, next - reached, trial_);
    if (outcome.status == Status::converged) {
      angles_ = trial_;
      reached = next;
      if (whole_way) return outcome;
      step = target_deg - reached;  // aim for the target again
    } else {
      if (++halvings > options_.max_halvings) return outcome;
      ++sweep_.step_halvings;
      step *= 0.5;
    }
  }
}

// 1. The pose at 1.57 rad, from the seed's estimates.
bool JansenSweepStepper::solve_seed_pose() {
  const PoseOutcome outcome = solve_pose(current_deg_, 0.0, angles_);
  if (outcome.status != Status::converged) return finish(outcome.status);
  ++poses_;
  if (std::abs(walk_to_deg_ - current_deg_) > 1e-12) {
    phase_ = Phase::walk_in;
  } else {
    begin_requested_poses();
  }
  return true;
}

// 2. One pose of the walk from 1.57 rad to the first requested angle (or to the angle a whole
//    number of turns from it nearest 1.57 rad), in steps of its own (walk_in_step_deg).
bool JansenSweepStepper::walk_in_one_pose() {
  const double next = std::abs(walk_to_deg_ - current_deg_) <= walk_in_step_deg
                          ? walk_to_deg_
                          : current_deg_ + std::copysign(walk_in_step_deg, walk_to_deg_ - current_deg_);
  const PoseOutcome outcome = advance_to(next);
  if (outcome.status != Status::converged) return finish(outcome.status);
  current_deg_ = next;
  ++sweep_.walk_in_poses;
  ++poses_;
  if (std::abs(walk_to_deg_ - current_deg_) <= 1e-12) begin_requested_poses();
  return true;
}

// Storage for every requested pose, allocated once: the requested poses allocate nothing. The walk
// has reached the first requested angle, or the same pose whole turns from it.
void JansenSweepStepper::begin_requested_poses() {
  current_deg_ = start_deg_;
  sweep_.angles.resize(angles_.size(), count_);
  sweep_.crank_deg.reserve(static_cast<std::size_t>(count_));
  sweep_.outcomes.reserve(static_cast<std::size_t>(count_));
  phase_ = Phase::requested;
}

// 3. The next requested angle.
bool JansenSweepStepper::solve_requested_pose() {
  const int i = next_;
  const double target = start_deg_ + i * step_deg_;
  PoseOutcome outcome;
  if (i > 0) {
    // The usual case: one solve from the prediction (made in trial_, so that angles_ keeps the
    // last pose solved for the fallbacks).
    predict_next_pose(sweep_.angles, i, trial_);
    outcome = solve_pose(target, target - current_deg_, trial_);
    if (outcome.status == Status::converged) {
      angles_.swap(trial_);
    } else {
      // 4. Halve the step from the prediction; if that fails too, from the last pose.
      predict_next_pose(sweep_.angles, i, angles_);
      outcome = advance_to(target);
      if (outcome.status != Status::converged && i > 1) {
        angles_ = sweep_.angles.col(i - 1);
        outcome = advance_to(target);
      }
    }
  } else {
    outcome = solve_pose(target, target - current_deg_, angles_);  // refine at the start itself
  }
  if (outcome.status != Status::converged) return finish(outcome.status);
  current_deg_ = target;
  sweep_.angles.col(i) = angles_;
  sweep_.crank_deg.push_back(target);
  sweep_.outcomes.push_back(outcome);
  ++poses_;
  if (++next_ == count_) return finish(Status::converged);
  return true;
}

JansenSweepAngles solve_crank_sweep(JansenModel model, JansenPoseSolver& solver, double start_deg, double stop_deg,
                                    double step_deg, const JansenSweepOptions& options,
                                    SweepObserver<JansenSweepStepper>* observer) {
  JansenSweepStepper stepper(model, solver, options);
  stepper.set_observer(observer);
  return stepper.solve(start_deg, stop_deg, step_deg);
}

namespace {

// The closed-form bound of one pose (closed_form_bound.hpp), on the model's closure.
ClosedFormBound jansen_closed_form_bound(JansenModel model, double crank, const Eigen::VectorXd& angles) {
  const JansenLengths L;
  const double links_sum = L.crank + L.l1 + L.l2 + L.l3 + L.l4 + L.l5 + L.l6 + L.l7 + L.l8 + JansenFootLengths{}.l9;
  if (model == JansenModel::eight_equations) {
    return closed_form_bound(JansenClosureOf<LibrarySines>(crank), JansenClosure::Vector(angles), links_sum);
  }
  return closed_form_bound(Jansen10ClosureOf<LibrarySines>(crank), Jansen10Closure::Vector(angles), links_sum);
}

}  // namespace

JansenSweep crank_sweep(JansenModel model, JansenPoseSolver& solver, double start_deg, double stop_deg,
                        double step_deg, const JansenSweepOptions& options,
                        SweepObserver<JansenSweepStepper>* observer) {
  return checked_sweep(model, solve_crank_sweep(model, solver, start_deg, stop_deg, step_deg, options, observer), options);
}

JansenSweep checked_sweep(JansenModel model, const JansenSweepAngles& solved, const JansenSweepOptions& options) {
  const JansenLeg leg;
  JansenSweep sweep;
  sweep.status = solved.status;
  sweep.step_halvings = solved.step_halvings;
  sweep.walk_in_poses = solved.walk_in_poses;
  bool triangles_kept = true;
  for (std::size_t i = 0; i < solved.outcomes.size(); ++i) {
    // Each solved pose: its joints, link lengths, orientation and distance from the closed form.
    JansenPose pose;
    pose.crank_deg = solved.crank_deg[i];
    pose.angles = solved.angles.col(static_cast<Eigen::Index>(i));
    pose.outcome = solved.outcomes[i];
    const double crank = crank_radians(pose.crank_deg);
    pose.joints = jansen_joints(model, leg, crank, pose.angles);
    if (!options.checks) {
      sweep.poses.push_back(std::move(pose));
      continue;
    }
    pose.length_error = leg.worst_length_error(pose.joints);
    if (const auto exact = leg.closed_form_joints(crank)) {
      for (int j = 0; j < jansen_joint_count; ++j) {
        pose.closed_form_distance = std::max(pose.closed_form_distance, (pose.joints[j] - (*exact)[j]).norm());
      }
    } else {
      pose.closed_form_distance = std::numeric_limits<double>::infinity();
    }
    // The distance the pose's residual and conditioning justify; beyond it, the pose is not verified.
    pose.closed_form_bound = jansen_closed_form_bound(model, crank, pose.angles).bound;
    if (!closed_form_verified(pose.closed_form_distance, pose.closed_form_bound, leg.lengths().crank)) {
      sweep.closed_form_verified = false;
    }
    if (JansenLeg::triangle_orientation(pose.joints) != 1) triangles_kept = false;
    sweep.worst_closed_form_distance = std::max(sweep.worst_closed_form_distance, pose.closed_form_distance);
    sweep.worst_closed_form_bound = std::max(sweep.worst_closed_form_bound, pose.closed_form_bound);
    sweep.worst_length_error = std::max(sweep.worst_length_error, pose.length_error);
    sweep.poses.push_back(std::move(pose));
  }
  // The branch is kept when the triangles never flipped and every pose is the closed form's, within
  // its bound; a sweep whose poses are not is no longer converged.
  sweep.orientation_kept = triangles_kept && sweep.closed_form_verified;
  if (sweep.status == Status::converged && !sweep.closed_form_verified) sweep.status = Status::no_progress;
  return sweep;
}

}  // namespace numlab::mechanisms
