#include "numlab/nonlinear/minpack_cases.hpp"

#include <stdexcept>

namespace numlab::nonlinear {

// FIRST CUT (lead): only the problems numlab has today, at the sizes they have. The MINPACK
// helper replaces this with the driver's full list (14 problems, 22 sizes, 55 cases).
const std::vector<MinpackCase>& minpack_cases() {
  static const std::vector<MinpackCase> cases = [] {
    std::vector<MinpackCase> list;
    const std::vector<std::pair<std::string, int>> problems = {
        {"rosenbrock", 3},   {"powell-singular", 3}, {"powell-badly-scaled", 2},  {"wood", 3},
        {"helical-valley", 3}, {"discrete-bvp", 3}, {"trigonometric", 3}, {"broyden-tridiagonal", 3}};
    for (const auto& [name, starts] : problems) {
      const int n = make_test_problem(name).system->dimension();
      double factor = 1.0;
      for (int start = 0; start < starts; ++start, factor *= 10.0) list.push_back({name, n, factor});
    }
    return list;
  }();
  return cases;
}

std::string case_label(const MinpackCase& test_case) {
  return test_case.problem + " n=" + std::to_string(test_case.n) + " start " +
         std::to_string(static_cast<long>(test_case.factor)) + "x0";
}

MinpackInstance make_minpack_instance(const MinpackCase& test_case) {
  TestProblem problem = make_test_problem(test_case.problem);
  if (problem.system->dimension() != test_case.n) {
    throw std::invalid_argument(test_case.problem + " has no size " + std::to_string(test_case.n));
  }
  Eigen::VectorXd start = test_case.factor * problem.standard_start;
  return {std::move(problem), std::move(start)};
}

}  // namespace numlab::nonlinear
