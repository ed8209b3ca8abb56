#pragma once
// How linkage_conditioning (linkage_sweep.hpp) measures J at a pose, its two ways, public for tests:
//
//   up to linkage_exact_conditioning_limit = 100 unknowns (every shipped model: at most 26): kappa_2(J) =
//     sigma_max / sigma_min and ||J^-1||_2 = 1 / sigma_min from a dense SVD, O(n^3);
//   beyond (a description of up to 1000 joints has ~2000 unknowns, where the SVD takes minutes):
//     estimates from the sparse LU of J (a few nonzeros per row): Hager's estimator (LAPACK's
//     xLACON, Higham's Algorithm 15.4) of ||J^-1||_1 and of ||J^-1||_inf = ||J^-T||_1, a few
//     sparse solves each, so about linear in the number of joints. condition is then
//     kappa_1(J) = ||J||_1 ||J^-1||_1 (its estimate: a lower bound, almost always within a factor
//     3, usually exact), and inverse_norm is sqrt(||J^-1||_1 ||J^-1||_inf) (estimated), which
//     bounds ||J^-1||_2 from above (Higham, Accuracy and Stability, 2nd ed., Section 6.3): the 2-norm
//     the sweep's closed-form bound needs.

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "numlab/mechanisms/linkage/linkage_sweep.hpp"

namespace numlab::mechanisms {

inline constexpr Eigen::Index linkage_exact_conditioning_limit = 100;

// J's nonzeros as a sparse matrix, in one column-major pass (Eigen's sparseView() inserts entry by
// entry: it took most of a 300-joint sweep's time).
Eigen::SparseMatrix<double> linkage_sparse_jacobian(const Eigen::MatrixXd& J);
// The model's J at (q, t) assembled sparse from its constraints (LinkageModel::jacobian_entries),
// never as a dense matrix: time and memory linear in the joints.
Eigen::SparseMatrix<double> linkage_sparse_jacobian(const LinkageModel& model, double t, const Eigen::VectorXd& q);

// kappa_2 and ||J^-1||_2 from the SVD of J (any size).
LinkageConditioning exact_linkage_conditioning(const Eigen::MatrixXd& J);
// kappa_1 and sqrt(||J^-1||_1 ||J^-1||_inf), estimated from J's sparse LU (any size); both infinite
// when the LU finds J singular.
LinkageConditioning estimated_linkage_conditioning(const Eigen::MatrixXd& J);
LinkageConditioning estimated_linkage_conditioning(const Eigen::SparseMatrix<double>& J);

// linkage_kinematics (linkage_sweep.hpp) from the sparse LU of J instead of a dense one: the same
// two solves, J qdot = -Phi_t and J qddot = gamma, in time about linear in the joints (the dense
// LU is O(n^3): ~1 s at 2000 unknowns). False, velocity and acceleration NaN, when the LU finds J
// singular.
bool sparse_linkage_kinematics(const LinkageModel& model, double t, const Eigen::VectorXd& q, Eigen::VectorXd& velocity,
                               Eigen::VectorXd& acceleration);

}  // namespace numlab::mechanisms
