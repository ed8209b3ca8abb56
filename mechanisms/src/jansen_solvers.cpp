#include "numlab/mechanisms/jansen_solvers.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "numlab/linalg/eigen_reference.hpp"
#include "numlab/linalg/gauss_elimination.hpp"
#include "numlab/linalg/gauss_seidel.hpp"
#include "numlab/mechanisms/anchored_sincos.hpp"
#include "numlab/mechanisms/dyad_newton.hpp"
#include "numlab/mechanisms/jansen10_closure.hpp"
#include "numlab/nonlinear/block_order.hpp"
#include "numlab/nonlinear/dynamic_adapter.hpp"
#include "numlab/nonlinear/gsl_multiroot.hpp"
#include "numlab/nonlinear/linear_step.hpp"
#include "numlab/nonlinear/sequential_newton.hpp"

namespace numlab::mechanisms {

namespace {

constexpr double degrees = std::numbers::pi / 180.0;
std::size_t at(JansenJoint joint) { return static_cast<std::size_t>(joint); }
Eigen::Vector2d unit(double angle) { return {std::cos(angle), std::sin(angle)}; }
double direction(const Eigen::Vector2d& from, const Eigen::Vector2d& to) { return std::atan2(to.y() - from.y(), to.x() - from.x()); }

PoseOutcome outcome_of(const nonlinear::NewtonCounts& result) { return {result.status, result.iterations, result.residual_norm}; }

// Full Newton on a fixed-size closure (8 or 10 equations) with a compile-time linear solver.
template <typename Closure, typename LinearStep>
class FullNewton final : public JansenPoseSolver {
 public:
  explicit FullNewton(const nonlinear::NewtonOptions& options) : closure_(0.0), newton_(closure_, options) {}
  FullNewton(const nonlinear::NewtonOptions& options, LinearStep linear_step)
      : closure_(0.0), newton_(closure_, options, std::move(linear_step)) {}
  PoseOutcome solve(double crank_angle, Eigen::VectorXd& angles) override {
    closure_.set_crank_angle(crank_angle);
    const auto result = newton_.solve(typename Closure::Vector(angles));
    angles = result.x;
    return outcome_of(result);
  }

 private:
  Closure closure_;
  nonlinear::Newton<Closure, LinearStep> newton_;
};

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
      total.residual_inf = std::max(total.residual_inf, newton.residual_norm());
      if (status != Status::converged) total.status = status;
      return status == Status::converged;
    };
    // u(theta1), u(theta3), u(theta7) in (y, x) order, from the blocks that solved them.
    auto direction = [&](int b, int which) { return blocks_[b].direction(which); };
    const bool ok = block(0, crank, L.l1, L.l2) &&
                    block(1, crank + L.l1 * direction(0, 0), L.l3, L.l4) &&
                    block(2, crank, L.l6, L.l7) &&
                    block(3, crank + L.l1 * direction(0, 0) + L.l3 * direction(1, 0) - L.l7 * direction(2, 1), L.l5, L.l8);
    (void)ok;  // a failed block has set total.status, and the blocks after it were not tried
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
    const auto result = nonlinear::sequential_newton(dynamic_, blocks_, angles, options_, "inverse2x2");
    angles = result.x;
    return {result.status, result.iterations, result.residual_norm};
  }

 private:
  nonlinear::NewtonOptions options_;
  Closure closure_;
  nonlinear::AsDynamicSystem<Closure> dynamic_;
  std::vector<nonlinear::Block> blocks_;
};

// One of GSL's solvers, allocated once and reused for every pose (as FullNewton's Newton is).
template <typename Closure>
class GslSolver final : public JansenPoseSolver {
 public:
  GslSolver(const std::string& type, const nonlinear::NewtonOptions& options)
      : options_(options), closure_(0.0), dynamic_(closure_), gsl_(dynamic_, type) {}
  PoseOutcome solve(double crank_angle, Eigen::VectorXd& angles) override {
    closure_.set_crank_angle(crank_angle);
    const auto result = gsl_.solve(angles, options_);
    angles = result.x;
    return {result.status, result.iterations, result.residual_norm};
  }

