#pragma once
// The cases of MINPACK's test driver for hybrj (Moré, Garbow & Hillstrom, "User guide for
// MINPACK-1", ANL-80-74, 1980; the driver's data file lists problem, size and number of starts):
// each case is one problem at one size from one start, x0, 10 x0 or 100 x0.

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
