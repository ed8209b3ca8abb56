#include "numlab/mechanisms/linkage/linkage_solver.hpp"

#include <fmt/format.h>

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "linkage_joints.hpp"
#include "numlab/mechanisms/circle_intersection.hpp"
#include "numlab/nonlinear/gsl_multiroot.hpp"
#include "numlab/nonlinear/linear_step.hpp"
#include "numlab/nonlinear/sequential_newton.hpp"

namespace numlab::mechanisms {

using detail::centre_of;
using detail::cross;
using detail::dyad_parts;
using detail::foot_on_line;
using detail::joint_at;

const std::vector<std::string>& linkage_solver_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> out{"full", "sequential", "analytic"};
    for (const std::string& type : nonlinear::gsl_multiroot_types()) out.push_back("gsl-" + type);
    return out;
  }();
  return names;
}

namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

int sign_of(double value) { return value >= 0.0 ? 1 : -1; }

// Of a dyad's two solutions, the one nearer where the joint was (or is predicted to be).
Eigen::Vector2d nearer(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& near) {
  return (a - near).squaredNorm() <= (b - near).squaredNorm() ? a : b;
}

double residual_norm(const LinkageModel& model, const Eigen::VectorXd& q, double t) {
  Eigen::VectorXd f;
  model.residual(q, t, f);
  return f.size() == 0 ? 0.0 : f.lpNorm<Eigen::Infinity>();
}

}  // namespace

LinkageSolver::LinkageSolver(const LinkageModel& model, LinkageSolverOptions options)
    : model_(model), options_(std::move(options)), blocks_(linkage_blocks(model)) {
  const auto& names = linkage_solver_names();
  if (std::find(names.begin(), names.end(), options_.solver) == names.end()) {
    throw std::invalid_argument("unknown linkage solver '" + options_.solver + "'");
  }
  (void)nonlinear::linear_method_named(options_.linear);  // throws for an unknown name
  if (options_.solver == "analytic") {
    for (std::size_t b = 0; b < blocks_.size(); ++b) {
      if (!blocks_[b].closed_form()) {
        throw std::invalid_argument(fmt::format("--solver analytic needs every block in closed form; block {} ({}) is not",
                                                b + 1, describe_block(model_, blocks_[b])));
      }
    }
  }
  // The size tolerances are relative to: the longest link.
  double longest = 0.0;
  for (const Constraint& c : model_.constraints()) {
    if (c.kind == ConstraintKind::distance || c.kind == ConstraintKind::crank) longest = std::max(longest, c.length);
  }
  if (longest > 0.0 && std::isfinite(longest)) size_ = longest;
  if (options_.tolerance_relative_to_size) {
    options_.newton.residual_tolerance *= size_;
    // The step test is ||dx|| <= tol (1 + ||x||): below size 1 the 1 would make it absolute.
    options_.newton.step_tolerance *= std::min(1.0, size_);
    options_.tolerance_relative_to_size = false;  // applied: options() holds the absolute tolerance
  }
  // The reference pose: damped Newton from the file's rough positions.
  reference_driver_ = model_.driver_from_user(model_.description().driver.reference);
  nonlinear::NewtonOptions newton = options_.newton;
  newton.damped = true;
  newton.max_iterations = std::max(newton.max_iterations, 100);
  const LinkageSystem system(model_, reference_driver_);
  const auto result = nonlinear::newton_solve(system, model_.unknowns(model_.rough_positions()), newton);
  if (result.status != Status::converged) {
    const auto& d = model_.description();
    throw LinkageFileError(d.file, d.driver.place,
                           fmt::format("the reference pose does not assemble: damped Newton from the rough joint positions "
                                       "at driver {:g} ends {} with ||Phi||_inf = {:.3g}",
                                       d.driver.reference, to_string(result.status), result.residual_norm));
  }
  reference_ = result.x;
  reference_signature_ = signature(reference_, reference_driver_);
}

LinkageSolution LinkageSolver::solve(double t, const Eigen::VectorXd& q0) const {
  if (options_.solver == "full") return solve_full(t, q0);
  if (options_.solver == "sequential") return solve_sequential(t, q0);
  if (options_.solver == "analytic") return closed_form(t, q0);
  return solve_gsl(t, q0);
}

