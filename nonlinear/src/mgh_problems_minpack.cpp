// The six problems that complete MINPACK's hybrj test set, in the square forms of its driver's
// vecfcn/vecjac/initpt (Moré, Garbow & Hillstrom, "User guide for MINPACK-1", ANL-80-74, 1980;
// problems from Moré, Garbow & Hillstrom, "Testing unconstrained optimization software", ACM TOMS 7,
// 1981). Read from fortran-lang/minpack test/test_hybrj.f90; written here from the equations.
// Indices below are 1-based as in the papers; the code is 0-based.

#include <algorithm>
#include <string>
#include <vector>

#include "mgh_problems_minpack.hpp"

namespace numlab::nonlinear::detail {

namespace {

template <typename Scalar>
using VectorOf = Eigen::Matrix<Scalar, Eigen::Dynamic, 1>;

// Eigen's AutoDiff scalars: a constant (no derivative vector) must not start a sum that later
// meets x's entries, so every sum below starts from a term that contains an x.

// Watson, as hybrj solves it: f = half the gradient of Watson's sum of squares
//   r_i = sum_{j=2..n} (j-1) x_j t_i^(j-2) - (sum_{j=1..n} x_j t_i^(j-1))^2 - 1, t_i = i/29 (i = 1..29),
//   r_30 = x_1, r_31 = x_2 - x_1^2 - 1;
// f_k = sum_i r_i dr_i/dx_k. Its roots are the stationary points of the sum of squares.
class Watson final : public TemplatedResidual<Watson> {
 public:
  explicit Watson(int n) : n_(n) {}
  int dimension() const override { return n_; }
  template <typename T>
  void evaluate(const VectorOf<T>& x, VectorOf<T>& f) const {
    for (int i = 1; i <= 29; ++i) {
      const double t = i / 29.0;
      // s1 = sum (j-1) x_j t^(j-2), s2 = sum x_j t^(j-1).
      T s1 = x(1);
      T s2 = x(0) + x(1) * t;
      double power = t;  // t^(j-1) for the 0-based j below
      for (int j = 2; j < n_; ++j) {
        s1 += static_cast<double>(j) * power * x(j);
        power *= t;
        s2 += power * x(j);
      }
      const T r = s1 - s2 * s2 - 1.0;
      // dr/dx_k = (k-1) t^(k-2) - 2 s2 t^(k-1) (1-based k).
      double t_k = 1.0;
      for (int k = 0; k < n_; ++k) {
        const double lower = k == 0 ? 0.0 : k * t_k / t;
        const T term = r * (lower - 2.0 * s2 * t_k);
        if (i == 1) {
          f(k) = term;
        } else {
          f(k) += term;
        }
        t_k *= t;
      }
    }
    const T r31 = x(1) - x(0) * x(0) - 1.0;
    f(0) += x(0) * (1.0 - 2.0 * r31);  // r_30 dr_30/dx_1 + r_31 dr_31/dx_1
    f(1) += r31;                       // r_31 dr_31/dx_2
  }
  // J = sum_i (g_i g_i^T - 2 r_i p_i p_i^T) + the r_30, r_31 terms, with g_i = grad r_i and
  // p_i = (1, t_i, t_i^2, ...) (the second derivative of r_i is -2 p_i p_i^T).
  void jacobian(const Eigen::VectorXd& x, Eigen::MatrixXd& J) const override {
    J.setZero(n_, n_);
    Eigen::VectorXd p(n_), g(n_);
    for (int i = 1; i <= 29; ++i) {
      const double t = i / 29.0;
      p(0) = 1.0;
      for (int k = 1; k < n_; ++k) p(k) = p(k - 1) * t;
      double s1 = 0.0;
      for (int k = 1; k < n_; ++k) s1 += k * p(k - 1) * x(k);
      const double s2 = p.dot(x);
      const double r = s1 - s2 * s2 - 1.0;
      for (int k = 0; k < n_; ++k) g(k) = (k == 0 ? 0.0 : k * p(k - 1)) - 2.0 * s2 * p(k);
      J += g * g.transpose() - 2.0 * r * p * p.transpose();
    }
    J(0, 0) += 6.0 * x(0) * x(0) - 2.0 * x(1) + 3.0;
    J(0, 1) -= 2.0 * x(0);
    J(1, 0) -= 2.0 * x(0);
    J(1, 1) += 1.0;
  }

