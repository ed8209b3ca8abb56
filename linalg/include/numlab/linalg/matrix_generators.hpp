#pragma once
// Matrix generators (a library part, not a test): each builds matrices chosen to show one behaviour of the
// linear solvers, for the labs, the benchmarks and the tests alike.
// Random ones are reproducible: the same seed gives the same matrix.

#include <Eigen/Core>
#include <string>
#include <string_view>
#include <vector>

namespace numlab::linalg {

// Entries uniform in [-1, 1].
Eigen::MatrixXd random_matrix(int n, unsigned seed = 1);

// h_ij = 1 / (i + j - 1): symmetric positive definite and famously ill-conditioned
// (kappa_2 ~ 1.6e13 at n = 10, 1.7e16 at n = 12).
Eigen::MatrixXd hilbert_matrix(int n);

// Wilkinson's growth matrix: 1 on the diagonal, -1 below it, 1 in the last column.
// Partial pivoting never swaps and the last column doubles at every step: growth 2^(n-1).
Eigen::MatrixXd wilkinson_matrix(int n);

// Random, then each diagonal entry set to 1 + the sum of |off-diagonal| in its row.
Eigen::MatrixXd diagonally_dominant_matrix(int n, unsigned seed = 1);

// [[1,2,4],[2,1,2],[4,2,1]]: plain Gauss-Seidel diverges on it (not diagonally dominant).
Eigen::MatrixXd gauss_seidel_divergence_example();

// Random integers in [-9, 9] with the last row the sum of the first two (twice the first when
// n = 2): exactly singular (n >= 2).
Eigen::MatrixXd singular_matrix(int n, unsigned seed = 1);

// U diag(1 ... 1/kappa) V^T with random orthogonal U, V: kappa_2 is exactly `kappa` (up to rounding).
Eigen::MatrixXd matrix_with_condition(int n, double kappa, unsigned seed = 1);

// A system A x = b whose exact solution is all ones (b = A * 1, as in `numlab solve linear --generate`).
struct GeneratedSystem {
  Eigen::MatrixXd A;
  Eigen::VectorXd b;
  Eigen::VectorXd exact_solution;
};

// The generator kinds of `--generate KIND:N`.
const std::vector<std::string>& generator_kinds();

// Builds KIND of size n (n is ignored for gs-diverge). Throws std::invalid_argument for an unknown
// kind or an n outside 1 ... max_generated_size (2 ... for singular).
GeneratedSystem generate_system(std::string_view kind, int n, unsigned seed = 1);

inline constexpr int max_generated_size = 4096;

}  // namespace numlab::linalg
