#pragma once
// The fast path beyond linkage_exact_conditioning_limit unknowns (linkage_conditioning.hpp): full
// Newton's J is assembled sparse from the constraints, in time linear in them, and factored by
// Eigen's sparse LU, whose pattern (fixed by the model) is analysed once; the velocity reads J's
// rows sparse. A dense n x n work matrix costs O(n^2) to clear and scan at every iteration: at
// 2000 unknowns, more than all the rest of a pose. The Newton steps are the dense path's to
// rounding; J is singular where the sparse LU finds no pivot.

#include <Eigen/SparseCore>
#include <Eigen/SparseLU>
#include <vector>

#include "numlab/mechanisms/linkage/linkage_fast_solver.hpp"
#include "numlab/status.hpp"

namespace numlab::mechanisms {

struct LinkageFastSolver::Sparse {
  std::vector<Eigen::Triplet<double>> entries;
  Eigen::SparseMatrix<double> J;
  Eigen::SparseLU<Eigen::SparseMatrix<double>> lu;
  bool analysed = false;
  bool factored = false;
  // J at x (each constraint's partial derivatives, partial_of) and its LU. False when an entry of
  // J is not finite.
  bool assemble(const LinkageModel& model, double t, const Eigen::VectorXd& x);
  // J dx = -f by the LU; Status::singular when the LU found no pivot, or gave a step not finite.
  Status solve(const Eigen::VectorXd& f, Eigen::VectorXd& dx);

  // The velocity's J (LinkageModel::jacobian's, by rows) at (q, t), and what it reads of it.
  Eigen::SparseMatrix<double, Eigen::RowMajor> rows;
  void read_rows(const LinkageModel& model, double t, const Eigen::VectorXd& q);
  double row_dot(int row, const Eigen::VectorXd& v) const;
};

namespace detail {

// Full Newton's problem on the sparse J, for newton_in_place (as the dense WholeProblem).
struct SparseWholeProblem {
  const LinkageModel& model;
  double t;
  Eigen::Vector2d crank_direction;
  LinkageFastSolver::Sparse& sparse;
  void residual(const Eigen::VectorXd& x, Eigen::VectorXd& f) const;
  bool jacobian(const Eigen::VectorXd& x) const { return sparse.assemble(model, t, x); }
  Status solve(const Eigen::VectorXd& f, Eigen::VectorXd& dx) const { return sparse.solve(f, dx); }
};

}  // namespace detail

}  // namespace numlab::mechanisms
