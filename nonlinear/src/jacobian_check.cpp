#include "numlab/nonlinear/jacobian_check.hpp"

#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

#include "numlab/linalg/input_checks.hpp"
#include "numlab/nonlinear/autodiff_system.hpp"

namespace numlab::nonlinear {

namespace {

Eigen::MatrixXd central_differences(const DynamicSystem& system, const Eigen::VectorXd& x) {
  const int n = system.dimension();
  const double scale = std::cbrt(std::numeric_limits<double>::epsilon());
  Eigen::MatrixXd J(n, n);
  Eigen::VectorXd forward_f, backward_f;
  for (int j = 0; j < n; ++j) {
    const double h = scale * std::max(1.0, std::abs(x(j)));
    Eigen::VectorXd forward = x, backward = x;
    forward(j) += h;
    backward(j) -= h;
    system.residual(forward, forward_f);
    system.residual(backward, backward_f);
    J.col(j) = (forward_f - backward_f) / (forward(j) - backward(j));  // the step actually taken
  }
  return J;
}

Eigen::MatrixXd autodiff_jacobian(const AutoDiffSystem& system, const Eigen::VectorXd& x) {
  const int n = system.dimension();
  AutoDiffVector ad_x(n), ad_f(n);
  for (int j = 0; j < n; ++j) ad_x(j) = AutoDiffScalar(x(j), n, j);  // value x_j, derivative e_j
  system.residual_autodiff(ad_x, ad_f);
  Eigen::MatrixXd J(n, n);
  for (int i = 0; i < n; ++i) {
    // A residual that does not depend on x at all carries no derivative vector: its row is zero.
    if (ad_f(i).derivatives().size() == n) {
      J.row(i) = ad_f(i).derivatives().transpose();
    } else {
      J.row(i).setZero();
    }
  }
  return J;
}

// max_ij |a - b| / max(1, |b|), and where.
double worst_relative_difference(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b, int& row, int& column) {
  double worst = 0.0;
  for (Eigen::Index i = 0; i < a.rows(); ++i) {
    for (Eigen::Index j = 0; j < a.cols(); ++j) {
      const double error = std::abs(a(i, j) - b(i, j)) / std::max(1.0, std::abs(b(i, j)));
      if (!(error <= worst)) {  // also catches NaN
        worst = error;
        row = static_cast<int>(i);
        column = static_cast<int>(j);
      }
    }
  }
  return worst;
}

}  // namespace

JacobianCheck check_jacobian(const DynamicSystem& system, const Eigen::VectorXd& x, double tolerance) {
  linalg::require_non_negative(tolerance, "Jacobian check tolerance");
  if (x.size() != system.dimension()) {
    throw std::invalid_argument("point has " + std::to_string(x.size()) + " entries but the system has " +
                                std::to_string(system.dimension()) + " unknowns");
  }
  linalg::require_finite(x, "point");
  JacobianCheck check;
  check.tolerance = tolerance;
  system.jacobian(x, check.analytic);
  check.finite_difference = central_differences(system, x);
  const Eigen::MatrixXd* reference = &check.finite_difference;
  if (const auto* differentiable = dynamic_cast<const AutoDiffSystem*>(&system)) {
    check.autodiff = autodiff_jacobian(*differentiable, x);
    reference = &check.autodiff;
    int ignored_row = 0, ignored_column = 0;
    check.finite_difference_agreement =
        worst_relative_difference(check.finite_difference, check.autodiff, ignored_row, ignored_column);
  }
  check.worst_error = worst_relative_difference(check.analytic, *reference, check.worst_row, check.worst_column);
  check.agrees = check.worst_error <= tolerance;
  return check;
}

std::string describe_worst_entry(const JacobianCheck& check) {
  const int i = check.worst_row, j = check.worst_column;
  char line[256];
  if (check.autodiff.size() > 0) {
    std::snprintf(line, sizeof line, "J(%d,%d) = %.6g; AutoDiff %.6g, finite differences %.6g; relative error %.2g",
                  i + 1, j + 1, check.analytic(i, j), check.autodiff(i, j), check.finite_difference(i, j),
                  check.worst_error);
  } else {
    std::snprintf(line, sizeof line, "J(%d,%d) = %.6g; finite differences %.6g; relative error %.2g", i + 1, j + 1,
                  check.analytic(i, j), check.finite_difference(i, j), check.worst_error);
  }
  return line;
}

}  // namespace numlab::nonlinear
