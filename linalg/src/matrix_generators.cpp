#include "numlab/linalg/matrix_generators.hpp"

#include <Eigen/QR>
#include <random>
#include <stdexcept>

namespace numlab::linalg {

Eigen::MatrixXd random_matrix(int n, unsigned seed) {
  std::mt19937_64 engine(seed);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  Eigen::MatrixXd A(n, n);
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) A(i, j) = uniform(engine);
  }
  return A;
}

Eigen::MatrixXd hilbert_matrix(int n) {
  Eigen::MatrixXd H(n, n);
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) H(i, j) = 1.0 / (i + j + 1);
  }
  return H;
}

Eigen::MatrixXd wilkinson_matrix(int n) {
  Eigen::MatrixXd W = Eigen::MatrixXd::Identity(n, n);
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < i; ++j) W(i, j) = -1.0;
  }
  W.col(n - 1).setOnes();
  return W;
}

Eigen::MatrixXd diagonally_dominant_matrix(int n, unsigned seed) {
  Eigen::MatrixXd A = random_matrix(n, seed);
  for (int i = 0; i < n; ++i) {
    A(i, i) = 0.0;
    A(i, i) = 1.0 + A.row(i).cwiseAbs().sum();
  }
  return A;
}

Eigen::MatrixXd gauss_seidel_divergence_example() {
  Eigen::MatrixXd A(3, 3);
  A << 1, 2, 4, 2, 1, 2, 4, 2, 1;
  return A;
}

Eigen::MatrixXd singular_matrix(int n, unsigned seed) {
  std::mt19937_64 engine(seed);
  std::uniform_int_distribution<int> digits(-9, 9);
  Eigen::MatrixXd A(n, n);
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) A(i, j) = digits(engine);
  }
  // The last row is a combination of the first ones: exactly dependent, in floating point too.
  if (n == 2) {
    A.row(1) = 2.0 * A.row(0);
  } else {
    A.row(n - 1) = A.row(0) + A.row(1);
  }
  return A;
}

Eigen::MatrixXd matrix_with_condition(int n, double kappa, unsigned seed) {
  // Orthogonal factors from the QR factorizations of two random matrices.
  const Eigen::MatrixXd U = Eigen::HouseholderQR<Eigen::MatrixXd>(random_matrix(n, seed)).householderQ();
  const Eigen::MatrixXd V = Eigen::HouseholderQR<Eigen::MatrixXd>(random_matrix(n, seed + 1)).householderQ();
  // Singular values spaced geometrically from 1 down to 1/kappa.
  Eigen::VectorXd sigma(n);
  for (int i = 0; i < n; ++i) sigma(i) = n == 1 ? 1.0 : std::pow(kappa, -static_cast<double>(i) / (n - 1));
  return U * sigma.asDiagonal() * V.transpose();
}

const std::vector<std::string>& generator_kinds() {
  static const std::vector<std::string> kinds = {"random",        "hilbert",    "wilkinson",
                                                 "diag-dominant", "gs-diverge", "singular"};
  return kinds;
}

GeneratedSystem generate_system(std::string_view kind, int n, unsigned seed) {
  const int smallest = kind == "singular" ? 2 : 1;
  if (kind != "gs-diverge" && (n < smallest || n > max_generated_size)) {
    throw std::invalid_argument("size " + std::to_string(n) + " for generator '" + std::string(kind) +
                                "' is outside " + std::to_string(smallest) + " ... " +
                                std::to_string(max_generated_size));
  }
  GeneratedSystem system;
  if (kind == "random") {
    system.A = random_matrix(n, seed);
  } else if (kind == "hilbert") {
    system.A = hilbert_matrix(n);
  } else if (kind == "wilkinson") {
    system.A = wilkinson_matrix(n);
  } else if (kind == "diag-dominant") {
    system.A = diagonally_dominant_matrix(n, seed);
  } else if (kind == "gs-diverge") {
    system.A = gauss_seidel_divergence_example();
  } else if (kind == "singular") {
    system.A = singular_matrix(n, seed);
  } else {
    throw std::invalid_argument("unknown generator '" + std::string(kind) +
                                "' (expected random, hilbert, wilkinson, diag-dominant, gs-diverge or singular)");
  }
  system.exact_solution = Eigen::VectorXd::Ones(system.A.rows());
  system.b = system.A * system.exact_solution;
  return system;
}

}  // namespace numlab::linalg
