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
  std::optional<Eigen::VectorXd> known_root;  // none for discrete-bvp and broyden-tridiagonal
};

// rosenbrock, freudenstein-roth, powell-badly-scaled, powell-singular, wood, helical-valley,
// discrete-bvp, trigonometric, broyden-tridiagonal; and arctangent, the classic case for damping.
const std::vector<std::string>& test_problem_names();

// The variable-size problems (discrete-bvp, trigonometric, broyden-tridiagonal) use n = 10.
inline constexpr int variable_problem_size = 10;

// Throws std::invalid_argument for an unknown name.
TestProblem make_test_problem(const std::string& name);

}  // namespace numlab::nonlinear
