#include "methods/linear_methods.hpp"

#include <map>
#include <stdexcept>

#include "numlab/linalg/eigen_reference.hpp"
#include "numlab/linalg/gsl_reference.hpp"
#include "numlab/linalg/inverse2x2.hpp"

namespace numlab::cli {

namespace {

const std::map<std::string, std::string>& descriptions() {
  static const std::map<std::string, std::string> table = {
      {"gepp", "Gaussian elimination with partial pivoting (hand-written)"},
      {"gepp-no-pivot", "Gaussian elimination without pivoting (hand-written, to show why pivoting matters)"},
      {"gauss-seidel", "Gauss-Seidel on the normal equations A^T A x = A^T b (hand-written)"},
      {"gauss-seidel-plain", "Gauss-Seidel on A x = b directly (hand-written, for comparison)"},
      {"inverse2x2", "2x2 closed-form inverse (hand-written; n = 2 only)"},
      {"gsl-lu", "GSL LU with partial pivoting (gsl_linalg_LU_decomp / LU_solve)"},
      {"gsl-qr", "GSL Householder QR (gsl_linalg_QR_decomp / QR_solve)"},
      {"eigen-lu", "Eigen PartialPivLU"},
  };
  return table;
}

DynamicResult run_gauss_elimination(const Eigen::MatrixXd& A, const Eigen::VectorXd& b, linalg::Pivoting pivoting,
                                    const LinearSettings& settings, LinearTracers tracers) {
  linalg::GaussEliminationOptions options;
  options.pivoting = pivoting;
  options.relative_pivot_tolerance = settings.tolerance;
  linalg::GaussElimination<Eigen::Dynamic> elimination(options);
  if (tracers.elimination == nullptr) return elimination.solve(A, b);  // untraced: the fast path
  // Traced (--trace, --step): the program owns the loop, as GSL's own test program loops on iterate.
  elimination.set_observer(tracers.elimination);
  elimination.start(A, b);
  while (elimination.step()) {
  }
  return elimination.result();
}

DynamicResult run_gauss_seidel(const Eigen::MatrixXd& A, const Eigen::VectorXd& b,
                               linalg::GaussSeidelOptions::System system, const LinearSettings& settings,
                               LinearTracers tracers) {
  linalg::GaussSeidelOptions options;
  options.system = system;
  if (settings.tolerance) options.tolerance = *settings.tolerance;
  if (settings.max_iterations) options.max_iterations = *settings.max_iterations;
  linalg::GaussSeidel<Eigen::Dynamic> iteration(options);
  iteration.set_observer(tracers.sweeps);
  iteration.start(A, b);
  while (iteration.step()) {  // one sweep
  }
  return iteration.result();
}

DynamicResult run_closed_form(const Eigen::MatrixXd& A, const Eigen::VectorXd& b) {
  if (A.rows() != 2 || A.cols() != 2 || b.size() != 2) {
    throw std::invalid_argument("inverse2x2 needs a 2x2 system, got " + std::to_string(A.rows()) + "x" +
                                std::to_string(A.cols()));
  }
  const linalg::LinearResult<2> fixed = linalg::solve2x2(A, b);
  DynamicResult result;
  result.x = fixed.x;
  result.status = fixed.status;
  result.iterations = fixed.iterations;
  result.residual_norm = fixed.residual_norm;
  return result;
}

}  // namespace

const std::vector<std::string>& linear_method_names() {
  static const std::vector<std::string> names = {"gepp",       "gepp-no-pivot", "gauss-seidel", "gauss-seidel-plain",
                                                 "inverse2x2", "gsl-lu",        "gsl-qr",       "eigen-lu"};
  return names;
}

std::string describe_linear_method(const std::string& method) {
  const auto found = descriptions().find(method);
  return found == descriptions().end() ? method : found->second;
}

DynamicResult run_linear_method(const std::string& method, const Eigen::MatrixXd& A, const Eigen::VectorXd& b,
                                const LinearSettings& settings, LinearTracers tracers) {
  using System = linalg::GaussSeidelOptions::System;
  if (method == "gepp") return run_gauss_elimination(A, b, linalg::Pivoting::partial, settings, tracers);
  if (method == "gepp-no-pivot") return run_gauss_elimination(A, b, linalg::Pivoting::none, settings, tracers);
  if (method == "gauss-seidel") return run_gauss_seidel(A, b, System::normal_equations, settings, tracers);
  if (method == "gauss-seidel-plain") return run_gauss_seidel(A, b, System::plain, settings, tracers);
  if (method == "inverse2x2") return run_closed_form(A, b);
  if (method == "gsl-lu") return linalg::gsl_lu_solve(A, b);
  if (method == "gsl-qr") return linalg::gsl_qr_solve(A, b);
  if (method == "eigen-lu") return linalg::EigenLu<Eigen::Dynamic>().solve(A, b);
  throw std::invalid_argument("unknown linear method '" + method + "'");
}

}  // namespace numlab::cli
