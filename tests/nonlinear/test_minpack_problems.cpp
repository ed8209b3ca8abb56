// MINPACK's hybrj test set in numlab's catalogue: the driver's case list, initpt's starts, exact
// Jacobians at every driver size, known roots, and residuals at the solutions MINPACK reports.
// Reference: fortran-lang/minpack test/test_hybrj.f90 (the MINPACK-1 driver, ANL-80-74, with the
// solutions its hybrj1 reached recorded for regression).

#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <map>
#include <random>

#include "numlab/nonlinear/jacobian_check.hpp"
#include "numlab/nonlinear/minpack_cases.hpp"

using namespace numlab::nonlinear;

namespace {

constexpr double eps = std::numeric_limits<double>::epsilon();

// initpt, transcribed here a second time from the driver (not from the library) for comparison.
Eigen::VectorXd initpt(int problem, int n, double factor) {
  Eigen::VectorXd x(n);
  for (int j = 1; j <= n; ++j) {
    const double t = static_cast<double>(j) / (n + 1);
    double value = 0.0;
    switch (problem) {
      case 1: value = j == 1 ? -1.2 : 1.0; break;
      case 2: value = std::array{3.0, -1.0, 0.0, 1.0}[j - 1]; break;
      case 3: value = j == 1 ? 0.0 : 1.0; break;
      case 4: value = j % 2 == 1 ? -3.0 : -1.0; break;
      case 5: value = j == 1 ? -1.0 : 0.0; break;
      case 6: value = 0.0; break;
      case 7: value = t; break;
      case 8: value = 0.5; break;
      case 9:
      case 10: value = t * (t - 1.0); break;
      case 11: value = 1.0 / n; break;
      case 12: value = 1.0 - static_cast<double>(j) / n; break;
      default: value = -1.0; break;  // 13, 14
    }
    x(j - 1) = value;
  }
  if (factor != 1.0) x = problem == 6 ? Eigen::VectorXd::Constant(n, factor) : Eigen::VectorXd(factor * x);
  return x;
}

Eigen::VectorXd residual_at(const TestProblem& problem, const Eigen::VectorXd& x) {
  Eigen::VectorXd f;
  problem.system->residual(x, f);
  return f;
}

Eigen::VectorXd vector_of(std::initializer_list<double> values) {
  return Eigen::Map<const Eigen::VectorXd>(values.begin(), static_cast<Eigen::Index>(values.size()));
}

}  // namespace

TEST_CASE("The case list is the hybrj driver's: 22 rows, 55 cases, starts x0, 10 x0, 100 x0", "[minpack]") {
  // The driver's data (test_hybrj.f90): problem number, size, number of starts.
  const std::vector<int> nprob = {1, 2, 3, 4, 5, 6, 6, 7, 7, 7, 7, 7, 8, 8, 8, 9, 10, 10, 11, 12, 13, 14};
  const std::vector<int> sizes = {2, 4, 2, 4, 3, 6, 9, 5, 6, 7, 8, 9, 10, 30, 40, 10, 1, 10, 10, 10, 10, 10};
  const std::vector<int> ntries = {3, 3, 2, 3, 3, 2, 2, 3, 3, 3, 1, 1, 3, 1, 1, 3, 3, 3, 3, 3, 3, 3};
  const auto& cases = minpack_cases();
  REQUIRE(cases.size() == 55);
  std::size_t next = 0;
  for (std::size_t row = 0; row < nprob.size(); ++row) {
    double factor = 1.0;
    for (int start = 0; start < ntries[row]; ++start, factor *= 10.0) {
      REQUIRE(next < cases.size());
      const MinpackCase& c = cases[next++];
      INFO(case_label(c));
      CHECK(minpack_problem_number(c.problem) == nprob[row]);
      CHECK(c.n == sizes[row]);
      CHECK(c.factor == factor);
    }
  }
  CHECK(next == cases.size());
  CHECK(minpack_sizes("chebyquad") == std::vector<int>{5, 6, 7, 8, 9});
  CHECK(minpack_sizes("discrete-integral") == std::vector<int>{1, 10});
  CHECK_THROWS_AS(minpack_problem_number("freudenstein-roth"), std::invalid_argument);
  CHECK(case_label(cases[5]) == "powell-singular n=4 start 100x0");
}

