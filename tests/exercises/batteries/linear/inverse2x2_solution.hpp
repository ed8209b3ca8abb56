#pragma once
// A correct student solution of `inverse2x2` in C++ (the reference; references/cpp/inverse2x2.cpp
// serves it): A scaled by a power of two, the closed form, the singular test.

#include <algorithm>
#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <numlab/exercise_protocol.hpp>

namespace inverse2x2_solution {

inline nlohmann::json solve(const nlohmann::json& request) {
  const numlab::exercise::Matrix A = numlab::exercise::matrix(request["A"]);
  const double largest = std::max({std::abs(A[0][0]), std::abs(A[0][1]), std::abs(A[1][0]), std::abs(A[1][1])});
  if (largest == 0.0) return {{"status", "singular"}};
  int exponent = 0;
  std::frexp(largest, &exponent);  // largest = m 2^exponent, 0.5 <= m < 1: scaled entries stay below 1
  const double a = std::ldexp(A[0][0], -exponent), b = std::ldexp(A[0][1], -exponent);
  const double c = std::ldexp(A[1][0], -exponent), d = std::ldexp(A[1][1], -exponent);
  const double det = a * d - b * c;
  if (std::abs(det) <= std::numeric_limits<double>::epsilon() * (a * a + b * b + c * c + d * d)) {
    return {{"status", "singular"}};
  }
  // (A / s)^-1 = s A^-1, so A^-1 = (adjugate / det) / s.
  const auto entry = [&](double value) { return std::ldexp(value / det, -exponent); };
  return {{"inverse", {{entry(d), entry(-b)}, {entry(-c), entry(a)}}}};
}

}  // namespace inverse2x2_solution
