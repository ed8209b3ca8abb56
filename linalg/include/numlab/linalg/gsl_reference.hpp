#pragma once
// GSL's LU and QR solvers, the references every hand-written linear method is checked against.
// This header and gsl_reference.cpp are the only place GSL's linear algebra is touched:
// callers see Eigen types only.

#include <Eigen/Core>
#include <memory>

#include "numlab/linalg/linear_result.hpp"

namespace numlab::linalg {

// gsl_linalg_LU_decomp + gsl_linalg_LU_solve. The workspace is allocated once, in the constructor,
// so repeated solves of the same size (benchmarks) allocate nothing.
// Status::singular when U has an exact zero on its diagonal (GSL's own test).
class GslLu {
 public:
  explicit GslLu(int n);
  ~GslLu();
  GslLu(const GslLu&) = delete;
  GslLu& operator=(const GslLu&) = delete;
  LinearResult<Eigen::Dynamic> solve(const Eigen::MatrixXd& A, const Eigen::VectorXd& b);

 private:
  struct Workspace;
  std::unique_ptr<Workspace> workspace_;
};

// gsl_linalg_QR_decomp + gsl_linalg_QR_solve (Householder). Status::singular when R has an exact
// zero on its diagonal.
class GslQr {
 public:
  explicit GslQr(int n);
  ~GslQr();
  GslQr(const GslQr&) = delete;
  GslQr& operator=(const GslQr&) = delete;
  LinearResult<Eigen::Dynamic> solve(const Eigen::MatrixXd& A, const Eigen::VectorXd& b);

 private:
  struct Workspace;
  std::unique_ptr<Workspace> workspace_;
};

// One-off solves (allocate a workspace each call).
LinearResult<Eigen::Dynamic> gsl_lu_solve(const Eigen::MatrixXd& A, const Eigen::VectorXd& b);
LinearResult<Eigen::Dynamic> gsl_qr_solve(const Eigen::MatrixXd& A, const Eigen::VectorXd& b);

}  // namespace numlab::linalg
