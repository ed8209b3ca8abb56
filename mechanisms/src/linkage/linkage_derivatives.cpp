// Positions solved to rounding, the kinematics of a pose where J cannot give them (on a crossing:
// differences of positions solved along the pose's branch), and the check of J's kinematics against
// differences of positions.
#include <array>
#include <cmath>
#include <limits>
#include <optional>

#include <Eigen/SparseCore>
#include <Eigen/SparseLU>

#include "linkage_crossings.hpp"
#include "numlab/mechanisms/linkage/linkage_conditioning.hpp"
#include "numlab/mechanisms/linkage/linkage_sweep.hpp"

namespace numlab::mechanisms {

namespace {

// Newton to `tolerance` on J's sparse LU (a few nonzeros per row), for models beyond 100 unknowns
// where a dense LU per step is O(n^3); at most 60 steps, each of which must not make ||Phi|| grow
// tenfold.
std::optional<Eigen::VectorXd> sparse_newton(const LinkageModel& model, double s, Eigen::VectorXd q, double tolerance) {
  Eigen::VectorXd f;
  for (int k = 0; k <= 60; ++k) {
    model.residual(q, s, f);
    const double norm = f.size() == 0 ? 0.0 : f.lpNorm<Eigen::Infinity>();
    if (!std::isfinite(norm)) return std::nullopt;
    if (norm <= tolerance) return q;
    if (k == 60) break;
    const Eigen::SparseMatrix<double> sparse = linkage_sparse_jacobian(model, s, q);
    Eigen::SparseLU<Eigen::SparseMatrix<double>> lu;
    lu.compute(sparse);
    if (lu.info() != Eigen::Success) return std::nullopt;
    const Eigen::VectorXd dx = lu.solve(-f);
    if (lu.info() != Eigen::Success || !dx.allFinite()) return std::nullopt;
    q += dx;
  }
  return std::nullopt;
}

}  // namespace

std::optional<Eigen::VectorXd> detail::solve_to_rounding(const LinkageSolver& solver, double s, const Eigen::VectorXd& start) {
  nonlinear::NewtonOptions newton = solver.options().newton;
  const double scale = (start.size() == 0 ? 0.0 : start.lpNorm<Eigen::Infinity>()) + solver.size();
  newton.residual_tolerance = 64.0 * std::numeric_limits<double>::epsilon() * scale;
  if (start.size() > linkage_exact_conditioning_limit) return sparse_newton(solver.model(), s, start, newton.residual_tolerance);
  newton.max_iterations = 60;  // linear convergence at a singular pose halves the error each step
  newton.damped = false;
  const LinkageSystem system(solver.model(), s);
  auto result = nonlinear::newton_solve(system, start, newton);
  if (result.status != Status::converged) return std::nullopt;
  return std::move(result.x);
}

bool detail::branch_kinematics(const LinkageSolver& solver, double t, double h, const BranchGuess& guess,
                               Eigen::VectorXd& velocity, Eigen::VectorXd& acceleration) {
  std::array<Eigen::VectorXd, 7> p;
  for (int k = -3; k <= 3; ++k) {
    const double s = t + k * h;
    const auto solved = solve_to_rounding(solver, s, guess(s));
    if (!solved) return false;
    p[static_cast<std::size_t>(k + 3)] = *solved;
  }
  // The 7-point stencils (6th order): q' and q'' at t.
  velocity = (-p[0] + 9.0 * p[1] - 45.0 * p[2] + 45.0 * p[4] - 9.0 * p[5] + p[6]) / (60.0 * h);
  acceleration = (2.0 * (p[0] + p[6]) - 27.0 * (p[1] + p[5]) + 270.0 * (p[2] + p[4]) - 490.0 * p[3]) / (180.0 * h * h);
  return velocity.allFinite() && acceleration.allFinite();
}

namespace {

// The 7-point stencil (6th order) for q'' at t from positions along the pose's branch at t + k h,
// solved outwards from the pose, each predicted by the polynomial through the ones before it (the
// tangent, the line, the quadratic) and kept on the smooth branch's side (a stencil that reaches
// past a crossing stays on the pose's branch). Empty when a position does not solve.
std::optional<Eigen::VectorXd> stencil_acceleration(const LinkageSolver& solver, double t, const Eigen::VectorXd& q,
                                                    const Eigen::VectorXd& velocity, double h) {
  std::array<std::optional<Eigen::VectorXd>, 7> s;
  s[3] = q;
  for (const int side : {1, -1}) {
    const auto at = [&](int k) -> const Eigen::VectorXd& { return *s[static_cast<std::size_t>(3 + side * k)]; };
    for (int k = 1; k <= 3; ++k) {
      const Eigen::VectorXd guess = k == 1   ? Eigen::VectorXd(q + velocity * (side * h))
                                    : k == 2 ? Eigen::VectorXd(2.0 * at(1) - at(0))
                                             : Eigen::VectorXd(3.0 * at(2) - 3.0 * at(1) + at(0));
      auto& point = s[static_cast<std::size_t>(3 + side * k)];
      point = detail::solve_to_rounding(solver, t + side * k * h, guess);
      if (!point) return std::nullopt;
      detail::keep_smooth_sides(solver, t + side * (k - 1) * h, at(k - 1), t + side * k * h, *point);
    }
  }
  return Eigen::VectorXd((2.0 * (*s[0] + *s[6]) - 27.0 * (*s[1] + *s[5]) + 270.0 * (*s[2] + *s[4]) - 490.0 * *s[3]) /
                         (180.0 * h * h));
}

}  // namespace

DerivativeCheck check_derivatives(const LinkageSolver& solver, double t_given, const Eigen::VectorXd& q_near) {
  const LinkageModel& model = solver.model();
  DerivativeCheck check;
  // A crank's pose repeats every turn: the differences are taken within the first turn, where t + h
  // is t plus h to rounding (at crank 1e9 deg, t's last bit is 4e-9 rad: 4e-4 of h = 1e-5).
  const double t = model.crank_driven() ? std::remainder(t_given, 2.0 * std::acos(-1.0)) : t_given;
  // The reading's units: a crank's velocity is a length per radian, a slider's a length per length.
  check.velocity_reference = model.crank_driven() ? solver.size() : 1.0;
  check.acceleration_reference = model.crank_driven() ? solver.size() : 1.0 / solver.size();
  // Positions at t + k h, solved to rounding level by full Newton, each from the tangent's
  // prediction (from the pose itself near a singular pose): the pose itself too, since a sweep's
  // pose is only as exact as its tolerance.
  const auto q = detail::solve_to_rounding(solver, t, q_near);
  if (!q) {
    check.solved = false;
    return check;
  }
  check.condition = linkage_conditioning(model, t, *q).condition;
  if (!(check.condition <= detail::singular_condition)) {
    check.singular = true;  // J gives no velocity here: the sweep took it from differences already
    for (const double margin : solver.dyad_margins(*q)) {
      if (margin <= 1e-3 * solver.size()) check.near_meeting_point = true;  // NaN (not a dyad): false
    }
    return check;
  }
  Eigen::VectorXd velocity, acceleration;
  linkage_kinematics(model, t, *q, velocity, acceleration);
  check.velocity_scale = velocity.size() == 0 ? 0.0 : velocity.lpNorm<Eigen::Infinity>();
  check.acceleration_scale = acceleration.size() == 0 ? 0.0 : acceleration.lpNorm<Eigen::Infinity>();
  const auto solve_at = [&](double s) { return detail::solve_to_rounding(solver, s, Eigen::VectorXd(*q + velocity * (s - t))); };
  // Central difference for the velocity, h ~ cbrt(eps); the 7-point stencil for the acceleration.
  const double h1 = 1e-5, h2 = 1e-2;
  const auto p1 = solve_at(t + h1), m1 = solve_at(t - h1);
  const auto coarse = stencil_acceleration(solver, t, *q, velocity, h2);
  const auto fine = stencil_acceleration(solver, t, *q, velocity, 0.5 * h2);
  check.solved = p1 && m1 && coarse && fine;
  if (!check.solved) return check;
  const Eigen::VectorXd fd_velocity = (*p1 - *m1) / (2.0 * h1);
  check.velocity_difference = (fd_velocity - velocity).lpNorm<Eigen::Infinity>();
  check.acceleration_difference = (*fine - acceleration).lpNorm<Eigen::Infinity>();
  check.acceleration_reference_spread = (*coarse - *fine).lpNorm<Eigen::Infinity>();
  return check;
}

}  // namespace numlab::mechanisms