TEST_CASE("Every case starts where initpt puts it, Watson's zero start becoming (factor, ..., factor)", "[minpack]") {
  for (const MinpackCase& c : minpack_cases()) {
    const MinpackInstance instance = make_minpack_instance(c);
    INFO(case_label(c));
    REQUIRE(instance.start.size() == c.n);
    CHECK(instance.start == initpt(minpack_problem_number(c.problem), c.n, c.factor));
    CHECK(instance.problem.system->dimension() == c.n);
  }
  const TestProblem watson = make_test_problem("watson", 6);
  CHECK(minpack_start("watson", watson.standard_start, 1.0).isZero());
  CHECK(minpack_start("watson", watson.standard_start, 10.0) == Eigen::VectorXd::Constant(6, 10.0));
  const TestProblem wood = make_test_problem("wood");
  CHECK(minpack_start("wood", wood.standard_start, 100.0) == 100.0 * wood.standard_start);
}

TEST_CASE("Every hand-written Jacobian agrees with AutoDiff and finite differences at every driver size",
          "[minpack][jacobian-check]") {
  std::mt19937 generator(18);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  for (const MinpackCase& c : minpack_cases()) {
    const MinpackInstance instance = make_minpack_instance(c);
    Eigen::VectorXd random_point(c.n);
    for (int j = 0; j < c.n; ++j) random_point(j) = uniform(generator);
    for (const Eigen::VectorXd& x : {instance.start, random_point}) {
      const JacobianCheck check = check_jacobian(*instance.problem.system, x);
      const double f_size = residual_at(instance.problem, x).lpNorm<Eigen::Infinity>();
      INFO(case_label(c) << " at x = " << x.transpose() << ": " << describe_worst_entry(check));
      REQUIRE(check.autodiff.size() > 0);
      // AutoDiff and the hand-written formula round differently; entries are sums of at most
      // 29 (n + 2) products (Watson's), so a few hundred eps relative is rounding.
      CHECK(check.worst_error <= 500 * eps);
      // Central differences' error model (jacobian_check.hpp), h = cbrt(eps) max(1, |x_j|): rounding
      // eps ||f|| / h, relative to entries of at least 1, plus truncation h^2 |f'''| / 6, which for
      // these polynomial and trigonometric terms at |x| <= 100 stays below 1e-7 relative.
      const double rounding = eps * std::max(1.0, f_size) / std::cbrt(eps);
      CHECK(check.finite_difference_agreement <= 10.0 * rounding + 1e-7);
    }
  }
}

TEST_CASE("Known roots give a residual at rounding level", "[minpack][mgh]") {
  for (const std::string& name : test_problem_names()) {
    const ProblemSizes sizes = problem_sizes(name);
    std::vector<int> ns = {sizes.default_size};
    if (!sizes.fixed()) ns = {sizes.smallest, sizes.default_size, 30};
    for (int n : ns) {
      const TestProblem problem = make_test_problem(name, n);
      if (!problem.known_root) continue;
      const Eigen::VectorXd& root = *problem.known_root;
      Eigen::MatrixXd J;
      problem.system->jacobian(root, J);
      // Each f_i sums terms no larger than |J| |x| (or 1) in size; rounding of n of them.
      const double term_size = std::max(1.0, J.cwiseAbs().maxCoeff() * std::max(1.0, root.lpNorm<Eigen::Infinity>()));
      INFO(name << " n = " << n);
      CHECK(residual_at(problem, root).lpNorm<Eigen::Infinity>() <= 4.0 * n * eps * term_size);
    }
  }
}

TEST_CASE("Chebyquad's roots for n = 1, 2, 3 are Chebyshev's equal-weight quadrature nodes", "[minpack][mgh]") {
  // Closed forms on [-1, 1]: n = 2 nodes +-1/sqrt(3), n = 3 nodes 0, +-1/sqrt(2); mapped to [0, 1].
  const std::map<int, Eigen::VectorXd> nodes = {
      {1, vector_of({0.5})},
      {2, vector_of({0.5 - 0.5 / std::sqrt(3.0), 0.5 + 0.5 / std::sqrt(3.0)})},
      {3, vector_of({0.5 - 0.5 / std::sqrt(2.0), 0.5, 0.5 + 0.5 / std::sqrt(2.0)})}};
  for (const auto& [n, x] : nodes) {
    INFO("n = " << n);
    CHECK(residual_at(make_test_problem("chebyquad", n), x).lpNorm<Eigen::Infinity>() <= 8 * eps);
  }
  // And a point that is not a rule is not a root.
  CHECK(residual_at(make_test_problem("chebyquad", 2), vector_of({0.25, 0.75})).lpNorm<Eigen::Infinity>() > 1e-2);
}