LinkageSolution LinkageSolver::solve_full(double t, const Eigen::VectorXd& q0) const {
  const LinkageSystem system(model_, t);
  // Past an assembly limit a sweep makes hundreds of Newton runs that cannot succeed (every
  // continuation halving, every bisection step), and there J is nearly singular: an iterative inner
  // solve (Gauss-Seidel on the normal equations, ~kappa(J)^2 sweeps) reaches its sweep limit. The
  // first such capped solve whose step does not decrease ||f|| ends the run (newton.hpp,
  // inner_step_failed) instead of up to twenty of them; capped solves that still decrease ||f||, as
  // near a change point, go on.
  nonlinear::NewtonOptions newton_options = options_.newton;
  newton_options.stop_on_failed_inner_step = true;
  nonlinear::Newton<LinkageSystem, nonlinear::RuntimeLinearStep> newton(
      system, newton_options, nonlinear::RuntimeLinearStep(options_.linear, system.dimension()));
  auto result = newton.solve(q0);
  return {std::move(result.x), static_cast<nonlinear::NewtonCounts>(result), -1};
}

namespace {

// The system in shifted unknowns z = q + shift, for GSL's types that estimate J themselves. GSL's finite-difference Jacobian steps by
// sqrt(eps) |z_j|, which is ~1e-31 for a coordinate that is zero up to rounding (a joint on an
// axis: 4.7e-23); with every z_j >= 1 the step is sane. The residuals, and so the stop tests, are
// those of q.
class ShiftedSystem final : public nonlinear::DynamicSystem {
 public:
  ShiftedSystem(const LinkageSystem& system, Eigen::VectorXd shift) : system_(system), shift_(std::move(shift)) {}
  int dimension() const override { return system_.dimension(); }
  void residual(const Eigen::VectorXd& z, Eigen::VectorXd& f) const override { system_.residual(z - shift_, f); }
  void jacobian(const Eigen::VectorXd& z, Eigen::MatrixXd& J) const override { system_.jacobian(z - shift_, J); }

 private:
  const LinkageSystem& system_;
  Eigen::VectorXd shift_;
};

}  // namespace

LinkageSolution LinkageSolver::solve_gsl(double t, const Eigen::VectorXd& q0) const {
  const LinkageSystem system(model_, t);
  const std::string type = options_.solver.substr(4);
  const bool finite_differences = type == "hybrids" || type == "hybrid" || type == "dnewton" || type == "broyden";
  if (!finite_differences) {  // the types given J need no shift (and its size would loosen their step test)
    auto result = nonlinear::gsl_multiroot_solve(system, q0, type, options_.newton);
    return {std::move(result.x), static_cast<nonlinear::NewtonCounts>(result), -1};
  }
  const double size = q0.size() == 0 ? 0.0 : q0.lpNorm<Eigen::Infinity>();
  const Eigen::VectorXd shift = Eigen::VectorXd::Constant(q0.size(), 2.0 * (1.0 + size));
  const ShiftedSystem shifted(system, shift);
  auto result = nonlinear::gsl_multiroot_solve(shifted, q0 + shift, type, options_.newton);
  return {Eigen::VectorXd(result.x - shift), static_cast<nonlinear::NewtonCounts>(result), -1};
}

