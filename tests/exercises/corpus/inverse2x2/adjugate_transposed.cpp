// BUG: the inverse is written {{d, -c}, {-b, a}} / det: the off-diagonal entries are transposed
// CAUSE: transposed
#include <algorithm>
#include <limits>

json solve(const json& request) {
  Matrix m = numlab::exercise::matrix(request["A"]);
  double a = m[0][0], b = m[0][1], c = m[1][0], d = m[1][1];
  const double big = std::max({std::abs(a), std::abs(b), std::abs(c), std::abs(d)});
  if (big == 0.0) return json{{"status", "singular"}};
  int e = 0;
  std::frexp(big, &e);
  a = std::ldexp(a, -e);
  b = std::ldexp(b, -e);
  c = std::ldexp(c, -e);
  d = std::ldexp(d, -e);
  const double det = a * d - b * c;
  if (std::abs(det) <= std::numeric_limits<double>::epsilon() * (a * a + b * b + c * c + d * d))
    return json{{"status", "singular"}};
  Matrix inv = {{d / det, -c / det}, {-b / det, a / det}};
  for (auto& row : inv)
    for (double& v : row) v = std::ldexp(v, -e);
  return json{{"inverse", inv}};
}