TEST_CASE("The residual vanishes, to hybrj's accuracy, at the solutions MINPACK's driver reports", "[minpack][mgh]") {
  // x from test_hybrj.f90's recorded solutions (hybrj1 exit 1, x to relative accuracy sqrt(eps)).
  struct Reported {
    std::string problem;
    Eigen::VectorXd x;
  };
  const std::vector<Reported> reported = {
      {"watson", vector_of({-0.1572508640131874E-01, 0.1012434869369120E+01, -0.2329916259568086E+00,
                            0.1260430087800509E+01, -0.1513728922723659E+01, 0.9929964324319899E+00})},
      {"watson", vector_of({-0.1530703902928690E-04, 0.9997897039319343E+00, 0.1476396368990648E-01,
                            0.1463423283093984E+00, 0.1000821102959179E+01, -0.2617731140413794E+01,
                            0.4104403164336241E+01, -0.3143612278455328E+01, 0.1052626407979455E+01})},
      {"chebyquad", vector_of({0.8375125649943561E-01, 0.3127292952232932E+00, 0.5000000000000018E+00,
                               0.6872707047767043E+00, 0.9162487435005652E+00})},
      {"chebyquad", vector_of({0.5806914960717641E-01, 0.2351716124057688E+00, 0.3380440947078516E+00,
                               0.4999999999993442E+00, 0.6619559052930899E+00, 0.7648283875938304E+00,
                               0.9419308503929387E+00})},
      {"brown-almost-linear", vector_of({0.9794303033498583, 0.9794303033498583, 0.9794303033498583,
                                         0.9794303033498583, 0.9794303033498583, 0.9794303033498583,
                                         0.9794303033498583, 0.9794303033498583, 0.9794303033498583,
                                         0.1205696966501417E+01})},
      {"discrete-integral", vector_of({-0.1528138835625800E+00})},
      {"discrete-integral", vector_of({-0.4316498251876487E-01, -0.8157715653538729E-01, -0.1144857143805310E+00,
                                       -0.1409735768625996E+00, -0.1599086961819857E+00, -0.1698772023127759E+00,
                                       -0.1690899837812080E+00, -0.1552495352218311E+00, -0.1253558916789344E+00,
                                       -0.7541653368589175E-01})},
      {"broyden-banded", vector_of({-0.4283028636053096E+00, -0.4765964242962532E+00, -0.5196524638125551E+00,
                                    -0.5580993246169653E+00, -0.5925061569509360E+00, -0.6245036821428090E+00,
                                    -0.6232394714478015E+00, -0.6213938418388717E+00, -0.6204535966122983E+00,
                                    -0.5864692707477790E+00})}};
  for (const Reported& point : reported) {
    const TestProblem problem = make_test_problem(point.problem, static_cast<int>(point.x.size()));
    Eigen::MatrixXd J;
    problem.system->jacobian(point.x, J);
    // An x within sqrt(eps) |x| of a root leaves |f| <= |J| sqrt(eps) |x|; a wrong equation leaves O(1).
    const double allowed = 10.0 * J.cwiseAbs().rowwise().sum().maxCoeff() * std::sqrt(eps) *
                           std::max(1.0, point.x.lpNorm<Eigen::Infinity>());
    INFO(point.problem << " n = " << point.x.size());
    CHECK(residual_at(problem, point.x).lpNorm<Eigen::Infinity>() <= allowed);
  }
}

TEST_CASE("Sizes a problem does not have are refused", "[minpack][mgh][failure]") {
  CHECK_THROWS_AS(make_test_problem("rosenbrock", 3), std::invalid_argument);
  CHECK_THROWS_AS(make_test_problem("helical-valley", 2), std::invalid_argument);
  CHECK_THROWS_AS(make_test_problem("watson", 1), std::invalid_argument);
  CHECK_THROWS_AS(make_test_problem("watson", 32), std::invalid_argument);
  CHECK_THROWS_AS(make_test_problem("chebyquad", 0), std::invalid_argument);
  CHECK_THROWS_AS(make_test_problem("broyden-banded", -4), std::invalid_argument);
  CHECK_THROWS_AS(make_test_problem("no-such-problem", 2), std::invalid_argument);
  CHECK_THROWS_WITH(make_test_problem("watson", 40), Catch::Matchers::Contains("n = 2..31"));
  CHECK(make_test_problem("watson", 31).system->dimension() == 31);
  CHECK(make_test_problem("rosenbrock", 2).system->dimension() == 2);
  // The defaults: n = 10 as before, the driver's first size for watson and chebyquad.
  CHECK(make_test_problem("discrete-bvp").system->dimension() == variable_problem_size);
  CHECK(make_test_problem("watson").system->dimension() == 6);
  CHECK(make_test_problem("chebyquad").system->dimension() == 5);
  CHECK(describe_sizes(problem_sizes("wood")) == "n = 4 only");
  CHECK(describe_sizes(problem_sizes("broyden-banded")) == "n >= 1");
}
