#pragma once
// The `gsl-<type>` pose solver of both linkages: one of GSL's multiroot solvers on the whole
// closure. Its workspace is allocated once and reused for every pose, as full Newton's is.

#include <Eigen/Core>
#include <string>

#include "numlab/mechanisms/pose_solver.hpp"
#include "numlab/nonlinear/dynamic_adapter.hpp"
#include "numlab/nonlinear/gsl_multiroot.hpp"

namespace numlab::mechanisms {

template <typename Closure, typename Angles>
class GslPoseSolver final : public PoseSolver<Angles> {
 public:
  // Throws std::invalid_argument for a type that is not one of gsl_multiroot_types().
  GslPoseSolver(const std::string& type, const nonlinear::NewtonOptions& options)
      : options_(options), closure_(0.0), dynamic_(closure_), gsl_(dynamic_, type, options) {}

  PoseOutcome solve(double input_angle, Angles& x) override {
    closure_.set_crank_angle(input_angle);
    const auto result = gsl_.solve(x);
    if (result.x.allFinite()) x = result.x;  // a failed solve may end at no point at all
    return {result.status, result.iterations, result.residual_norm};
  }

 private:
  nonlinear::NewtonOptions options_;
  Closure closure_;
  nonlinear::AsDynamicSystem<Closure> dynamic_;
  nonlinear::GslMultiroot gsl_;
};

}  // namespace numlab::mechanisms
