#include "numlab/nonlinear/mgh_problems.hpp"

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <type_traits>

#include "mgh_problems_minpack.hpp"

namespace numlab::nonlinear {

namespace {

template <typename Scalar>
using VectorOf = Eigen::Matrix<Scalar, Eigen::Dynamic, 1>;

using std::cos;
using std::exp;
using std::sin;
using std::sqrt;

// Rosenbrock: f1 = 10 (x2 - x1^2), f2 = 1 - x1. Root (1, 1).
class Rosenbrock final : public TemplatedResidual<Rosenbrock> {
 public:
  int dimension() const override { return 2; }
  template <typename T>
  void evaluate(const VectorOf<T>& x, VectorOf<T>& f) const {
    f(0) = 10.0 * (x(1) - x(0) * x(0));
    f(1) = 1.0 - x(0);
  }
  void jacobian(const Eigen::VectorXd& x, Eigen::MatrixXd& J) const override {
    J.resize(2, 2);
    J << -20.0 * x(0), 10.0, -1.0, 0.0;
  }
};

// Freudenstein-Roth: f1 = -13 + x1 + ((5 - x2) x2 - 2) x2, f2 = -29 + x1 + ((x2 + 1) x2 - 14) x2.
// Root (5, 4); ||f|| also has a local minimum near (11.41, -0.8968), where J is singular.
class FreudensteinRoth final : public TemplatedResidual<FreudensteinRoth> {
 public:
  int dimension() const override { return 2; }
  template <typename T>
  void evaluate(const VectorOf<T>& x, VectorOf<T>& f) const {
    f(0) = -13.0 + x(0) + ((5.0 - x(1)) * x(1) - 2.0) * x(1);
    f(1) = -29.0 + x(0) + ((x(1) + 1.0) * x(1) - 14.0) * x(1);
  }
  void jacobian(const Eigen::VectorXd& x, Eigen::MatrixXd& J) const override {
    J.resize(2, 2);
    J << 1.0, (10.0 - 3.0 * x(1)) * x(1) - 2.0, 1.0, (3.0 * x(1) + 2.0) * x(1) - 14.0;
  }
};

// Powell badly scaled: f1 = 1e4 x1 x2 - 1, f2 = exp(-x1) + exp(-x2) - 1.0001.
class PowellBadlyScaled final : public TemplatedResidual<PowellBadlyScaled> {
 public:
  int dimension() const override { return 2; }
  template <typename T>
  void evaluate(const VectorOf<T>& x, VectorOf<T>& f) const {
    f(0) = 1e4 * x(0) * x(1) - 1.0;
    f(1) = exp(-x(0)) + exp(-x(1)) - 1.0001;
  }
  void jacobian(const Eigen::VectorXd& x, Eigen::MatrixXd& J) const override {
    J.resize(2, 2);
    J << 1e4 * x(1), 1e4 * x(0), -std::exp(-x(0)), -std::exp(-x(1));
  }
};

// Powell singular: f = (x1 + 10 x2, sqrt5 (x3 - x4), (x2 - 2 x3)^2, sqrt10 (x1 - x4)^2).
// Root 0, where J is singular: Newton converges only linearly.
class PowellSingular final : public TemplatedResidual<PowellSingular> {
 public:
  int dimension() const override { return 4; }
  template <typename T>
  void evaluate(const VectorOf<T>& x, VectorOf<T>& f) const {
    f(0) = x(0) + 10.0 * x(1);
    f(1) = std::sqrt(5.0) * (x(2) - x(3));
    f(2) = (x(1) - 2.0 * x(2)) * (x(1) - 2.0 * x(2));
    f(3) = std::sqrt(10.0) * (x(0) - x(3)) * (x(0) - x(3));
  }
  void jacobian(const Eigen::VectorXd& x, Eigen::MatrixXd& J) const override {
    const double a = 2.0 * (x(1) - 2.0 * x(2));
    const double b = 2.0 * std::sqrt(10.0) * (x(0) - x(3));
    J.setZero(4, 4);
    J(0, 0) = 1.0;
    J(0, 1) = 10.0;
    J(1, 2) = std::sqrt(5.0);
    J(1, 3) = -std::sqrt(5.0);
    J(2, 1) = a;
    J(2, 2) = -2.0 * a;
    J(3, 0) = b;
    J(3, 3) = -b;
  }
};

// Wood, as a system (MINPACK): half the gradient of Wood's function. Root (1, 1, 1, 1).
class Wood final : public TemplatedResidual<Wood> {
 public:
  int dimension() const override { return 4; }
  template <typename T>
  void evaluate(const VectorOf<T>& x, VectorOf<T>& f) const {
    const T first = x(1) - x(0) * x(0);
    const T second = x(3) - x(2) * x(2);
    f(0) = -200.0 * x(0) * first - (1.0 - x(0));
    f(1) = 200.0 * first + 20.2 * (x(1) - 1.0) + 19.8 * (x(3) - 1.0);
    f(2) = -180.0 * x(2) * second - (1.0 - x(2));
    f(3) = 180.0 * second + 20.2 * (x(3) - 1.0) + 19.8 * (x(1) - 1.0);
  }
  void jacobian(const Eigen::VectorXd& x, Eigen::MatrixXd& J) const override {
    J.setZero(4, 4);
    J(0, 0) = -200.0 * (x(1) - 3.0 * x(0) * x(0)) + 1.0;
    J(0, 1) = -200.0 * x(0);
    J(1, 0) = -400.0 * x(0);
    J(1, 1) = 220.2;
    J(1, 3) = 19.8;
    J(2, 2) = -180.0 * (x(3) - 3.0 * x(2) * x(2)) + 1.0;
    J(2, 3) = -180.0 * x(2);
    J(3, 1) = 19.8;
    J(3, 2) = -360.0 * x(2);
    J(3, 3) = 200.2;
  }
};

// Helical valley: theta = atan(x2/x1) / 2pi (+ 1/2 when x1 < 0; +-1/4 when x1 = 0), f1 = 10 (x3 - 10 theta),
// f2 = 10 (sqrt(x1^2 + x2^2) - 1), f3 = x3. Root (1, 0, 0).
class HelicalValley final : public TemplatedResidual<HelicalValley> {
 public:
  int dimension() const override { return 3; }
  template <typename T>
  void evaluate(const VectorOf<T>& x, VectorOf<T>& f) const {
    // atan2 / 2pi equals MGH's theta everywhere except x1 < 0, x2 < 0, where it is 1 lower.
    using std::atan2;
    T theta = atan2(x(1), x(0)) / (2.0 * std::numbers::pi);
    if (x(0) < 0.0 && x(1) < 0.0) theta += 1.0;
    f(0) = 10.0 * (x(2) - 10.0 * theta);
    f(1) = 10.0 * (sqrt(x(0) * x(0) + x(1) * x(1)) - 1.0);
    f(2) = x(2);
  }
  void jacobian(const Eigen::VectorXd& x, Eigen::MatrixXd& J) const override {
    const double r2 = x(0) * x(0) + x(1) * x(1);
    const double r = std::sqrt(r2);
    const double dtheta_scale = 100.0 / (2.0 * std::numbers::pi * r2);  // d(100 theta) = 100/(2 pi r^2) (x1 dx2 - x2 dx1)
    J.setZero(3, 3);
    J(0, 0) = dtheta_scale * x(1);
    J(0, 1) = -dtheta_scale * x(0);
    J(0, 2) = 10.0;
    J(1, 0) = 10.0 * x(0) / r;
    J(1, 1) = 10.0 * x(1) / r;
    J(2, 2) = 1.0;
  }
};

// Discrete boundary value: h = 1/(n+1), t_i = i h,
// f_i = 2 x_i - x_{i-1} - x_{i+1} + h^2 (x_i + t_i + 1)^3 / 2, with x_0 = x_{n+1} = 0.
class DiscreteBoundaryValue final : public TemplatedResidual<DiscreteBoundaryValue> {
 public:
  explicit DiscreteBoundaryValue(int n) : n_(n) {}
  int dimension() const override { return n_; }
  template <typename T>
  void evaluate(const VectorOf<T>& x, VectorOf<T>& f) const {
    const double h = 1.0 / (n_ + 1);
    // Neighbours outside the grid are the boundary values 0, so they are simply left out (an
    // AutoDiff constant 0 would carry an empty derivative vector into the sum).
    for (int i = 0; i < n_; ++i) {
      const T cube_base = x(i) + (i + 1) * h + 1.0;
      f(i) = 2.0 * x(i) + h * h * cube_base * cube_base * cube_base / 2.0;
      if (i > 0) f(i) -= x(i - 1);
      if (i + 1 < n_) f(i) -= x(i + 1);
    }
  }
  void jacobian(const Eigen::VectorXd& x, Eigen::MatrixXd& J) const override {
    const double h = 1.0 / (n_ + 1);
    J.setZero(n_, n_);
    for (int i = 0; i < n_; ++i) {
      const double base = x(i) + (i + 1) * h + 1.0;
      J(i, i) = 2.0 + 1.5 * h * h * base * base;
      if (i > 0) J(i, i - 1) = -1.0;
      if (i + 1 < n_) J(i, i + 1) = -1.0;
    }
  }