// The blocks in order. An explicit block (a crank, a body point, a driven slider) is placed
// directly: no equation to solve. Any other block by Newton with every other unknown held: the 2x2
// closed-form inverse for a two-unknown block, GEPP for a bigger one.
LinkageSolution LinkageSolver::solve_sequential(double t, const Eigen::VectorXd& q0) const {
  const LinkageSystem whole(model_, t);
  LinkageSolution solution{q0, {}, -1};
  int evaluations = 0;
  nonlinear::BlockSystem block_system(whole, solution.q, evaluations);
  const Eigen::Vector2d crank = detail::crank_direction(model_, t);
  solution.outcome.status = Status::converged;
  solution.outcome.reason = nonlinear::StopReason::residual_small;
  for (std::size_t b = 0; b < blocks_.size(); ++b) {
    const nonlinear::Block& block = blocks_[b].rows_and_columns;
    block_system.select(block);
    const int n = static_cast<int>(block.unknowns.size());
    Eigen::VectorXd start(n);
    for (int i = 0; i < n; ++i) start(i) = solution.q(block.unknowns[static_cast<std::size_t>(i)]);
    nonlinear::NewtonCounts result;
    if (blocks_[b].placed_directly()) {
      // 1. A crank, body point or driven slider is placed directly: no equation to solve.
      detail::place_block(model_, blocks_[b], t, crank, solution.q);
      // 2. Its rows at the placed joint must still pass the residual test.
      Eigen::VectorXd placed(n), rows;
      for (int i = 0; i < n; ++i) placed(i) = solution.q(block.unknowns[static_cast<std::size_t>(i)]);
      block_system.residual(placed, rows);
      result = detail::placed_block_counts(rows, options_.newton.residual_tolerance);
    } else {
      // 3. Any other block: Newton on its rows, the joints solved before held.
      const auto method = n == 2 ? nonlinear::LinearMethod::inverse2x2 : nonlinear::LinearMethod::gepp;
      nonlinear::Newton<nonlinear::BlockSystem, nonlinear::RuntimeLinearStep> newton(
          block_system, options_.newton, nonlinear::RuntimeLinearStep(method, n));
      const auto newton_result = newton.solve(start);
      for (int i = 0; i < n; ++i) solution.q(block.unknowns[static_cast<std::size_t>(i)]) = newton_result.x(i);
      result = newton_result;
    }
    solution.outcome.iterations += result.iterations;
    solution.outcome.jacobian_evaluations += result.jacobian_evaluations;
    solution.outcome.step_norm = result.step_norm;
    if (result.status != Status::converged) {
      solution.outcome.status = result.status;
      solution.outcome.reason = result.reason;
      solution.failed_block = static_cast<int>(b);
      break;
    }
  }
  solution.outcome.function_evaluations = evaluations;
  solution.outcome.residual_norm = residual_norm(model_, solution.q, t);
  // Every block converged, so the whole residual is small unless a block's test was too loose.
  if (solution.outcome.status == Status::converged && !(solution.outcome.residual_norm <= options_.newton.residual_tolerance)) {
    solution.outcome.status = Status::no_progress;
    solution.outcome.reason = nonlinear::StopReason::no_progress;
  }
  return solution;
}

LinkageSolution LinkageSolver::closed_form(double t, const Eigen::VectorXd& q0) const {
  LinkageSolution solution{q0, {}, -1};
  solution.failed_block = detail::closed_form_in_place(model_, blocks_, t, solution.q);
  solution.outcome.status = solution.failed_block < 0 ? Status::converged : Status::cannot_assemble;
  solution.outcome.reason = solution.failed_block < 0 ? nonlinear::StopReason::residual_small : nonlinear::StopReason::running;
  solution.outcome.residual_norm = residual_norm(model_, solution.q, t);
  if (solution.failed_block < 0 && !(solution.outcome.residual_norm <= options_.newton.residual_tolerance)) {
    solution.outcome.status = Status::no_progress;
    solution.outcome.reason = nonlinear::StopReason::no_progress;
  }
  return solution;
}

int detail::closed_form_in_place(const LinkageModel& model, const std::vector<LinkageBlock>& blocks, double t,
                                 Eigen::VectorXd& q) {
  return closed_form_in_place(model, blocks, t, crank_direction(model, t), q);
}

int detail::closed_form_in_place(const LinkageModel& model, const std::vector<LinkageBlock>& blocks, double t,
                                 const Eigen::Vector2d& crank_direction, Eigen::VectorXd& q) {
  for (std::size_t b = 0; b < blocks.size(); ++b) {
    if (!place_block(model, blocks[b], t, crank_direction, q)) return static_cast<int>(b);
  }
  return -1;
}

