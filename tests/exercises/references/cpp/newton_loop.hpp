#pragma once
// Full Newton-Raphson for the reference solutions: test max |f_i| <= tolerance, else solve
// J dx = -f by partial-pivoting LU, x <- x + dx, one trace entry per iteration.
#include <Eigen/Dense>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace newton_reference {

// closure(x, f, J) evaluates f and J at x.
template <int N, typename Closure>
nlohmann::json newton(Closure&& closure, Eigen::Matrix<double, N, 1> x, double tolerance, int max_iterations,
                      const char* answer_field) {
  Eigen::Matrix<double, N, 1> f;
  Eigen::Matrix<double, N, N> J;
  nlohmann::json trace = nlohmann::json::array();
  std::string status = "max_iterations";
  int iterations = 0;
  closure(x, f, J);
  while (true) {
    if (f.template lpNorm<Eigen::Infinity>() <= tolerance) {
      status = "converged";
      break;
    }
    if (iterations >= max_iterations) break;
    const Eigen::FullPivLU<Eigen::Matrix<double, N, N>> lu(J);
    if (!lu.isInvertible()) {
      status = "singular";
      break;
    }
    const Eigen::Matrix<double, N, 1> dx = lu.solve(-f);
    x += dx;
    ++iterations;
    closure(x, f, J);
    trace.push_back({{"residual_inf", f.template lpNorm<Eigen::Infinity>()}, {"step_inf", dx.template lpNorm<Eigen::Infinity>()}});
    if (!f.allFinite()) {
      status = "diverged";
      break;
    }
  }
  return {{answer_field, std::vector<double>(x.data(), x.data() + N)}, {"status", status}, {"iterations", iterations},
          {"trace", trace}};
}

}  // namespace newton_reference
