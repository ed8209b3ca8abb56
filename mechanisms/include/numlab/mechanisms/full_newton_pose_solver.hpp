#pragma once
// The `full` pose solver of both linkages: Newton on the whole closure, with the linear step
// chosen by name (--linear: gepp, gauss-seidel, gsl-lu, eigen-lu) and fixed at compile time.

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
    // Each inner solve sweeps the normal equations until ||J dx + f|| <= eta_k ||f||, eta_k being
    // Newton's forcing term (options.forcing, nonlinear/forcing_term.hpp).
    return std::make_unique<FullNewtonPoseSolver<Closure, linalg::GaussSeidel<N>, Angles>>(
        options, linalg::GaussSeidel<N>(nonlinear::inner_gauss_seidel_options(options.forcing)));
  }
  if (linear == "gsl-lu") return std::make_unique<FullNewtonPoseSolver<Closure, nonlinear::GslLuStep<N>, Angles>>(options);
  if (linear == "eigen-lu") return std::make_unique<FullNewtonPoseSolver<Closure, linalg::EigenLu<N>, Angles>>(options);
  throw std::invalid_argument("unknown linear method '" + linear + "' for full Newton (expected gepp, gauss-seidel, "
                              "gsl-lu or eigen-lu)");
}

}  // namespace numlab::mechanisms