bool detail::place_block(const LinkageModel& model, const LinkageBlock& block, double t, const Eigen::Vector2d& crank_direction,
                         Eigen::VectorXd& q) {
  const auto at = [&](int joint) { return joint_at(model, q, joint); };
  if (block.kind == BlockKind::newton) return false;
  const int joint = block.joints[0];
  const Eigen::Vector2d was = at(joint);  // the start's place: q's entries of this joint are not written yet
  const Constraint& c = model.constraints()[static_cast<std::size_t>(block.constraints[0])];
  switch (block.kind) {
    case BlockKind::crank:  // 1. p_A = p_O + r u(t)
      set_joint(model, q, joint, at(c.joints[0]) + c.length * (c.held ? c.direction : crank_direction));
      break;
    case BlockKind::body_point: {  // 2. p_c = p_b0 + a base + b perp(base)
      const Eigen::Vector2d base = at(c.joints[1]) - at(c.joints[0]);
      set_joint(model, q, joint, at(c.joints[0]) + c.coefficients.x() * base + c.coefficients.y() * Eigen::Vector2d(-base.y(), base.x()));
      break;
    }
    case BlockKind::slider: {  // 3. p = P + s u
      const Constraint& line = c.kind == ConstraintKind::slider_travel ? c : model.constraints()[static_cast<std::size_t>(block.constraints[1])];
      set_joint(model, q, joint, line.point + (line.held ? line.held_value : t) * line.direction);
      break;
    }
    case BlockKind::circle_circle: {  // 4. two circles meet: the point nearer the start's (continuation)
      const auto [first, second] = dyad_parts(model, block);
      const Eigen::Vector2d c1 = at(centre_of(*first, joint)), c2 = at(centre_of(*second, joint));
      const auto left = circle_intersection(c1, first->length, c2, second->length, 1);
      const auto right = circle_intersection(c1, first->length, c2, second->length, -1);
      if (!left || !right) return false;
      set_joint(model, q, joint, nearer(*left, *right, was));
      break;
    }
    case BlockKind::circle_line: {  // 5. a circle meets a line: the point nearer the start's
      const auto [circle, line] = dyad_parts(model, block);
      const Eigen::Vector2d centre = at(centre_of(*circle, joint)), foot = foot_on_line(*line, centre);
      double half_chord_squared = circle->length * circle->length - (centre - foot).squaredNorm();
      // A circle that touches the line gives zero less rounding: that is zero.
      const double rounding = 8.0 * std::numeric_limits<double>::epsilon() * (circle->length * circle->length + (centre - foot).squaredNorm());
      if (half_chord_squared < 0.0 && half_chord_squared >= -rounding) half_chord_squared = 0.0;
      if (!(half_chord_squared >= 0.0)) return false;
      const Eigen::Vector2d along = std::sqrt(half_chord_squared) * line->direction;
      set_joint(model, q, joint, nearer(foot + along, foot - along, was));
      break;
    }
    case BlockKind::slot_pivot: {  // 6. a slotted link about K through the known joint A: J = K + L u
      const auto [distance, slot] = dyad_parts(model, block);
      const int centre = centre_of(*distance, joint);
      const Eigen::Vector2d pivot = at(centre), d = at(slot->joints[0]) - pivot;
      // The slot's offset to the left of K -> J (the file states it from `from` to `to`).
      const double offset = slot->joints[1] == centre ? slot->offset : -slot->offset;
      const double rho = d.norm();
      if (!(rho > 0.0) || !(std::abs(offset) <= rho)) return false;  // no line through K passes A at that offset
      // u makes the angle alpha with d, sin alpha = offset / rho, cos alpha = +-sqrt(1 - sin^2): A is then
      // `offset` to the line's left; the two signs are the two solutions.
      const double sine = offset / rho, cosine = std::sqrt(std::max(0.0, 1.0 - sine * sine));
      const Eigen::Vector2d d_hat = d / rho, d_perp(d_hat.y(), -d_hat.x());  // d_hat turned by -90 deg
      const Eigen::Vector2d towards = pivot + distance->length * (cosine * d_hat + sine * d_perp);
      const Eigen::Vector2d away = pivot + distance->length * (-cosine * d_hat + sine * d_perp);
      set_joint(model, q, joint, nearer(towards, away, was));
      break;
    }
    case BlockKind::newton:
      return false;
  }
  return true;
}