 private:
  int n_;
};

// Trigonometric: f_i = n + i - sin x_i - sum_j cos x_j - i cos x_i (i = 1..n). x = 0 is a root.
class Trigonometric final : public TemplatedResidual<Trigonometric> {
 public:
  explicit Trigonometric(int n) : n_(n) {}
  int dimension() const override { return n_; }
  template <typename T>
  void evaluate(const VectorOf<T>& x, VectorOf<T>& f) const {
    T cosine_sum = cos(x(0));
    for (int j = 1; j < n_; ++j) cosine_sum += cos(x(j));
    for (int i = 0; i < n_; ++i) {
      f(i) = static_cast<double>(n_ + i + 1) - sin(x(i)) - cosine_sum - static_cast<double>(i + 1) * cos(x(i));
    }
  }
  void jacobian(const Eigen::VectorXd& x, Eigen::MatrixXd& J) const override {
    J.resize(n_, n_);
    for (int j = 0; j < n_; ++j) {
      J.col(j).setConstant(std::sin(x(j)));
      J(j, j) = (j + 2) * std::sin(x(j)) - std::cos(x(j));
    }
  }

 private:
  int n_;
};

// Broyden tridiagonal: f_i = (3 - 2 x_i) x_i - x_{i-1} - 2 x_{i+1} + 1, with x_0 = x_{n+1} = 0.
class BroydenTridiagonal final : public TemplatedResidual<BroydenTridiagonal> {
 public:
  explicit BroydenTridiagonal(int n) : n_(n) {}
  int dimension() const override { return n_; }
  template <typename T>
  void evaluate(const VectorOf<T>& x, VectorOf<T>& f) const {
    for (int i = 0; i < n_; ++i) {  // neighbours outside are 0 and left out, as in DiscreteBoundaryValue
      f(i) = (3.0 - 2.0 * x(i)) * x(i) + 1.0;
      if (i > 0) f(i) -= x(i - 1);
      if (i + 1 < n_) f(i) -= 2.0 * x(i + 1);
    }
  }
  void jacobian(const Eigen::VectorXd& x, Eigen::MatrixXd& J) const override {
    J.setZero(n_, n_);
    for (int i = 0; i < n_; ++i) {
      J(i, i) = 3.0 - 4.0 * x(i);
      if (i > 0) J(i, i - 1) = -1.0;
      if (i + 1 < n_) J(i, i + 1) = -2.0;
    }
  }

