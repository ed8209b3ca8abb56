#include "methods/linear_methods.hpp"

#include <stdexcept>

#include "numlab/linalg/eigen_reference.hpp"
#include "numlab/linalg/gsl_reference.hpp"
#include "numlab/linalg/inverse2x2.hpp"
#include "numlab/nonlinear/linear_step.hpp"

namespace numlab::cli {

namespace {

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

DynamicResult run_closed_form(const Eigen::MatrixXd& A, const Eigen::VectorXd& b,
                              linalg::ClosedForm2x2::Observer* observer) {
  if (A.rows() != 2 || A.cols() != 2 || b.size() != 2) {
    throw std::invalid_argument("inverse2x2 needs a 2x2 system, got " + std::to_string(A.rows()) + "x" +
                                std::to_string(A.cols()));
  }
  // Traced: the stepper, whose one step is solve2x2's closed form, with its observer.
  linalg::ClosedForm2x2 stepper;
  stepper.set_observer(observer);
  const linalg::LinearResult<2> fixed =
      observer == nullptr ? linalg::solve2x2(A, b) : stepper.solve(Eigen::Matrix2d(A), Eigen::Vector2d(b));
  DynamicResult result;
  result.x = fixed.x;
  result.status = fixed.status;
  result.iterations = fixed.iterations;
  result.residual_norm = fixed.residual_norm;
  return result;
}

}  // namespace

namespace {

// One row per method: its name, what it is, and how it runs. The five Newton can use inside its
// iteration take their names from the nonlinear library (nonlinear::to_string), so the two lists
// cannot drift apart.
struct LinearMethodEntry {
  std::string name;
  std::string description;
  DynamicResult (*run)(const Eigen::MatrixXd& A, const Eigen::VectorXd& b, const LinearSettings& settings,
                       LinearTracers tracers);
};

std::string newton_name(nonlinear::LinearMethod method) { return std::string(nonlinear::to_string(method)); }

const std::vector<LinearMethodEntry>& linear_methods() {
  using nonlinear::LinearMethod;
  using System = linalg::GaussSeidelOptions::System;
  static const std::vector<LinearMethodEntry> table = {
      {newton_name(LinearMethod::gepp), "Gaussian elimination with partial pivoting (hand-written)",
       [](const Eigen::MatrixXd& A, const Eigen::VectorXd& b, const LinearSettings& s, LinearTracers t) {
         return run_gauss_elimination(A, b, linalg::Pivoting::partial, s, t);
       }},
      {"gepp-no-pivot", "Gaussian elimination without pivoting (hand-written, to show why pivoting matters)",
       [](const Eigen::MatrixXd& A, const Eigen::VectorXd& b, const LinearSettings& s, LinearTracers t) {
         return run_gauss_elimination(A, b, linalg::Pivoting::none, s, t);
       }},
      {newton_name(LinearMethod::gauss_seidel), "Gauss-Seidel on the normal equations A^T A x = A^T b (hand-written)",
       [](const Eigen::MatrixXd& A, const Eigen::VectorXd& b, const LinearSettings& s, LinearTracers t) {
         return run_gauss_seidel(A, b, System::normal_equations, s, t);
       }},
      {"gauss-seidel-plain", "Gauss-Seidel on A x = b directly (hand-written, for comparison)",
       [](const Eigen::MatrixXd& A, const Eigen::VectorXd& b, const LinearSettings& s, LinearTracers t) {
         return run_gauss_seidel(A, b, System::plain, s, t);
       }},
      {newton_name(LinearMethod::inverse2x2), "2x2 closed-form inverse (hand-written; n = 2 only)",
       [](const Eigen::MatrixXd& A, const Eigen::VectorXd& b, const LinearSettings&, LinearTracers t) {
         return run_closed_form(A, b, t.closed_form);
       }},
      {newton_name(LinearMethod::gsl_lu), "GSL LU with partial pivoting (gsl_linalg_LU_decomp / LU_solve)",
       [](const Eigen::MatrixXd& A, const Eigen::VectorXd& b, const LinearSettings&, LinearTracers) {
         return linalg::gsl_lu_solve(A, b);
       }},
      {"gsl-qr", "GSL Householder QR (gsl_linalg_QR_decomp / QR_solve)",
       [](const Eigen::MatrixXd& A, const Eigen::VectorXd& b, const LinearSettings&, LinearTracers) {
         return linalg::gsl_qr_solve(A, b);
       }},
      {newton_name(LinearMethod::eigen_lu), "Eigen PartialPivLU",
       [](const Eigen::MatrixXd& A, const Eigen::VectorXd& b, const LinearSettings&, LinearTracers) {
         return linalg::EigenLu<Eigen::Dynamic>().solve(A, b);
       }},
  };
  return table;
}

const LinearMethodEntry* method_named(const std::string& name) {
  for (const LinearMethodEntry& entry : linear_methods()) {
    if (entry.name == name) return &entry;
  }
  return nullptr;
}

}  // namespace

const std::vector<std::string>& linear_method_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> all;
    for (const LinearMethodEntry& entry : linear_methods()) all.push_back(entry.name);
    return all;
  }();
  return names;
}

std::string describe_linear_method(const std::string& method) {
  const LinearMethodEntry* entry = method_named(method);
  return entry == nullptr ? method : entry->description;
}

DynamicResult run_linear_method(const std::string& method, const Eigen::MatrixXd& A, const Eigen::VectorXd& b,
                                const LinearSettings& settings, LinearTracers tracers) {
  const LinearMethodEntry* entry = method_named(method);
  if (entry == nullptr) throw std::invalid_argument("unknown linear method '" + method + "'");
  return entry->run(A, b, settings, tracers);
}

}  // namespace numlab::cli