 private:
  nonlinear::NewtonOptions options_;
  Closure closure_;
  nonlinear::AsDynamicSystem<Closure> dynamic_;
  nonlinear::GslMultiroot gsl_;
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

template <typename Closure>
std::unique_ptr<JansenPoseSolver> make_full(const std::string& linear, const nonlinear::NewtonOptions& options) {
  constexpr int N = Closure::size;
  if (linear == "gepp") return std::make_unique<FullNewton<Closure, linalg::GaussElimination<N>>>(options);
  if (linear == "gauss-seidel") {
    // An inexact inner solve slows Newton down, a very inexact one stops it: sweep the normal
    // equations until the update is far below Newton's own tolerance.
    linalg::GaussSeidelOptions inner;
    inner.tolerance = std::min(1e-9, 1e-3 * options.residual_tolerance);
    inner.max_iterations = 100000;
    return std::make_unique<FullNewton<Closure, linalg::GaussSeidel<N>>>(options, linalg::GaussSeidel<N>(inner));
  }
  if (linear == "gsl-lu") return std::make_unique<FullNewton<Closure, nonlinear::GslLuStep<N>>>(options);
  if (linear == "eigen-lu") return std::make_unique<FullNewton<Closure, linalg::EigenLu<N>>>(options);
  throw std::invalid_argument("unknown linear method '" + linear + "' for full Newton (expected gepp, gauss-seidel, "
                              "gsl-lu or eigen-lu)");
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
    return eight ? make_full<JansenClosureOf<TableSines>>(linear, options)
                 : make_full<Jansen10ClosureOf<TableSines>>(linear, options);
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
    if (eight) return std::make_unique<GslSolver<JansenClosureOf<TableSines>>>(type, options);
    return std::make_unique<GslSolver<Jansen10ClosureOf<TableSines>>>(type, options);
  }
  throw std::invalid_argument("unknown solver '" + solver + "' (expected full, sequential, analytic or gsl-<type>)");
}

