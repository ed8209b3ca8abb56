#pragma once
// The cases of MINPACK's test driver for hybrj (Moré, Garbow & Hillstrom, "User guide for
// MINPACK-1", ANL-80-74, 1980; the driver's data file lists problem, size and number of starts):
// each case is one problem at one size from one start, x0, 10 x0 or 100 x0.
// The driver's data (fortran-lang/minpack test/test_hybrj.f90, "originally from file21"):
//   problem 1..14 = rosenbrock, powell-singular, powell-badly-scaled, wood, helical-valley, watson,
//   chebyquad, brown-almost-linear, discrete-bvp, discrete-integral, trigonometric,
//   variably-dimensioned, broyden-tridiagonal, broyden-banded;
//   22 (problem, size, number of starts) rows giving 55 cases; start k uses factor 10^(k-1).

#include <Eigen/Core>
#include <string>
#include <vector>

#include "numlab/nonlinear/mgh_problems.hpp"

namespace numlab::nonlinear {

struct MinpackCase {
  std::string problem;  // one of test_problem_names()
  int n;                // the size the driver uses
  double factor;        // 1, 10 or 100: the start is factor x0 (MINPACK's initpt)
};

// Every case the driver runs, in its order.
const std::vector<MinpackCase>& minpack_cases();

// MINPACK's problem number (1..14) of a problem in the hybrj set; throws std::invalid_argument for
// any other name (freudenstein-roth and arctangent are not in it).
int minpack_problem_number(const std::string& problem);

// The sizes the driver uses for a problem, in its order (e.g. chebyquad: 5, 6, 7, 8, 9).
std::vector<int> minpack_sizes(const std::string& problem);

// MINPACK's initpt: factor x0, except that Watson's standard start is zero, so for Watson with a
// factor other than 1 every entry is the factor itself.
Eigen::VectorXd minpack_start(const std::string& problem, const Eigen::VectorXd& standard_start, double factor);

// "helical-valley n=3 start 10x0".
std::string case_label(const MinpackCase& test_case);

// The case's problem at its size, and its start.
struct MinpackInstance {
  TestProblem problem;
  Eigen::VectorXd start;
};

// Throws std::invalid_argument for an unknown problem or a size it does not have.
MinpackInstance make_minpack_instance(const MinpackCase& test_case);

}  // namespace numlab::nonlinear