 private:
  int n_;
};

// Chebyquad: f_i = (1/n) sum_j T_i(2 x_j - 1) - integral_0^1 T_i(2t - 1) dt, where T_i is the
// Chebyshev polynomial and the integral is -1/(i^2 - 1) for even i, 0 for odd i (i = 1..n).
// A root is an equal-weight quadrature rule on [0, 1]: one exists for n = 1..7 and 9 only.
class Chebyquad final : public TemplatedResidual<Chebyquad> {
 public:
  explicit Chebyquad(int n) : n_(n) {}
  int dimension() const override { return n_; }
  template <typename T>
  void evaluate(const VectorOf<T>& x, VectorOf<T>& f) const {
    for (int j = 0; j < n_; ++j) {
      const T y = 2.0 * x(j) - 1.0;
      T previous = y;            // T_1(y)
      T current = 2.0 * y * y - 1.0;  // T_2(y)
      for (int i = 0; i < n_; ++i) {
        T value = y;
        if (i == 1) value = current;
        if (i >= 2) {  // T_{i+1} = 2 y T_i - T_{i-1}
          const T next = 2.0 * y * current - previous;
          previous = current;
          current = next;
          value = current;
        }
        if (j == 0) {
          f(i) = value / static_cast<double>(n_);
        } else {
          f(i) += value / static_cast<double>(n_);
        }
      }
    }
    for (int i = 1; i < n_; i += 2) {  // 0-based odd = 1-based even
      const double degree = i + 1.0;
      f(i) += 1.0 / (degree * degree - 1.0);
    }
  }
  // dT_i(2x - 1)/dx = 2 T_i'(y), with T_0' = 0, T_1' = 1, T_{i+1}' = 2 T_i + 2 y T_i' - T_{i-1}'.
  void jacobian(const Eigen::VectorXd& x, Eigen::MatrixXd& J) const override {
    J.resize(n_, n_);
    for (int j = 0; j < n_; ++j) {
      const double y = 2.0 * x(j) - 1.0;
      double value_before = 1.0, value = y;       // T_0, T_1
      double slope_before = 0.0, slope = 1.0;     // T_0', T_1'
      for (int i = 0; i < n_; ++i) {
        J(i, j) = 2.0 * slope / n_;
        const double next_slope = 2.0 * value + 2.0 * y * slope - slope_before;
        const double next_value = 2.0 * y * value - value_before;
        slope_before = slope;
        slope = next_slope;
        value_before = value;
        value = next_value;
      }
    }
  }

 private:
  int n_;
};

// Brown almost-linear: f_k = x_k + sum_j x_j - (n + 1) for k < n, f_n = prod_j x_j - 1.
// Roots: x = (1, ..., 1), and (a, ..., a, a^(1-n)) with n a + a^(1-n) = n + 1.
class BrownAlmostLinear final : public TemplatedResidual<BrownAlmostLinear> {
 public:
  explicit BrownAlmostLinear(int n) : n_(n) {}
  int dimension() const override { return n_; }
  template <typename T>
  void evaluate(const VectorOf<T>& x, VectorOf<T>& f) const {
    T sum = x(0);
    T product = x(0);
    for (int j = 1; j < n_; ++j) {
      sum += x(j);
      product *= x(j);
    }
    for (int k = 0; k + 1 < n_; ++k) f(k) = x(k) + sum - static_cast<double>(n_ + 1);
    f(n_ - 1) = product - 1.0;
  }
  void jacobian(const Eigen::VectorXd& x, Eigen::MatrixXd& J) const override {
    J.setOnes(n_, n_);
    for (int k = 0; k + 1 < n_; ++k) J(k, k) = 2.0;
    for (int j = 0; j < n_; ++j) {  // d(prod)/dx_j = the product of the others (no division: x_j may be 0)
      double others = 1.0;
      for (int k = 0; k < n_; ++k) {
        if (k != j) others *= x(k);
      }
      J(n_ - 1, j) = others;
    }
  }

