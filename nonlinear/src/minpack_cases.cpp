#include "numlab/nonlinear/minpack_cases.hpp"

#include <array>
#include <stdexcept>

namespace numlab::nonlinear {

namespace {

// MINPACK's problem numbers 1..14, in order.
const std::array<const char*, 14> problem_by_number = {
    "rosenbrock",        "powell-singular", "powell-badly-scaled",  "wood",
    "helical-valley",    "watson",          "chebyquad",            "brown-almost-linear",
    "discrete-bvp",      "discrete-integral", "trigonometric",      "variably-dimensioned",
    "broyden-tridiagonal", "broyden-banded"};

// The hybrj driver's data, row by row: problem number, size, number of starts.
struct DriverRow {
  int problem;
  int n;
  int starts;
};
constexpr std::array<DriverRow, 22> driver_rows = {{{1, 2, 3},   {2, 4, 3},   {3, 2, 2},   {4, 4, 3},  {5, 3, 3},
                                                    {6, 6, 2},   {6, 9, 2},   {7, 5, 3},   {7, 6, 3},  {7, 7, 3},
                                                    {7, 8, 1},   {7, 9, 1},   {8, 10, 3},  {8, 30, 1}, {8, 40, 1},
                                                    {9, 10, 3},  {10, 1, 3},  {10, 10, 3}, {11, 10, 3}, {12, 10, 3},
                                                    {13, 10, 3}, {14, 10, 3}}};

}  // namespace

const std::vector<MinpackCase>& minpack_cases() {
  static const std::vector<MinpackCase> cases = [] {
    std::vector<MinpackCase> list;
    for (const DriverRow& row : driver_rows) {
      double factor = 1.0;
      for (int start = 0; start < row.starts; ++start, factor *= 10.0) {
        list.push_back({problem_by_number[row.problem - 1], row.n, factor});
      }
    }
    return list;
  }();
  return cases;
}

int minpack_problem_number(const std::string& problem) {
  for (std::size_t i = 0; i < problem_by_number.size(); ++i) {
    if (problem == problem_by_number[i]) return static_cast<int>(i) + 1;
  }
  throw std::invalid_argument("'" + problem + "' is not in MINPACK's hybrj test set");
}

std::vector<int> minpack_sizes(const std::string& problem) {
  const int number = minpack_problem_number(problem);
  std::vector<int> sizes;
  for (const DriverRow& row : driver_rows) {
    if (row.problem == number) sizes.push_back(row.n);
  }
  return sizes;
}

Eigen::VectorXd minpack_start(const std::string& problem, const Eigen::VectorXd& standard_start, double factor) {
  if (factor == 1.0) return standard_start;  // initpt: "if factor is unity, no multiplication is performed"
  if (problem == "watson") return Eigen::VectorXd::Constant(standard_start.size(), factor);
  return factor * standard_start;
}

std::string case_label(const MinpackCase& test_case) {
  return test_case.problem + " n=" + std::to_string(test_case.n) + " start " +
         std::to_string(static_cast<long>(test_case.factor)) + "x0";
}

MinpackInstance make_minpack_instance(const MinpackCase& test_case) {
  TestProblem problem = make_test_problem(test_case.problem, test_case.n);
  Eigen::VectorXd start = minpack_start(test_case.problem, problem.standard_start, test_case.factor);
  return {std::move(problem), std::move(start)};
}

}  // namespace numlab::nonlinear
