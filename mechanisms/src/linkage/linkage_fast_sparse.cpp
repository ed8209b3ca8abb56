#include "linkage_fast_sparse.hpp"

#include <cmath>

#include "linkage_fast_kernels.hpp"
#include "numlab/mechanisms/linkage/linkage_conditioning.hpp"

namespace numlab::mechanisms {

bool LinkageFastSolver::Sparse::assemble(const LinkageModel& model, double t, const Eigen::VectorXd& x) {
  entries.clear();
  bool finite = true;
  for (std::size_t k = 0; k < model.constraints().size(); ++k) {
    const Constraint& c = model.constraints()[k];
    const int first_row = model.first_row(static_cast<int>(k));
    for (const int joint : c.joints) {
      if (joint < 0 || model.column_of(joint) < 0) continue;  // unused slot, or a ground joint
      const Eigen::Matrix2d d = detail::partial_of(model, c, x, t, joint);
      for (int r = 0; r < c.rows(); ++r) {
        for (int xy = 0; xy < 2; ++xy) {
          finite = finite && std::isfinite(d(r, xy));
          entries.emplace_back(first_row + r, model.column_of(joint) + xy, d(r, xy));
        }
      }
    }
  }
  factored = false;
  if (!finite) return false;
  J.resize(model.equation_count(), model.unknown_count());
  J.setFromTriplets(entries.begin(), entries.end());  // explicit zeros kept: the pattern never changes
  if (!analysed) {
    lu.analyzePattern(J);
    analysed = true;
  }
  lu.factorize(J);
  factored = lu.info() == Eigen::Success;
  return true;
}

Status LinkageFastSolver::Sparse::solve(const Eigen::VectorXd& f, Eigen::VectorXd& dx) {
  if (!factored) return Status::singular;
  dx = lu.solve(Eigen::VectorXd(-f));
  return lu.info() == Eigen::Success && dx.allFinite() ? Status::converged : Status::singular;
}

void LinkageFastSolver::Sparse::read_rows(const LinkageModel& model, double t, const Eigen::VectorXd& q) {
  rows = linkage_sparse_jacobian(model, t, q);  // LinkageModel::jacobian's entries, by rows
}

double LinkageFastSolver::Sparse::row_dot(int row, const Eigen::VectorXd& v) const {
  double sum = 0.0;
  for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(rows, row); it; ++it) sum += it.value() * v(it.col());
  return sum;
}

namespace detail {

void SparseWholeProblem::residual(const Eigen::VectorXd& x, Eigen::VectorXd& f) const {
  whole_residual(model, x, t, crank_direction, f);
}

}  // namespace detail

}  // namespace numlab::mechanisms
