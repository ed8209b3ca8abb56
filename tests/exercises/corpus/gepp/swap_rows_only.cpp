// BUG: std::swap(A[k], A[p]) swaps the rows of A but b is never swapped with them
// CAUSE: swap_without_b
#include <algorithm>
#include <limits>

json solve(const json& request) {
  Matrix A = numlab::exercise::matrix(request["A"]);
  Vector b = numlab::exercise::vector(request["b"]);
  const std::size_t n = b.size();
  double amax = 0.0;
  for (const auto& row : A)
    for (double v : row) amax = std::max(amax, std::abs(v));
  const double tiny = n * std::numeric_limits<double>::epsilon() * amax;
  json trace = json::array();
  for (std::size_t k = 0; k < n; ++k) {
    std::size_t p = k;
    for (std::size_t i = k + 1; i < n; ++i)
      if (std::abs(A[i][k]) > std::abs(A[p][k])) p = i;
    std::swap(A[k], A[p]);
    if (std::abs(A[k][k]) <= tiny) return json{{"status", "singular"}};
    trace.push_back({{"column", k}, {"pivot_row", p}, {"pivot", A[k][k]}});
    for (std::size_t i = k + 1; i < n; ++i) {
      const double l = A[i][k] / A[k][k];
      for (std::size_t j = k; j < n; ++j) A[i][j] -= l * A[k][j];
      b[i] -= l * b[k];
    }
  }
  Vector x(n);
  for (std::size_t i = n; i-- > 0;) {
    double s = b[i];
    for (std::size_t j = i + 1; j < n; ++j) s -= A[i][j] * x[j];
    x[i] = s / A[i][i];
  }
  return json{{"x", x}, {"trace", trace}};
}