std::vector<int> LinkageSolver::signature(const Eigen::VectorXd& q, double t) const {
  std::vector<int> out(blocks_.size(), 0);
  Eigen::MatrixXd J;
  for (std::size_t b = 0; b < blocks_.size(); ++b) {
    const LinkageBlock& block = blocks_[b];
    if (block.kind == BlockKind::circle_circle) {
      const auto [first, second] = dyad_parts(model_, block);
      const int joint = block.joints[0];
      const Eigen::Vector2d k1 = joint_at(model_, q, centre_of(*first, joint)), k2 = joint_at(model_, q, centre_of(*second, joint));
      out[b] = sign_of(cross(k2 - k1, joint_at(model_, q, joint) - k1));
    } else if (block.kind == BlockKind::circle_line) {
      const auto [circle, line] = dyad_parts(model_, block);
      const int joint = block.joints[0];
      const Eigen::Vector2d foot = foot_on_line(*line, joint_at(model_, q, centre_of(*circle, joint)));
      out[b] = sign_of((joint_at(model_, q, joint) - foot).dot(line->direction));
    } else if (block.kind == BlockKind::slot_pivot) {  // the slotted link pointing towards A or away
      const auto [distance, slot] = dyad_parts(model_, block);
      const Eigen::Vector2d pivot = joint_at(model_, q, centre_of(*distance, block.joints[0]));
      out[b] = sign_of((joint_at(model_, q, block.joints[0]) - pivot).dot(joint_at(model_, q, slot->joints[0]) - pivot));
    } else if (block.kind == BlockKind::newton) {
      if (J.size() == 0) model_.jacobian(q, t, J);
      const auto& rc = block.rows_and_columns;
      const int n = static_cast<int>(rc.unknowns.size());
      Eigen::MatrixXd sub(n, n);
      for (int i = 0; i < n; ++i) {
        for (int j = 0; j < n; ++j) sub(i, j) = J(rc.equations[static_cast<std::size_t>(i)], rc.unknowns[static_cast<std::size_t>(j)]);
      }
      out[b] = sign_of(sub.determinant());
    }
  }
  return out;
}

std::vector<double> LinkageSolver::transmission_angles(const Eigen::VectorXd& q) const {
  std::vector<double> out(blocks_.size(), nan);
  const auto angle_between = [](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return std::atan2(std::abs(cross(a, b)), a.dot(b)) * 180.0 / std::numbers::pi;
  };
  for (std::size_t b = 0; b < blocks_.size(); ++b) {
    const LinkageBlock& block = blocks_[b];
    if (!block.dyad()) continue;
    const int joint = block.joints[0];
    const Eigen::Vector2d p = joint_at(model_, q, joint);
    const auto [first, second] = dyad_parts(model_, block);
    const Eigen::Vector2d link = joint_at(model_, q, centre_of(*first, joint)) - p;
    if (block.kind == BlockKind::circle_circle) {
      out[b] = angle_between(link, joint_at(model_, q, centre_of(*second, joint)) - p);
    } else {
      out[b] = angle_between(link, Eigen::Vector2d(-second->direction.y(), second->direction.x()));
    }
  }
  return out;
}

std::vector<double> LinkageSolver::dyad_margins(const Eigen::VectorXd& q) const {
  std::vector<double> out(blocks_.size(), nan);
  for (std::size_t b = 0; b < blocks_.size(); ++b) {
    const LinkageBlock& block = blocks_[b];
    if (!block.dyad()) continue;
    const int joint = block.joints[0];
    const auto [first, second] = dyad_parts(model_, block);
    const Eigen::Vector2d centre = joint_at(model_, q, centre_of(*first, joint));
    if (block.kind == BlockKind::circle_circle) {
      const double d = (joint_at(model_, q, centre_of(*second, joint)) - centre).norm();
      out[b] = std::min(d - std::abs(first->length - second->length), first->length + second->length - d);
    } else {
      out[b] = first->length - (centre - foot_on_line(*second, centre)).norm();
    }
  }
  return out;
}

}  // namespace numlab::mechanisms
