#pragma once
// Internal to mgh_problems.cpp: the six problems of MINPACK's hybrj test set that complete the
// catalogue (mgh_problems_minpack.cpp). Each takes a size already checked against problem_sizes().

#include "numlab/nonlinear/mgh_problems.hpp"

namespace numlab::nonlinear::detail {

TestProblem make_watson(int n);
TestProblem make_chebyquad(int n);
TestProblem make_brown_almost_linear(int n);
TestProblem make_discrete_integral(int n);
TestProblem make_variably_dimensioned(int n);
TestProblem make_broyden_banded(int n);

}  // namespace numlab::nonlinear::detail
