// BUG: back substitution divides only b_i by the pivot, x_i = b_i / u_ii - sum_j u_ij x_j (the sum is not divided by u_ii)
// CAUSE: back_substitution
// SET: heldout
#include <algorithm>
#include <limits>

json solve(const json& request) {
  Matrix a = numlab::exercise::matrix(request["A"]);
  Vector rhs = numlab::exercise::vector(request["b"]);
  const int n = static_cast<int>(rhs.size());
  double biggest = 0.0;
  for (const Vector& row : a)
    for (double v : row) biggest = std::max(biggest, std::fabs(v));
  const double negligible = n * std::numeric_limits<double>::epsilon() * biggest;
  json pivots = json::array();
  for (int k = 0; k < n; ++k) {
    int p = k;
    for (int i = k + 1; i < n; ++i)
      if (std::fabs(a[i][k]) > std::fabs(a[p][k])) p = i;
    if (p != k) {
      std::swap(a[k], a[p]);
      std::swap(rhs[k], rhs[p]);
    }
    if (std::fabs(a[k][k]) <= negligible) return json{{"status", "singular"}};
    pivots.push_back({{"column", k}, {"pivot_row", p}, {"pivot", a[k][k]}});
    for (int i = k + 1; i < n; ++i) {
      const double m = a[i][k] / a[k][k];
      for (int j = k; j < n; ++j) a[i][j] -= m * a[k][j];
      rhs[i] -= m * rhs[k];
    }
  }
  Vector x(n, 0.0);
  for (int i = n - 1; i >= 0; --i) {
    double value = rhs[i] / a[i][i];
    for (int j = i + 1; j < n; ++j) value -= a[i][j] * x[j];
    x[i] = value;
  }
  return json{{"x", x}, {"trace", pivots}};
}
