#pragma once
// Generators of the nonlinear test systems (a library part, not a test) from Moré, Garbow & Hillstrom, "Testing unconstrained optimization
// software" (ACM TOMS 7, 1981), in the square forms MINPACK uses for equation solvers, each with
// its analytic Jacobian, standard starting point and, where one is known, a root. One more,
// "arctangent", shows what damping is for.

#include <Eigen/Core>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "numlab/nonlinear/autodiff_system.hpp"

namespace numlab::nonlinear {

struct TestProblem {
  std::string name;
  std::string description;
  std::shared_ptr<const AutoDiffSystem> system;
  Eigen::VectorXd standard_start;
  std::optional<Eigen::VectorXd> known_root;  // none where no closed form is known (see the description)
  // Where the square system has no root (chebyquad n = 8 and n >= 10): the minimum of ||f||_2^2 the
  // literature gives (Moré, Garbow & Hillstrom 1981, table of results), if it gives one.
  std::optional<double> least_squares_minimum = std::nullopt;
};

// rosenbrock, freudenstein-roth, powell-badly-scaled, powell-singular, wood, helical-valley,
// discrete-bvp, trigonometric, broyden-tridiagonal; and arctangent, the classic case for damping;
// then the rest of MINPACK's hybrj test set: watson, chebyquad, brown-almost-linear,
// discrete-integral, variably-dimensioned, broyden-banded.
const std::vector<std::string>& test_problem_names();

// The sizes a problem has: fixed-size problems have one (smallest == largest == default_size).
// Variable-size problems default to n = 10, except watson (6) and chebyquad (5), whose defaults are
// the first sizes MINPACK's hybrj driver uses.
struct ProblemSizes {
  int default_size;
  int smallest;
  int largest;  // std::numeric_limits<int>::max() where there is no upper limit
  bool fixed() const { return smallest == largest; }
};

// The default size of discrete-bvp, trigonometric, broyden-tridiagonal and the other n = 10 problems.
inline constexpr int variable_problem_size = 10;

// Throws std::invalid_argument for an unknown name.
ProblemSizes problem_sizes(const std::string& name);

// "n = 2..31", "n = 4 only", "n >= 1": for messages and docs.
std::string describe_sizes(const ProblemSizes& sizes);

// The problem at its default size. Throws std::invalid_argument for an unknown name.
TestProblem make_test_problem(const std::string& name);

// The problem at size n. Throws std::invalid_argument for an unknown name or a size the problem
// does not have (rosenbrock n = 3, watson n < 2 or n > 31, chebyquad n < 1, ...).
TestProblem make_test_problem(const std::string& name, int n);

}  // namespace numlab::nonlinear