 private:
  int n_;
};

// Discrete integral equation: h = 1/(n+1), t_k = k h, u_j = (x_j + t_j + 1)^3,
// f_k = x_k + h/2 [ (1 - t_k) sum_{j<=k} t_j u_j + t_k sum_{j>k} (1 - t_j) u_j ].
class DiscreteIntegral final : public TemplatedResidual<DiscreteIntegral> {
 public:
  explicit DiscreteIntegral(int n) : n_(n) {}
  int dimension() const override { return n_; }
  template <typename T>
  void evaluate(const VectorOf<T>& x, VectorOf<T>& f) const {
    const double h = 1.0 / (n_ + 1);
    for (int k = 0; k < n_; ++k) {
      const double t_k = (k + 1) * h;
      f(k) = x(k);
      for (int j = 0; j < n_; ++j) {
        const double t_j = (j + 1) * h;
        const T base = x(j) + t_j + 1.0;
        const double weight = j <= k ? (1.0 - t_k) * t_j : t_k * (1.0 - t_j);  // the Green's function
        f(k) += h / 2.0 * weight * base * base * base;
      }
    }
  }
  void jacobian(const Eigen::VectorXd& x, Eigen::MatrixXd& J) const override {
    const double h = 1.0 / (n_ + 1);
    J.resize(n_, n_);
    for (int k = 0; k < n_; ++k) {
      const double t_k = (k + 1) * h;
      for (int j = 0; j < n_; ++j) {
        const double t_j = (j + 1) * h;
        const double base = x(j) + t_j + 1.0;
        const double weight = j <= k ? (1.0 - t_k) * t_j : t_k * (1.0 - t_j);
        J(k, j) = h / 2.0 * weight * 3.0 * base * base;
      }
      J(k, k) += 1.0;
    }
  }

 private:
  int n_;
};

// Variably dimensioned: s = sum_j j (x_j - 1), f_k = x_k - 1 + k s (1 + 2 s^2). Root (1, ..., 1).
class VariablyDimensioned final : public TemplatedResidual<VariablyDimensioned> {
 public:
  explicit VariablyDimensioned(int n) : n_(n) {}
  int dimension() const override { return n_; }
  template <typename T>
  void evaluate(const VectorOf<T>& x, VectorOf<T>& f) const {
    T s = x(0) - 1.0;
    for (int j = 1; j < n_; ++j) s += static_cast<double>(j + 1) * (x(j) - 1.0);
    const T growth = s * (1.0 + 2.0 * s * s);
    for (int k = 0; k < n_; ++k) f(k) = x(k) - 1.0 + static_cast<double>(k + 1) * growth;
  }
  void jacobian(const Eigen::VectorXd& x, Eigen::MatrixXd& J) const override {
    double s = 0.0;
    for (int j = 0; j < n_; ++j) s += (j + 1) * (x(j) - 1.0);
    const double slope = 1.0 + 6.0 * s * s;
    J.resize(n_, n_);
    for (int k = 0; k < n_; ++k) {
      for (int j = 0; j < n_; ++j) J(k, j) = (k + 1.0) * (j + 1.0) * slope;
      J(k, k) += 1.0;
    }
  }

