// BUG: every x_i of a sweep is computed from xold, the vector before the sweep: a Jacobi sweep
// CAUSE: jacobi_sweep
#include <algorithm>

json solve(const json& request) {
  Matrix A = numlab::exercise::matrix(request["A"]);
  Vector b = numlab::exercise::vector(request["b"]);
  Vector x = numlab::exercise::vector(request["x0"]);
  const std::size_t n = x.size();
  if (request["normal_equations"].get<bool>()) {
    Matrix M(n, Vector(n, 0.0));
    Vector c(n, 0.0);
    for (std::size_t i = 0; i < n; ++i) {
      for (std::size_t r = 0; r < A.size(); ++r) c[i] += A[r][i] * b[r];
      for (std::size_t j = 0; j < n; ++j)
        for (std::size_t r = 0; r < A.size(); ++r) M[i][j] += A[r][i] * A[r][j];
    }
    A = M;
    b = c;
  }
  const double tol = request["tolerance"].get<double>();
  const int max_it = request["max_iterations"].get<int>();
  json trace = json::array();
  std::string status = "max_iterations";
  double first = 0.0;
  int it = 0;
  while (it < max_it) {
    ++it;
    const Vector xold = x;
    for (std::size_t i = 0; i < n; ++i) {
      double s = b[i];
      for (std::size_t j = 0; j < n; ++j)
        if (j != i) s -= A[i][j] * xold[j];
      x[i] = s / A[i][i];
    }
    double du = 0.0, xmax = 1.0;
    for (std::size_t i = 0; i < n; ++i) {
      du = std::max(du, std::abs(x[i] - xold[i]));
      xmax = std::max(xmax, std::abs(x[i]));
    }
    if (it == 1) first = du;
    trace.push_back({{"x", x}, {"update_inf", du}});
    if (du <= tol * xmax) { status = "converged"; break; }
    if (du > 1e8 * std::max(first, tol)) { status = "diverged"; break; }
  }
  return json{{"x", x}, {"status", status}, {"iterations", it}, {"trace", trace}};
}
