#pragma once
// A correct student solution of `gepp` in C++ (the reference; references/cpp/gepp.cpp serves it):
// Gaussian elimination with partial pivoting, its singular test and its pivot trace.

#include <algorithm>
#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <numlab/exercise_protocol.hpp>
#include <utility>

namespace gepp_solution {

// The pivot rule: the textbook's, or (for the in-process mutants of test_exercise_linear) a known mistake.
enum class PivotRule { largest_magnitude, largest_signed_value, none };

inline nlohmann::json solve_with(const nlohmann::json& request, PivotRule rule) {
  using numlab::exercise::Matrix;
  using numlab::exercise::Vector;
  Matrix a = numlab::exercise::matrix(request["A"]);
  Vector b = numlab::exercise::vector(request["b"]);
  const std::size_t n = b.size();
  double largest = 0.0;
  for (const Vector& row : a) {
    for (double entry : row) largest = std::max(largest, std::abs(entry));
  }
  const double negligible = static_cast<double>(n) * std::numeric_limits<double>::epsilon() * largest;
  nlohmann::json trace = nlohmann::json::array();
  for (std::size_t k = 0; k < n; ++k) {
    std::size_t p = k;  // the row with the largest |a_pk|, p >= k
    for (std::size_t i = k + 1; i < n; ++i) {
      if (rule == PivotRule::largest_magnitude && std::abs(a[i][k]) > std::abs(a[p][k])) p = i;
      if (rule == PivotRule::largest_signed_value && a[i][k] > a[p][k]) p = i;
    }
    std::swap(a[k], a[p]);
    std::swap(b[k], b[p]);
    if (std::abs(a[k][k]) <= negligible) return {{"status", "singular"}, {"trace", trace}};
    trace.push_back({{"column", k}, {"pivot_row", p}, {"pivot", a[k][k]}});
    for (std::size_t i = k + 1; i < n; ++i) {
      const double l = a[i][k] / a[k][k];
      for (std::size_t j = k; j < n; ++j) a[i][j] -= l * a[k][j];
      b[i] -= l * b[k];
    }
  }
  Vector x(n, 0.0);
  for (std::size_t i = n; i-- > 0;) {
    double sum = b[i];
    for (std::size_t j = i + 1; j < n; ++j) sum -= a[i][j] * x[j];
    x[i] = sum / a[i][i];
  }
  return {{"x", x}, {"trace", trace}};
}

inline nlohmann::json solve(const nlohmann::json& request) { return solve_with(request, PivotRule::largest_magnitude); }

}  // namespace gepp_solution
