#include "numlab/linalg/gsl_reference.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_linalg.h>
#include <gsl/gsl_matrix.h>
#include <gsl/gsl_permutation.h>
#include <gsl/gsl_vector.h>

#include <limits>
#include <memory>
#include <stdexcept>
#include <string>

#include "numlab/linalg/input_checks.hpp"

namespace numlab::linalg {

namespace {

// GSL's default error handler aborts the program (e.g. on a singular matrix). numlab reports
// such outcomes as statuses, so the handler is switched off before any GSL call.
void disable_gsl_abort() {
  static const bool disabled = [] {
    gsl_set_error_handler_off();
    return true;
  }();
  (void)disabled;
}

void require_size(const Eigen::MatrixXd& A, std::size_t n, const char* solver) {
  if (static_cast<std::size_t>(A.rows()) != n) {
    throw std::invalid_argument(std::string(solver) + " workspace is " + std::to_string(n) + "x" + std::to_string(n) +
                                " but the matrix is " + std::to_string(A.rows()) + "x" + std::to_string(A.cols()));
  }
}

// GSL stores matrices row by row with a row stride (tda); map that storage so the copy is one
// Eigen assignment rather than n^2 function calls (keeps the benchmark fair to GSL).
using GslMatrixMap = Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>, 0, Eigen::OuterStride<>>;
using GslVectorMap = Eigen::Map<Eigen::VectorXd, 0, Eigen::InnerStride<>>;

void copy_into(const Eigen::MatrixXd& A, gsl_matrix* target) {
  GslMatrixMap(target->data, target->size1, target->size2, Eigen::OuterStride<>(target->tda)) = A;
}

void copy_into(const Eigen::VectorXd& v, gsl_vector* target) {
  GslVectorMap(target->data, target->size, Eigen::InnerStride<>(target->stride)) = v;
}

bool has_zero_diagonal(const gsl_matrix* factor) {
  for (std::size_t i = 0; i < factor->size1; ++i) {
    if (gsl_matrix_get(factor, i, i) == 0.0) return true;
  }
  return false;
}

// Fills the result from GSL's solution vector: singular, non-finite, or converged with its residual.
LinearResult<Eigen::Dynamic> finish(const Eigen::MatrixXd& A, const Eigen::VectorXd& b, const gsl_vector* solution,
                                    bool singular) {
  LinearResult<Eigen::Dynamic> result;
  result.iterations = 1;
  result.x.resize(A.rows());
  if (singular) {
    result.status = Status::singular;
    result.x.setConstant(std::numeric_limits<double>::quiet_NaN());
    return result;
  }
  result.x = Eigen::Map<const Eigen::VectorXd, 0, Eigen::InnerStride<>>(solution->data, solution->size, Eigen::InnerStride<>(solution->stride));
  result.status = result.x.allFinite() ? Status::converged : Status::non_finite;
  if (result.status == Status::converged) result.residual_norm = residual_inf_norm(A, b, result.x);
  return result;
}

// GSL objects freed by their own gsl_*_free when the owner goes.
struct GslFree {
  void operator()(gsl_matrix* matrix) const { gsl_matrix_free(matrix); }
  void operator()(gsl_vector* vector) const { gsl_vector_free(vector); }
  void operator()(gsl_permutation* permutation) const { gsl_permutation_free(permutation); }
};
template <typename GslType>
using GslOwned = std::unique_ptr<GslType, GslFree>;

// What LU and QR share: the matrix to factorize in place, the right-hand side and the solution.
struct GslSystem {
  explicit GslSystem(int n) : factors(gsl_matrix_alloc(n, n)), rhs(gsl_vector_alloc(n)), solution(gsl_vector_alloc(n)) {
    disable_gsl_abort();
  }

  // Checks A x = b and copies it in.
  void load(const Eigen::MatrixXd& A, const Eigen::VectorXd& b, const char* solver) {
    require_valid_system(A, b);
    require_size(A, factors->size1, solver);
    copy_into(A, factors.get());
    copy_into(b, rhs.get());
  }

  GslOwned<gsl_matrix> factors;
  GslOwned<gsl_vector> rhs;
  GslOwned<gsl_vector> solution;
};

}  // namespace

struct GslLu::Workspace {
  explicit Workspace(int n) : system(n), permutation(gsl_permutation_alloc(n)) {}
  GslSystem system;
  GslOwned<gsl_permutation> permutation;
};

GslLu::GslLu(int n) : workspace_(std::make_unique<Workspace>(n)) {}
GslLu::~GslLu() = default;

LinearResult<Eigen::Dynamic> GslLu::solve(const Eigen::MatrixXd& A, const Eigen::VectorXd& b) {
  GslSystem& system = workspace_->system;
  system.load(A, b, "GSL LU");
  int sign = 0;
  gsl_linalg_LU_decomp(system.factors.get(), workspace_->permutation.get(), &sign);
  const bool singular = has_zero_diagonal(system.factors.get());
  if (!singular) {
    gsl_linalg_LU_solve(system.factors.get(), workspace_->permutation.get(), system.rhs.get(), system.solution.get());
  }
  return finish(A, b, system.solution.get(), singular);
}

struct GslQr::Workspace {
  explicit Workspace(int n) : system(n), tau(gsl_vector_alloc(n)) {}
  GslSystem system;
  GslOwned<gsl_vector> tau;
};

GslQr::GslQr(int n) : workspace_(std::make_unique<Workspace>(n)) {}
GslQr::~GslQr() = default;

LinearResult<Eigen::Dynamic> GslQr::solve(const Eigen::MatrixXd& A, const Eigen::VectorXd& b) {
  GslSystem& system = workspace_->system;
  system.load(A, b, "GSL QR");
  gsl_linalg_QR_decomp(system.factors.get(), workspace_->tau.get());
  const bool singular = has_zero_diagonal(system.factors.get());
  if (!singular) gsl_linalg_QR_solve(system.factors.get(), workspace_->tau.get(), system.rhs.get(), system.solution.get());
  return finish(A, b, system.solution.get(), singular);
}

LinearResult<Eigen::Dynamic> gsl_lu_solve(const Eigen::MatrixXd& A, const Eigen::VectorXd& b) {
  require_square(A, "matrix");
  return GslLu(static_cast<int>(A.rows())).solve(A, b);
}

LinearResult<Eigen::Dynamic> gsl_qr_solve(const Eigen::MatrixXd& A, const Eigen::VectorXd& b) {
  require_square(A, "matrix");
  return GslQr(static_cast<int>(A.rows())).solve(A, b);
}

}  // namespace numlab::linalg
