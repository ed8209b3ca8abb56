#include "numlab/mechanisms/linkage/linkage_conditioning.hpp"

#include <Eigen/SVD>
#include <Eigen/SparseCore>
#include <Eigen/SparseLU>
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace numlab::mechanisms {

Eigen::SparseMatrix<double> linkage_sparse_jacobian(const Eigen::MatrixXd& J) {
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(static_cast<std::size_t>(8 * J.rows()));
  for (Eigen::Index c = 0; c < J.cols(); ++c) {
    for (Eigen::Index r = 0; r < J.rows(); ++r) {
      if (J(r, c) != 0.0) entries.emplace_back(static_cast<int>(r), static_cast<int>(c), J(r, c));
    }
  }
  Eigen::SparseMatrix<double> sparse(J.rows(), J.cols());
  sparse.setFromTriplets(entries.begin(), entries.end());
  return sparse;
}

Eigen::SparseMatrix<double> linkage_sparse_jacobian(const LinkageModel& model, double t, const Eigen::VectorXd& q) {
  std::vector<LinkageModel::JacobianEntry> entries;
  model.jacobian_entries(q, t, entries);
  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(entries.size());
  for (const auto& e : entries) triplets.emplace_back(e.row, e.column, e.value);
  Eigen::SparseMatrix<double> sparse(model.equation_count(), model.unknown_count());
  sparse.setFromTriplets(triplets.begin(), triplets.end());
  return sparse;
}

namespace {

constexpr double infinity = std::numeric_limits<double>::infinity();

}  // namespace

// kappa_2(J) = sigma_max / sigma_min and ||J^-1||_2 = 1 / sigma_min, from all of J's singular values.
LinkageConditioning exact_linkage_conditioning(const Eigen::MatrixXd& J) {
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(J);
  const auto& s = svd.singularValues();
  if (s.size() == 0) return {1.0, 0.0};
  const double smallest = s(s.size() - 1);
  if (smallest == 0.0) return {infinity, infinity};
  return {s(0) / smallest, 1.0 / smallest};
}

namespace {

// Hager's estimate of ||A^-1||_1 (Hager 1984, as refined by Higham 1988 for LAPACK's xLACON; Higham,
// Accuracy and Stability of Numerical Algorithms, 2nd ed., Algorithm 15.4), where solve(x) gives
// A^-1 x and solve_transposed(x) gives A^-T x. It maximises ||A^-1 x||_1 over ||x||_1 = 1, a
// convex function, by a gradient ascent over the vertices e_j of the unit ball:
//   x = (1/n, ..., 1/n)
//   repeat at most 5 times:
//     y = A^-1 x,  xi = sign(y),  z = A^-T xi
//     if ||z||_inf <= z' x: stop (a local maximum: the estimate is ||y||_1)
//     x = e_j, j the index of the largest |z_j|
//   and, against matrices that fool the ascent, also 2 ||A^-1 b||_1 / (3n) for
//   b_i = (-1)^(i+1) (1 + (i-1)/(n-1)); the larger of the two.
// A lower bound on ||A^-1||_1, almost always within a factor 3 of it (usually equal).
template <typename Solve, typename SolveTransposed>
double inverse_one_norm_estimate(Eigen::Index n, Solve solve, SolveTransposed solve_transposed) {
  Eigen::VectorXd x = Eigen::VectorXd::Constant(n, 1.0 / static_cast<double>(n));
  double estimate = 0.0;
  Eigen::Index last_j = -1;
  for (int k = 0; k < 5; ++k) {
    const Eigen::VectorXd y = solve(x);
    const double norm = y.lpNorm<1>();
    if (k > 0 && norm <= estimate) break;  // no increase: the ascent has stalled
    estimate = norm;
    const Eigen::VectorXd xi = y.unaryExpr([](double v) { return v >= 0.0 ? 1.0 : -1.0; });
    const Eigen::VectorXd z = solve_transposed(xi);
    Eigen::Index j = 0;
    const double largest = z.cwiseAbs().maxCoeff(&j);
    if (largest <= z.dot(x) || j == last_j) break;
    x.setZero();
    x(j) = 1.0;
    last_j = j;
  }
  Eigen::VectorXd b(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const double magnitude = 1.0 + (n > 1 ? static_cast<double>(i) / static_cast<double>(n - 1) : 0.0);
    b(i) = i % 2 == 0 ? magnitude : -magnitude;
  }
  return std::max(estimate, 2.0 * Eigen::VectorXd(solve(b)).lpNorm<1>() / (3.0 * static_cast<double>(n)));
}

}  // namespace

// The sparse LU of J (a linkage's J has a few nonzeros per row), Hager's estimates of ||J^-1||_1
// and of ||J^-1||_inf = ||J^-T||_1 from it, a handful of sparse solves each: time about linear in
// the number of joints.
LinkageConditioning estimated_linkage_conditioning(const Eigen::MatrixXd& dense) {
  return estimated_linkage_conditioning(linkage_sparse_jacobian(dense));
}

LinkageConditioning estimated_linkage_conditioning(const Eigen::SparseMatrix<double>& J) {
  Eigen::SparseLU<Eigen::SparseMatrix<double>> lu;
  lu.compute(J);
  if (lu.info() != Eigen::Success) return {infinity, infinity};  // singular to working precision
  const auto solve = [&](const Eigen::VectorXd& v) -> Eigen::VectorXd { return lu.solve(v); };
  const auto solve_transposed = [&](const Eigen::VectorXd& v) -> Eigen::VectorXd { return lu.transpose().solve(v); };
  const double inverse_one = inverse_one_norm_estimate(J.rows(), solve, solve_transposed);
  const double inverse_inf = inverse_one_norm_estimate(J.rows(), solve_transposed, solve);
  if (!std::isfinite(inverse_one) || !std::isfinite(inverse_inf)) return {infinity, infinity};
  // ||J||_1: the largest column sum.
  double one_norm = 0.0;
  for (Eigen::Index c = 0; c < J.outerSize(); ++c) {
    double sum = 0.0;
    for (Eigen::SparseMatrix<double>::InnerIterator it(J, c); it; ++it) sum += std::abs(it.value());
    one_norm = std::max(one_norm, sum);
  }
  // ||J^-1||_2 <= sqrt(||J^-1||_1 ||J^-1||_inf): the 2-norm bound the sweep's closed-form check reads.
  return {one_norm * inverse_one, std::sqrt(inverse_one * inverse_inf)};
}

bool sparse_linkage_kinematics(const LinkageModel& model, double t, const Eigen::VectorXd& q, Eigen::VectorXd& velocity,
                               Eigen::VectorXd& acceleration) {
  Eigen::VectorXd phi_t, gamma;
  model.driver_derivative(q, t, phi_t);
  const Eigen::SparseMatrix<double> J = linkage_sparse_jacobian(model, t, q);
  Eigen::SparseLU<Eigen::SparseMatrix<double>> lu;
  lu.compute(J);
  if (lu.info() != Eigen::Success) {
    velocity.setConstant(q.size(), std::numeric_limits<double>::quiet_NaN());
    acceleration = velocity;
    return false;
  }
  velocity = lu.solve(Eigen::VectorXd(-phi_t));      // 1. J qdot = -Phi_t
  model.acceleration_rhs(q, velocity, t, gamma);
  acceleration = lu.solve(gamma);                     // 2. J qddot = gamma
  return true;
}

LinkageConditioning linkage_conditioning(const LinkageModel& model, double t, const Eigen::VectorXd& q) {
  if (q.size() > linkage_exact_conditioning_limit) return estimated_linkage_conditioning(linkage_sparse_jacobian(model, t, q));
  Eigen::MatrixXd J;
  model.jacobian(q, t, J);
  return exact_linkage_conditioning(J);
}

}  // namespace numlab::mechanisms