 private:
  int n_;
};

// Broyden banded (lower bandwidth 5, upper 1):
// f_k = x_k (2 + 5 x_k^2) + 1 - sum_{j in [k-5, k+1], j != k} x_j (1 + x_j).
class BroydenBanded final : public TemplatedResidual<BroydenBanded> {
 public:
  explicit BroydenBanded(int n) : n_(n) {}
  int dimension() const override { return n_; }
  template <typename T>
  void evaluate(const VectorOf<T>& x, VectorOf<T>& f) const {
    for (int k = 0; k < n_; ++k) {
      f(k) = x(k) * (2.0 + 5.0 * x(k) * x(k)) + 1.0;
      for (int j = first(k); j <= last(k); ++j) {
        if (j != k) f(k) -= x(j) * (1.0 + x(j));
      }
    }
  }
  void jacobian(const Eigen::VectorXd& x, Eigen::MatrixXd& J) const override {
    J.setZero(n_, n_);
    for (int k = 0; k < n_; ++k) {
      for (int j = first(k); j <= last(k); ++j) J(k, j) = -(1.0 + 2.0 * x(j));
      J(k, k) = 2.0 + 15.0 * x(k) * x(k);
    }
  }

 private:
  int first(int k) const { return std::max(0, k - 5); }
  int last(int k) const { return std::min(n_ - 1, k + 1); }
  int n_;
};

}  // namespace

// The standard starts are initpt's; where the literature gives a root or a minimum it is stated.

namespace {
std::string sized(const std::string& title, int n, const std::string& note) {
  return title + " (n = " + std::to_string(n) + "); " + note;
}
}  // namespace

TestProblem make_watson(int n) {
  return {"watson",
          sized("Watson", n,
                "the gradient system hybrj solves: its roots are stationary points, no closed form "
                "(least-squares minimum 2.28767e-3 at n = 6, 1.39976e-6 at n = 9)"),
          std::make_shared<Watson>(n), Eigen::VectorXd::Zero(n), std::nullopt, std::nullopt};
}

TestProblem make_chebyquad(int n) {
  Eigen::VectorXd start(n);
  for (int j = 0; j < n; ++j) start(j) = (j + 1.0) / (n + 1.0);
  // MGH 1981 give the minimum of ||f||^2 for m = n = 8 and m = n = 10.
  std::optional<double> minimum;
  std::string note = "roots are equal-weight quadrature rules on [0, 1], no closed form";
  if (n == 8 || n >= 10) note = "residual minimum, no root";
  if (n == 8) {
    minimum = 3.51687e-3;
    note += " (min ||f||^2 = 3.51687e-3)";
  }
  if (n == 10) {
    minimum = 6.50395e-3;
    note += " (min ||f||^2 = 6.50395e-3)";
  }
  return {"chebyquad", sized("Chebyquad", n, note), std::make_shared<Chebyquad>(n), start, std::nullopt, minimum};
}

TestProblem make_brown_almost_linear(int n) {
  return {"brown-almost-linear", sized("Brown almost-linear", n, "root (1, ..., 1), others (a, ..., a, a^(1-n))"),
          std::make_shared<BrownAlmostLinear>(n), Eigen::VectorXd::Constant(n, 0.5), Eigen::VectorXd::Ones(n),
          std::nullopt};
}

// Discrete BVP's start too: t_j (t_j - 1).
TestProblem make_discrete_integral(int n) {
  Eigen::VectorXd start(n);
  for (int j = 0; j < n; ++j) {
    const double t = (j + 1.0) / (n + 1.0);
    start(j) = t * (t - 1.0);
  }
  return {"discrete-integral", sized("Discrete integral equation", n, "no closed-form root"),
          std::make_shared<DiscreteIntegral>(n), start, std::nullopt, std::nullopt};
}

TestProblem make_variably_dimensioned(int n) {
  Eigen::VectorXd start(n);
  for (int j = 0; j < n; ++j) start(j) = 1.0 - (j + 1.0) / n;
  return {"variably-dimensioned", sized("Variably dimensioned", n, "root (1, ..., 1)"),
          std::make_shared<VariablyDimensioned>(n), start, Eigen::VectorXd::Ones(n), std::nullopt};
}

TestProblem make_broyden_banded(int n) {
  return {"broyden-banded", sized("Broyden banded", n, "no closed-form root"), std::make_shared<BroydenBanded>(n),
          Eigen::VectorXd::Constant(n, -1.0), std::nullopt, std::nullopt};
}

}  // namespace numlab::nonlinear::detail
