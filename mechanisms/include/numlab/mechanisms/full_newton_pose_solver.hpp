#pragma once
// The `full` pose solver of both linkages: Newton on the whole closure, with the linear step
// chosen by name (--linear: gepp, gauss-seidel, gsl-lu, eigen-lu) and fixed at compile time.

#include <algorithm>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>

#include "numlab/linalg/eigen_reference.hpp"
#include "numlab/linalg/gauss_elimination.hpp"
#include "numlab/linalg/gauss_seidel.hpp"
#include "numlab/mechanisms/pose_solver.hpp"
#include "numlab/nonlinear/linear_step.hpp"
#include "numlab/nonlinear/newton.hpp"

namespace numlab::mechanisms {

// Closure: a fixed-size system with set_crank_angle() (JansenClosure, Jansen10Closure,
// MustangClosure). Its Newton is built once and reused for every pose.
template <typename Closure, typename LinearStep, typename Angles>
class FullNewtonPoseSolver final : public PoseSolver<Angles> {
 public:
  explicit FullNewtonPoseSolver(const nonlinear::NewtonOptions& options) : closure_(0.0), newton_(closure_, options) {}
  FullNewtonPoseSolver(const nonlinear::NewtonOptions& options, LinearStep linear_step)
      : closure_(0.0), newton_(closure_, options, std::move(linear_step)) {}

  PoseOutcome solve(double input_angle, Angles& x) override {
    closure_.set_crank_angle(input_angle);
    const auto result = newton_.solve(typename Closure::Vector(x));
    x = result.x;
    return {result.status, result.iterations, result.residual_norm};
  }

 private:
  Closure closure_;
  nonlinear::Newton<Closure, LinearStep> newton_;
};

// Throws std::invalid_argument for an unknown linear method.
template <typename Closure, typename Angles>
std::unique_ptr<PoseSolver<Angles>> make_full_newton(const std::string& linear, const nonlinear::NewtonOptions& options) {
  constexpr int N = Closure::size;
  if (linear == "gepp") return std::make_unique<FullNewtonPoseSolver<Closure, linalg::GaussElimination<N>, Angles>>(options);
  if (linear == "gauss-seidel") {
    // An inexact inner solve slows Newton down, a very inexact one stops it: sweep the normal
    // equations until the update is far below Newton's own tolerance.
    linalg::GaussSeidelOptions inner;
    inner.tolerance = std::min(1e-9, 1e-3 * options.residual_tolerance);
    inner.max_iterations = 100000;
    return std::make_unique<FullNewtonPoseSolver<Closure, linalg::GaussSeidel<N>, Angles>>(options,
                                                                                            linalg::GaussSeidel<N>(inner));
  }
  if (linear == "gsl-lu") return std::make_unique<FullNewtonPoseSolver<Closure, nonlinear::GslLuStep<N>, Angles>>(options);
  if (linear == "eigen-lu") return std::make_unique<FullNewtonPoseSolver<Closure, linalg::EigenLu<N>, Angles>>(options);
  throw std::invalid_argument("unknown linear method '" + linear + "' for full Newton (expected gepp, gauss-seidel, "
                              "gsl-lu or eigen-lu)");
}

}  // namespace numlab::mechanisms