JansenSweepAngles solve_crank_sweep(JansenModel model, JansenPoseSolver& solver, double start_deg, double stop_deg,
                                    double step_deg) {
  if (!(step_deg != 0.0) || !std::isfinite(start_deg) || !std::isfinite(stop_deg) || !std::isfinite(step_deg) ||
      (stop_deg - start_deg) * step_deg < 0.0) {
    throw std::invalid_argument("sweep " + std::to_string(start_deg) + ":" + std::to_string(stop_deg) + ":" +
                                std::to_string(step_deg) + " does not step from its start towards its stop");
  }
  JansenSweepAngles sweep;
  Eigen::VectorXd angles = jansen_seed_estimates(model, JansenLeg());
  double current_deg = JansenClosure::seed_crank_angle / degrees;

  // Moves from current_deg to target_deg: tries the whole step; when a solve fails, halves the
  // step and tries again from the last pose that solved (at most 20 halvings in all).
  Eigen::VectorXd trial = angles;  // buffer reused from pose to pose (no allocation per pose)
  auto advance_to = [&](double target_deg) -> PoseOutcome {
    double reached = current_deg, step = target_deg - current_deg;
    int halvings = 0;
    while (true) {
      const bool whole_way = step == target_deg - reached;
      const double next = whole_way ? target_deg : reached + step;
      trial = angles;
      const PoseOutcome outcome = solver.solve(next * degrees, trial);
      if (outcome.status == Status::converged) {
        angles = trial;
        reached = next;
        if (whole_way) return outcome;
        step = target_deg - reached;  // aim for the target again
      } else {
        if (++halvings > 20) return outcome;
        ++sweep.step_halvings;
        step *= 0.5;
      }
    }
  };

  // Solve at 1.57 rad from the seed's estimates, then walk to the first requested angle.
  PoseOutcome outcome = solver.solve(current_deg * degrees, angles);
  if (outcome.status != Status::converged) {
    sweep.status = outcome.status;
    return sweep;
  }
  const double walk_step = std::abs(step_deg);
  while (std::abs(start_deg - current_deg) > 1e-12) {
    const double next = std::abs(start_deg - current_deg) <= walk_step
                            ? start_deg
                            : current_deg + std::copysign(walk_step, start_deg - current_deg);
    outcome = advance_to(next);
    if (outcome.status != Status::converged) {
      sweep.status = outcome.status;
      return sweep;
    }
    current_deg = next;
    ++sweep.walk_in_poses;
  }

  // Storage for every pose, allocated once: the loop below allocates nothing.
  const int count = static_cast<int>(std::floor((stop_deg - start_deg) / step_deg + 1e-9)) + 1;
  sweep.angles.resize(angles.size(), count);
  sweep.crank_deg.reserve(static_cast<std::size_t>(count));
  sweep.outcomes.reserve(static_cast<std::size_t>(count));
  for (int i = 0; i < count; ++i) {
    const double target = start_deg + i * step_deg;
    if (i > 0) {
      // The usual case: one solve from the prediction (made in `trial`, so that `angles` keeps the
      // last pose solved for the fallbacks).
      predict_next_pose(sweep.angles, i, trial);
      outcome = solver.solve(target * degrees, trial);
      if (outcome.status == Status::converged) {
        angles.swap(trial);
      } else {
        // Halve the step from the prediction; if that fails too, from the last pose.
        predict_next_pose(sweep.angles, i, angles);
        outcome = advance_to(target);
        if (outcome.status != Status::converged && i > 1) {
          angles = sweep.angles.col(i - 1);
          outcome = advance_to(target);
        }
      }
    } else {
      outcome = solver.solve(target * degrees, angles);  // refine at the start itself
    }
    if (outcome.status != Status::converged) {
      sweep.status = outcome.status;
      break;
    }
    current_deg = target;
    sweep.angles.col(i) = angles;
    sweep.crank_deg.push_back(target);
    sweep.outcomes.push_back(outcome);
  }
  return sweep;
}

JansenSweep crank_sweep(JansenModel model, JansenPoseSolver& solver, double start_deg, double stop_deg,
                        double step_deg) {
  const JansenSweepAngles solved = solve_crank_sweep(model, solver, start_deg, stop_deg, step_deg);
  const JansenLeg leg;
  JansenSweep sweep;
  sweep.status = solved.status;
  sweep.step_halvings = solved.step_halvings;
  sweep.walk_in_poses = solved.walk_in_poses;
  for (std::size_t i = 0; i < solved.outcomes.size(); ++i) {
    // Each solved pose: its joints, link lengths, orientation and distance from the closed form.
    JansenPose pose;
    pose.crank_deg = solved.crank_deg[i];
    pose.angles = solved.angles.col(static_cast<Eigen::Index>(i));
    pose.outcome = solved.outcomes[i];
    pose.joints = jansen_joints(model, leg, pose.crank_deg * degrees, pose.angles);
    pose.length_error = leg.worst_length_error(pose.joints);
    if (const auto exact = leg.closed_form_joints(pose.crank_deg * degrees)) {
      for (int j = 0; j < jansen_joint_count; ++j) {
        pose.closed_form_distance = std::max(pose.closed_form_distance, (pose.joints[j] - (*exact)[j]).norm());
      }
    } else {
      pose.closed_form_distance = std::numeric_limits<double>::infinity();
    }
    if (JansenLeg::triangle_orientation(pose.joints) != 1) sweep.orientation_kept = false;
    sweep.worst_closed_form_distance = std::max(sweep.worst_closed_form_distance, pose.closed_form_distance);
    sweep.worst_length_error = std::max(sweep.worst_length_error, pose.length_error);
    sweep.poses.push_back(std::move(pose));
  }
  return sweep;
}

}  // namespace numlab::mechanisms
