#pragma once
// The inner linear solve of Newton's method, J dx = -f, by any numlab linear method.
//
// A LinearStep<N> policy has
//   linalg::LinearResult<N> solve(const Matrix<N>& J, const Vector<N>& rhs);
// GEPP, Gauss-Seidel (normal equations), Eigen LU and, for N = 2, the closed form already have it.
// GSL LU needs a dynamic matrix, so fixed sizes go through GslLuStep's copy.
// RuntimeLinearStep picks one of them at run time (a LinearMethod, or its command-line name).

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "numlab/linalg/eigen_reference.hpp"
#include "numlab/linalg/gauss_elimination.hpp"
#include "numlab/linalg/gauss_seidel.hpp"
#include "numlab/linalg/gsl_reference.hpp"
#include "numlab/linalg/inverse2x2.hpp"
#include "numlab/nonlinear/forcing_term.hpp"
#include "numlab/nonlinear/system.hpp"

namespace numlab::nonlinear {

// GSL LU for any N (a fixed-size J is copied into GSL's dynamic workspace).
template <int N>
class GslLuStep {
 public:
  linalg::LinearResult<N> solve(const Matrix<N>& J, const Vector<N>& rhs) {
    if (!lu_ || size_ != J.rows()) {
      size_ = static_cast<int>(J.rows());
      lu_ = std::make_unique<linalg::GslLu>(size_);
    }
    const linalg::LinearResult<Eigen::Dynamic> dynamic = lu_->solve(J, rhs);
    linalg::LinearResult<N> result;
    result.x = dynamic.x;
    result.status = dynamic.status;
    result.iterations = dynamic.iterations;
    result.residual_norm = dynamic.residual_norm;
    return result;
  }

 private:
  int size_ = 0;
  std::unique_ptr<linalg::GslLu> lu_;
};

// Gauss-Seidel's options as Newton's inner solver. With a forcing term each solve sweeps until
// ||J dx + f|| <= eta_k ||f||, and the sweep limit (inner_sweep_limit) is only a guard: the normal
// equations of an ill-conditioned J need many sweeps (their rate is set by kappa(J)^2). Without one
// (Kind::none): seed 001's defaults, an update of 1e-9 and 100 sweeps, the old fixed inner stop.
inline constexpr int inner_sweep_limit = 100000;
inline linalg::GaussSeidelOptions inner_gauss_seidel_options(const ForcingOptions& forcing) {
  linalg::GaussSeidelOptions options;
  if (forcing.kind != ForcingOptions::Kind::none) options.max_iterations = inner_sweep_limit;
  return options;
}

// The linear methods Newton can use at run time (inverse2x2: the closed form, for n = 2 only).
enum class LinearMethod { gepp, gauss_seidel, gsl_lu, eigen_lu, inverse2x2 };

// Their command-line names, in LinearMethod's order: gepp, gauss-seidel, gsl-lu, eigen-lu, inverse2x2.
const std::vector<std::string>& newton_linear_methods();
// The method of a command-line name. Throws std::invalid_argument for an unknown name.
LinearMethod linear_method_named(const std::string& name);
std::string_view to_string(LinearMethod method);

// One of the linear methods, chosen at run time (dynamic sizes only).
class RuntimeLinearStep {
 public:
  // Throws std::invalid_argument for inverse2x2 when n != 2. Gauss-Seidel's options default to
  // those for Newton's default forcing term (inner_gauss_seidel_options).
  RuntimeLinearStep(LinearMethod method, int n,
                    linalg::GaussSeidelOptions gauss_seidel = inner_gauss_seidel_options(ForcingOptions{}));
  // By command-line name; also throws std::invalid_argument for an unknown name.
  RuntimeLinearStep(const std::string& method, int n,
                    linalg::GaussSeidelOptions gauss_seidel = inner_gauss_seidel_options(ForcingOptions{}));
  linalg::LinearResult<Eigen::Dynamic> solve(const Eigen::MatrixXd& J, const Eigen::VectorXd& rhs);
  LinearMethod method() const { return method_; }
  // Gauss-Seidel is iterative and takes Newton's forcing term as its relative residual target;
  // the direct methods solve exactly and ignore it.
  bool iterative() const { return method_ == LinearMethod::gauss_seidel; }
  void set_relative_residual_tolerance(double eta) { gauss_seidel_.set_relative_residual_tolerance(eta); }
  // GEPP keeps the factors of its last J: the chord method (NewtonOptions::reuse_jacobian) solves
  // another right-hand side with them. The other methods keep none.
  bool keeps_factors() const { return method_ == LinearMethod::gepp; }
  linalg::LinearResult<Eigen::Dynamic> solve_with_factors(const Eigen::VectorXd& rhs) const;

 private:
  LinearMethod method_;
  linalg::GaussElimination<Eigen::Dynamic> gepp_;
  linalg::GaussSeidel<Eigen::Dynamic> gauss_seidel_;
  linalg::EigenLu<Eigen::Dynamic> eigen_lu_;
  GslLuStep<Eigen::Dynamic> gsl_lu_;
};

}  // namespace numlab::nonlinear
