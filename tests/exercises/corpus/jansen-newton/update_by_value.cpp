// BUG: the update is done in a helper apply_step(Vector theta, const Vector& dx) that takes theta by value: the caller's angles never change, so every iteration repeats the first step
// CAUSE: x_never_updated
// SET: heldout
#include <algorithm>
#include <string>

namespace {
struct Leg {
  double l1 = 50.0, l2 = 41.5, l3 = 55.8, l4 = 40.1, l5 = 39.4, l6 = 61.9, l7 = 39.3, l8 = 36.7;
};

Vector residual(double ti, const Vector& t) {
  const Leg g;
  const double Y = 15.0 * std::sin(ti) + 7.8, X = 15.0 * std::cos(ti) + 38.0;
  return {Y + g.l1 * std::sin(t[0]) - g.l2 * std::sin(t[1]),
          X + g.l1 * std::cos(t[0]) - g.l2 * std::cos(t[1]),
          Y + g.l1 * std::sin(t[0]) + g.l3 * std::sin(t[2]) - g.l4 * std::sin(t[3]),
          X + g.l1 * std::cos(t[0]) + g.l3 * std::cos(t[2]) - g.l4 * std::cos(t[3]),
          Y + g.l6 * std::sin(t[5]) - g.l7 * std::sin(t[6]),
          X + g.l6 * std::cos(t[5]) - g.l7 * std::cos(t[6]),
          Y + g.l1 * std::sin(t[0]) + g.l3 * std::sin(t[2]) + g.l5 * std::sin(t[4]) - g.l7 * std::sin(t[6]) -
              g.l8 * std::sin(t[7]),
          X + g.l1 * std::cos(t[0]) + g.l3 * std::cos(t[2]) + g.l5 * std::cos(t[4]) - g.l7 * std::cos(t[6]) -
              g.l8 * std::cos(t[7])};
}

Matrix jacobian(const Vector& t) {
  const Leg g;
  const double l[8] = {g.l1, g.l2, g.l3, g.l4, g.l5, g.l6, g.l7, g.l8};
  const int sign[4][8] = {{1, -1, 0, 0, 0, 0, 0, 0}, {1, 0, 1, -1, 0, 0, 0, 0},
                          {0, 0, 0, 0, 0, 1, -1, 0}, {1, 0, 1, 0, 1, 0, -1, -1}};
  Matrix J(8, Vector(8, 0.0));
  for (int loop = 0; loop < 4; ++loop)
    for (int k = 0; k < 8; ++k) {
      J[2 * loop][k] = sign[loop][k] * l[k] * std::cos(t[k]);
      J[2 * loop + 1][k] = -sign[loop][k] * l[k] * std::sin(t[k]);
    }
  return J;
}

// J dx = rhs by elimination with partial pivoting on an augmented copy
Vector linear_solve(Matrix J, const Vector& rhs) {
  const std::size_t n = rhs.size();
  for (std::size_t i = 0; i < n; ++i) J[i].push_back(rhs[i]);
  for (std::size_t col = 0; col < n; ++col) {
    auto best = std::max_element(J.begin() + col, J.end(), [col](const Vector& r, const Vector& s) {
      return std::abs(r[col]) < std::abs(s[col]);
    });
    std::iter_swap(J.begin() + col, best);
    if (J[col][col] == 0.0) throw std::runtime_error("J is singular");
    for (std::size_t row = col + 1; row < n; ++row) {
      const double factor = J[row][col] / J[col][col];
      for (std::size_t c = col; c <= n; ++c) J[row][c] -= factor * J[col][c];
    }
  }
  Vector dx(n, 0.0);
  for (std::size_t row = n; row-- > 0;) {
    double sum = J[row][n];
    for (std::size_t c = row + 1; c < n; ++c) sum -= J[row][c] * dx[c];
    dx[row] = sum / J[row][row];
  }
  return dx;
}

double max_abs(const Vector& v) {
  double m = 0.0;
  for (double e : v) m = std::max(m, std::abs(e));
  return m;
}

void apply_step(Vector theta, const Vector& dx) {
  for (std::size_t k = 0; k < theta.size(); ++k) theta[k] += dx[k];
}
}  // namespace

json solve(const json& request) {
  const double ti = request["crank_angle"].get<double>();
  Vector theta = numlab::exercise::vector(request["theta0"]);
  const double tolerance = request["tolerance"].get<double>();
  const int limit = request["max_iterations"].get<int>();
  json trace = json::array();
  std::string status = "max_iterations";
  int count = 0;
  Vector f = residual(ti, theta);
  while (true) {
    if (max_abs(f) <= tolerance) {
      status = "converged";
      break;
    }
    if (count == limit) break;
    Vector minus_f(f.size());
    for (std::size_t i = 0; i < f.size(); ++i) minus_f[i] = -f[i];
    const Vector dx = linear_solve(jacobian(theta), minus_f);
    apply_step(theta, dx);
    ++count;
    f = residual(ti, theta);
    trace.push_back({{"residual_inf", max_abs(f)}, {"step_inf", max_abs(dx)}});
  }
  return json{{"theta", theta}, {"status", status}, {"iterations", count}, {"trace", trace}};
}