 private:
  int n_;
};

// Arctangent: f_i = atan(x_i), root 0. Not an MGH problem: the classic case where plain Newton
// overshoots (x <- x - atan(x)(1 + x^2) grows like x^3 once |x| > 1.3917) and damping cures it.
class Arctangent final : public TemplatedResidual<Arctangent> {
 public:
  int dimension() const override { return 2; }
  template <typename T>
  void evaluate(const VectorOf<T>& x, VectorOf<T>& f) const {
    for (int i = 0; i < 2; ++i) {
      if constexpr (std::is_same_v<T, double>) {
        f(i) = std::atan(x(i));
      } else {
        // Eigen's AutoDiff has no atan: asin(x / sqrt(1 + x^2)) is the same function, fine for
        // checking derivatives at moderate x (1 + x^2 overflows past 1e154, so not for solving).
        using std::asin;
        f(i) = asin(x(i) / sqrt(1.0 + x(i) * x(i)));
      }
    }
  }
  void jacobian(const Eigen::VectorXd& x, Eigen::MatrixXd& J) const override {
    J.setZero(2, 2);
    for (int i = 0; i < 2; ++i) J(i, i) = 1.0 / (1.0 + x(i) * x(i));
  }
};

Eigen::VectorXd vector_of(std::initializer_list<double> values) {
  Eigen::VectorXd v(static_cast<Eigen::Index>(values.size()));
  Eigen::Index i = 0;
  for (double value : values) v(i++) = value;
  return v;
}

// The root of Powell's badly scaled system with x1 < x2, found independently of any solver under
// test: on the curve x2 = 1e-4 / x1 the second equation g(x1) = exp(-x1) + exp(-1e-4/x1) - 1.0001
// rises from g(1e-6) < 0 to g(1e-4) > 0, so bisection brackets the root to the last bit.
// (The system is symmetric in x1 and x2: the mirror image is a root too.)
Eigen::VectorXd powell_badly_scaled_root() {
  auto g = [](double x1) { return std::exp(-x1) + std::exp(-1e-4 / x1) - 1.0001; };
  double below = 1e-6, above = 1e-4;  // g(below) < 0 < g(above)
  while (true) {
    const double middle = 0.5 * (below + above);
    if (middle == below || middle == above) break;
    (g(middle) < 0.0 ? below : above) = middle;
  }
  return vector_of({below, 1e-4 / below});
}

}  // namespace

const std::vector<std::string>& test_problem_names() {
  static const std::vector<std::string> names = {
      "rosenbrock",     "freudenstein-roth", "powell-badly-scaled", "powell-singular",     "wood",
      "helical-valley", "discrete-bvp",      "trigonometric",       "broyden-tridiagonal", "arctangent",
      "watson",         "chebyquad",         "brown-almost-linear", "discrete-integral",   "variably-dimensioned",
      "broyden-banded"};
  return names;
}

ProblemSizes problem_sizes(const std::string& name) {
  const auto fixed = [](int n) { return ProblemSizes{n, n, n}; };
  constexpr int unlimited = std::numeric_limits<int>::max();
  if (name == "rosenbrock" || name == "freudenstein-roth" || name == "powell-badly-scaled" || name == "arctangent") {
    return fixed(2);
  }
  if (name == "powell-singular" || name == "wood") return fixed(4);
  if (name == "helical-valley") return fixed(3);
  if (name == "watson") return {6, 2, 31};  // MGH 1981: 2 <= n <= 31
  if (name == "chebyquad") return {5, 1, unlimited};
  if (name == "discrete-bvp" || name == "trigonometric" || name == "broyden-tridiagonal" ||
      name == "brown-almost-linear" || name == "discrete-integral" || name == "variably-dimensioned" ||
      name == "broyden-banded") {
    return {variable_problem_size, 1, unlimited};
  }
  std::string expected;
  for (const std::string& known : test_problem_names()) expected += (expected.empty() ? "" : ", ") + known;
  throw std::invalid_argument("unknown problem '" + name + "' (expected one of " + expected + ")");
}

std::string describe_sizes(const ProblemSizes& sizes) {
  const std::string smallest = std::to_string(sizes.smallest);
  if (sizes.fixed()) return "n = " + smallest + " only";
  if (sizes.largest == std::numeric_limits<int>::max()) return "n >= " + smallest;
  return "n = " + smallest + ".." + std::to_string(sizes.largest);
}

TestProblem make_test_problem(const std::string& name) {
  return make_test_problem(name, problem_sizes(name).default_size);
}

TestProblem make_test_problem(const std::string& name, int n) {
  const ProblemSizes sizes = problem_sizes(name);
  if (n < sizes.smallest || n > sizes.largest) {
    throw std::invalid_argument(name + " has " + describe_sizes(sizes) + ", not n = " + std::to_string(n));
  }
  if (name == "rosenbrock") {
    return {name, "Rosenbrock (n = 2)", std::make_shared<Rosenbrock>(), vector_of({-1.2, 1.0}), vector_of({1.0, 1.0})};
  }
  if (name == "freudenstein-roth") {
    return {name, "Freudenstein-Roth (n = 2); ||f|| has a local minimum near (11.41, -0.897)",
            std::make_shared<FreudensteinRoth>(), vector_of({0.5, -2.0}), vector_of({5.0, 4.0})};
  }
  if (name == "powell-badly-scaled") {
    return {name, "Powell badly scaled (n = 2)", std::make_shared<PowellBadlyScaled>(), vector_of({0.0, 1.0}),
            powell_badly_scaled_root()};
  }
  if (name == "powell-singular") {
    return {name, "Powell singular (n = 4); J is singular at the root", std::make_shared<PowellSingular>(),
            vector_of({3.0, -1.0, 0.0, 1.0}), Eigen::VectorXd::Zero(4)};
  }
  if (name == "wood") {
    return {name, "Wood (n = 4)", std::make_shared<Wood>(), vector_of({-3.0, -1.0, -3.0, -1.0}),
            Eigen::VectorXd::Ones(4)};
  }
  if (name == "helical-valley") {
    return {name, "Helical valley (n = 3)", std::make_shared<HelicalValley>(), vector_of({-1.0, 0.0, 0.0}),
            vector_of({1.0, 0.0, 0.0})};
  }
  if (name == "discrete-bvp") {
    Eigen::VectorXd start(n);
    for (int i = 0; i < n; ++i) {
      const double t = (i + 1.0) / (n + 1.0);
      start(i) = t * (t - 1.0);
    }
    return {name, "Discrete boundary value (n = " + std::to_string(n) + "); no closed-form root", std::make_shared<DiscreteBoundaryValue>(n),
            start, std::nullopt};
  }
  if (name == "trigonometric") {
    return {name, "Trigonometric (n = " + std::to_string(n) + "); x = 0 is a root, not the only one", std::make_shared<Trigonometric>(n),
            Eigen::VectorXd::Constant(n, 1.0 / n), Eigen::VectorXd::Zero(n)};
  }
  if (name == "broyden-tridiagonal") {
    return {name, "Broyden tridiagonal (n = " + std::to_string(n) + "); no closed-form root", std::make_shared<BroydenTridiagonal>(n),
            Eigen::VectorXd::Constant(n, -1.0), std::nullopt};
  }
  if (name == "arctangent") {
    return {name, "Arctangent (n = 2, not MGH); plain Newton overshoots from |x| > 1.39, damping cures it",
            std::make_shared<Arctangent>(), vector_of({2.0, 2.0}), Eigen::VectorXd::Zero(2)};
  }
  if (name == "watson") return detail::make_watson(n);
  if (name == "chebyquad") return detail::make_chebyquad(n);
  if (name == "brown-almost-linear") return detail::make_brown_almost_linear(n);
  if (name == "discrete-integral") return detail::make_discrete_integral(n);
  if (name == "variably-dimensioned") return detail::make_variably_dimensioned(n);
  return detail::make_broyden_banded(n);  // the last name problem_sizes() accepted
}

}  // namespace numlab::nonlinear
