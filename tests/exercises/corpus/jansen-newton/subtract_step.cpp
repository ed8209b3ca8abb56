// BUG: after solving J dx = -f the update is x -= dx (the sign of the step flipped twice)
// CAUSE: step_sign
#include <algorithm>
#include <array>
#include <utility>

namespace {
const std::array<double, 8> L = {50.0, 41.5, 55.8, 40.1, 39.4, 61.9, 39.3, 36.7};
const std::array<std::array<int, 8>, 4> sign = {{{1, -1, 0, 0, 0, 0, 0, 0},
                                                 {1, 0, 1, -1, 0, 0, 0, 0},
                                                 {0, 0, 0, 0, 0, 1, -1, 0},
                                                 {1, 0, 1, 0, 1, 0, -1, -1}}};

void closure(double crank, const Vector& t, Vector& f, Matrix& J) {
  const double Y = 15.0 * std::sin(crank) + 7.8, X = 15.0 * std::cos(crank) + 38.0;
  for (int r = 0; r < 4; ++r) {
    f[2 * r] = Y;
    f[2 * r + 1] = X;
    for (int k = 0; k < 8; ++k) {
      const double w = sign[r][k] * L[k];
      f[2 * r] += w * std::sin(t[k]);
      f[2 * r + 1] += w * std::cos(t[k]);
      J[2 * r][k] = w * std::cos(t[k]);
      J[2 * r + 1][k] = -w * std::sin(t[k]);
    }
  }
}

Vector gauss(Matrix A, Vector b) {
  const std::size_t n = b.size();
  for (std::size_t k = 0; k < n; ++k) {
    std::size_t p = k;
    for (std::size_t i = k + 1; i < n; ++i)
      if (std::abs(A[i][k]) > std::abs(A[p][k])) p = i;
    std::swap(A[k], A[p]);
    std::swap(b[k], b[p]);
    if (A[k][k] == 0.0) throw std::runtime_error("singular Jacobian");
    for (std::size_t i = k + 1; i < n; ++i) {
      const double m = A[i][k] / A[k][k];
      for (std::size_t j = k; j < n; ++j) A[i][j] -= m * A[k][j];
      b[i] -= m * b[k];
    }
  }
  Vector x(n);
  for (std::size_t i = n; i-- > 0;) {
    double s = b[i];
    for (std::size_t j = i + 1; j < n; ++j) s -= A[i][j] * x[j];
    x[i] = s / A[i][i];
  }
  return x;
}

double inf_norm(const Vector& v) {
  double m = 0.0;
  for (double e : v) m = std::max(m, std::abs(e));
  return m;
}
}  // namespace

json solve(const json& request) {
  const double crank = request["crank_angle"].get<double>();
  Vector t = numlab::exercise::vector(request["theta0"]);
  const double tol = request["tolerance"].get<double>();
  const int max_it = request["max_iterations"].get<int>();
  Vector f(8);
  Matrix J(8, Vector(8));
  closure(crank, t, f, J);
  json trace = json::array();
  int it = 0;
  std::string status = "max_iterations";
  while (true) {
    if (inf_norm(f) <= tol) { status = "converged"; break; }
    if (it >= max_it) break;
    Vector minus_f(8);
    for (int i = 0; i < 8; ++i) minus_f[i] = -f[i];
    const Vector dx = gauss(J, minus_f);
    for (int i = 0; i < 8; ++i) t[i] -= dx[i];
    ++it;
    closure(crank, t, f, J);
    trace.push_back({{"residual_inf", inf_norm(f)}, {"step_inf", inf_norm(dx)}});
    if (!std::isfinite(inf_norm(f))) { status = "diverged"; break; }
  }
  return json{{"theta", t}, {"status", status}, {"iterations", it}, {"trace", trace}};
}
