#pragma once
// The numerical honesty checks, one helper for every contract test: whenever a status is
// converged, the test that justifies it is asserted here, computed again from the inputs.
//
//   Newton-type (Newton, GSL's adapter, sequential Newton, the dyad): ||f(x)||_inf <= tolerance,
//     with f evaluated again by the system;
//   linear solvers: ||b - A x||_inf <= 10 n eps (||A||_inf ||x||_inf + ||b||_inf), the residual of a
//     backward-stable solve (Gauss-Seidel's own test is looser: its tolerance in place of eps);
//   fits: the least-squares check (least_squares_check.hpp) and 0 <= R^2 <= 1;
//   sweeps: every pose within its closed-form bound (closed_form_bound.hpp), the branch kept.

#include <Eigen/Core>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>

#include "numlab/fitting/least_squares_check.hpp"
#include "numlab/fitting/polynomial_fit.hpp"
#include "numlab/mechanisms/jansen_solvers.hpp"
#include "numlab/mechanisms/mustang_sweep.hpp"
#include "numlab/nonlinear/system.hpp"
#include "numlab/status.hpp"

namespace numlab::test {

// Newton-type: the residual test, f evaluated again at x.
template <typename System, typename VectorType>
void check_justified(Status status, const System& system, const VectorType& x, double residual_tolerance) {
  if (status != Status::converged) return;
  nonlinear::Vector<System::size> f;
  const nonlinear::Vector<System::size> at = x;
  if constexpr (nonlinear::NonlinearSystem<System>) {
    system.residual(at, f);
  } else {  // a system with residual_and_jacobian() only (the dyad)
    nonlinear::Matrix<System::size> J;
    system.residual_and_jacobian(at, f, J);
  }
  INFO("converged with ||f||_inf = " << f.template lpNorm<Eigen::Infinity>() << ", tolerance " << residual_tolerance);
  CHECK(f.template lpNorm<Eigen::Infinity>() <= residual_tolerance);
}

// A DynamicSystem (the MGH problems, sequential Newton's systems).
inline void check_justified(Status status, const nonlinear::DynamicSystem& system, const Eigen::VectorXd& x,
                            double residual_tolerance) {
  if (status != Status::converged) return;
  Eigen::VectorXd f;
  system.residual(x, f);
  INFO("converged with ||f||_inf = " << f.lpNorm<Eigen::Infinity>() << ", tolerance " << residual_tolerance);
  CHECK(f.lpNorm<Eigen::Infinity>() <= residual_tolerance);
}

// A linear solve: the relative residual; `tolerance` is the method's own (eps for direct methods).
template <typename MatrixType, typename VectorType>
void check_justified(Status status, const MatrixType& A, const VectorType& b, const VectorType& x,
                     double tolerance = std::numeric_limits<double>::epsilon()) {
  if (status != Status::converged) return;
  const double residual = (b - A * x).template lpNorm<Eigen::Infinity>();
  const double scale = A.cwiseAbs().rowwise().sum().maxCoeff() * x.template lpNorm<Eigen::Infinity>() +
                       b.template lpNorm<Eigen::Infinity>();
  INFO("converged with ||b - A x||_inf = " << residual << " against scale " << scale);
  CHECK(residual <= 10.0 * static_cast<double>(A.rows()) * tolerance * scale);
}

// A fit: the least-squares check.
inline void check_justified(const fitting::PolynomialFit& fit, const Eigen::VectorXd& x, const Eigen::VectorXd& y) {
  if (fit.status != Status::converged) return;
  const fitting::LeastSquaresCheck check = fitting::check_least_squares(x, y, fit.coefficients, {}, fit.r_squared);
  INFO("converged fit: worst ratio " << check.worst_ratio << " at power " << check.worst_power << ", R^2 "
                                     << fit.r_squared);
  CHECK(check.passed());
  if (!std::isnan(fit.r_squared)) CHECK((fit.r_squared >= 0.0 && fit.r_squared <= 1.0));
}

// Sweeps: every pose within its closed-form bound, and the branch kept.
template <typename Sweep>
void check_justified(const Sweep& sweep) {
  if (sweep.status != Status::converged) return;
  for (const auto& pose : sweep.poses) {
    INFO("pose at " << pose.crank_deg << " deg: distance " << pose.closed_form_distance << ", bound "
                    << pose.closed_form_bound);
    CHECK(pose.closed_form_distance <= pose.closed_form_bound);
  }
  if constexpr (requires { sweep.orientation_kept; }) {
    CHECK(sweep.orientation_kept);
  } else {
    CHECK(sweep.branch_kept);
  }
}

}  // namespace numlab::test
