#pragma once
// A correct student solution of `gauss-seidel` in C++ (the reference; references/cpp/gauss_seidel.cpp
// serves it): sweeps of M x = c (M = A or A^T A), the stop test with |.|, and the sweep trace.

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <numlab/exercise_protocol.hpp>

namespace gauss_seidel_solution {

using numlab::exercise::Matrix;
using numlab::exercise::Vector;

// M = A^T A and c = A^T b.
inline void normal_equations(const Matrix& A, const Vector& b, Matrix& M, Vector& c) {
  const std::size_t rows = A.size(), n = A[0].size();
  M.assign(n, Vector(n, 0.0));
  c.assign(n, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = 0; j < n; ++j) {
      for (std::size_t r = 0; r < rows; ++r) M[i][j] += A[r][i] * A[r][j];
    }
    for (std::size_t r = 0; r < rows; ++r) c[i] += A[r][i] * b[r];
  }
}

// The stop test: the textbook's, or (for the in-process mutants) seed 001's all(x_new - x_old < tolerance).
enum class StopTest { absolute_update, signed_change };

inline nlohmann::json solve_with(const nlohmann::json& request, StopTest test) {
  Matrix M = numlab::exercise::matrix(request["A"]);
  Vector c = numlab::exercise::vector(request["b"]);
  if (request["normal_equations"].get<bool>()) {
    const Matrix A = M;
    const Vector b = c;
    normal_equations(A, b, M, c);
  }
  Vector x = numlab::exercise::vector(request["x0"]);
  const double tolerance = request["tolerance"].get<double>();
  const int max_iterations = request["max_iterations"].get<int>();
  const std::size_t n = x.size();
  nlohmann::json trace = nlohmann::json::array();
  double first_update = 0.0;
  std::string status = "max_iterations";
  int sweep = 0;
  while (sweep < max_iterations) {
    ++sweep;
    double update = 0.0, size = 0.0, largest_change = -HUGE_VAL;
    for (std::size_t i = 0; i < n; ++i) {
      double sum = c[i];
      for (std::size_t j = 0; j < n; ++j) {
        if (j != i) sum -= M[i][j] * x[j];
      }
      const double updated = sum / M[i][i];
      update = std::max(update, std::abs(updated - x[i]));
      largest_change = std::max(largest_change, updated - x[i]);
      x[i] = updated;
    }
    for (double value : x) size = std::max(size, std::abs(value));
    if (sweep == 1) first_update = update;
    trace.push_back({{"x", x}, {"update_inf", update}});
    const bool small = test == StopTest::absolute_update ? update <= tolerance * std::max(1.0, size)
                                                         : largest_change < tolerance;
    if (small) {
      status = "converged";
      break;
    }
    if (update > 1e8 * std::max(first_update, tolerance)) {
      status = "diverged";
      break;
    }
  }
  return {{"x", x}, {"status", status}, {"iterations", sweep}, {"trace", trace}};
}

inline nlohmann::json solve(const nlohmann::json& request) { return solve_with(request, StopTest::absolute_update); }

}  // namespace gauss_seidel_solution
