#pragma once
// Small fixed-size systems built to make Newton end in each status, with the reason obvious.

#include <cmath>

#include "numlab/nonlinear/newton.hpp"
#include "numlab/nonlinear/system.hpp"

namespace numlab::test {

using Vector2 = nonlinear::Vector<2>;
using Matrix2 = nonlinear::Matrix<2>;

// f = (x1^2 + 1, x2 - 1): J = diag(2 x1, 1) is exactly singular at x1 = 0 (and f has no real root).
struct SingularAtZero {
  static constexpr int size = 2;
  int dimension() const { return 2; }
  void residual(const Vector2& x, Vector2& f) const { f << x(0) * x(0) + 1.0, x(1) - 1.0; }
  void jacobian(const Vector2& x, Matrix2& J) const { J << 2.0 * x(0), 0.0, 0.0, 1.0; }
};

// f = (sqrt(x1) - 2, x2): from x1 = 100 the first Newton step lands at x1 = -60, where sqrt is NaN.
struct SquareRoot {
  static constexpr int size = 2;
  int dimension() const { return 2; }
  void residual(const Vector2& x, Vector2& f) const { f << std::sqrt(x(0)) - 2.0, x(1); }
  void jacobian(const Vector2& x, Matrix2& J) const { J << 0.5 / std::sqrt(x(0)), 0.0, 0.0, 1.0; }
};

// f = (cbrt(x1), x2): Newton maps x1 to -2 x1, so |f1| grows by 2^(1/3) every iteration.
struct CubeRoot {
  static constexpr int size = 2;
  int dimension() const { return 2; }
  void residual(const Vector2& x, Vector2& f) const { f << std::cbrt(x(0)), x(1); }
  void jacobian(const Vector2& x, Matrix2& J) const {
    const double r = std::cbrt(x(0));
    J << 1.0 / (3.0 * r * r), 0.0, 0.0, 1.0;
  }
};

// Rosenbrock as a fixed-size system: f = (10 (x2 - x1^2), 1 - x1), root (1, 1).
struct FixedRosenbrock {
  static constexpr int size = 2;
  int dimension() const { return 2; }
  void residual(const Vector2& x, Vector2& f) const { f << 10.0 * (x(1) - x(0) * x(0)), 1.0 - x(0); }
  void jacobian(const Vector2& x, Matrix2& J) const { J << -20.0 * x(0), 10.0, -1.0, 0.0; }
};

// The labs' Newton settings for the test problems: residual 1e-10, up to 100 iterations.
inline nonlinear::NewtonOptions lab_options() {
  nonlinear::NewtonOptions options;
  options.residual_tolerance = 1e-10;
  options.max_iterations = 100;
  return options;
}

}  // namespace numlab::test
