// GEPP keeps its factors: P A = L U to rounding, the same P, L and U as Eigen's PartialPivLU, on
// both paths (stepped and fast), and solve_with_factors(b) gives a fresh solve's x bit for bit.

#include <Eigen/LU>
#include <catch2/catch.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "numlab/linalg/gauss_elimination.hpp"
#include "numlab/linalg/matrix_generators.hpp"
#include "reference_tolerance.hpp"

using namespace numlab;
using namespace numlab::linalg;
using numlab::test::eps;

namespace {

struct Factors {
  Eigen::MatrixXd L, U;
  Eigen::VectorXi permutation;
  Status status;
  int columns;
  double growth;
};

// By the fast path (solve) or stepping (start, step) to the end.
Factors factor(const Eigen::MatrixXd& A, bool stepped) {
  GaussElimination<Eigen::Dynamic> gepp;
  const Eigen::VectorXd b = Eigen::VectorXd::Ones(A.rows());
  if (stepped) {
    gepp.start(A, b);
    while (gepp.step()) {
    }
  } else {
    gepp.solve(A, b);
  }
  return {gepp.lower(), gepp.upper(), gepp.permutation().indices(), gepp.status(), gepp.iterations(),
          gepp.growth_factor()};
}

// max|PA - LU| / (n eps max|A| growth): rounding alone keeps it of order 1.
double scaled_factor_error(const Eigen::MatrixXd& A, const Factors& f) {
  const Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> P(f.permutation);
  const double error = (P * A - f.L * f.U).cwiseAbs().maxCoeff();
  const double growth = std::isnan(f.growth) ? 1.0 : std::max(f.growth, 1.0);
  return error / (static_cast<double>(A.rows()) * eps * A.cwiseAbs().maxCoeff() * growth);
}

struct Named {
  std::string name;
  Eigen::MatrixXd A;
};

std::vector<Named> nonsingular_matrices() {
  Eigen::MatrixXd zero_corner(3, 3);  // a_11 = 0: pivots at once
  zero_corner << 0, 2, 1, 1, 1, 1, 4, 3, -2;
  Eigen::MatrixXd needs_swaps(4, 4);  // the largest entry of each column is low down
  needs_swaps << 1, 2, 3, 4, 2, 1, 0, 1, 5, 3, 1, 2, -7, 1, 2, 3;
  std::vector<Named> all = {{"zero corner", zero_corner},
                            {"needs swaps", needs_swaps},
                            {"wilkinson 12", wilkinson_matrix(12)},
                            {"hilbert 6", hilbert_matrix(6)},
                            {"diagonally dominant 9", diagonally_dominant_matrix(9, 3)}};
  for (int n : {1, 2, 5, 17, 40}) all.push_back({"random " + std::to_string(n), random_matrix(n, static_cast<unsigned>(n))});
  return all;
}

}  // namespace

TEST_CASE("GEPP's factors: PA = LU to rounding, and Eigen's PartialPivLU's P, L and U", "[gepp][factors]") {
  for (const Named& m : nonsingular_matrices()) {
    const Eigen::PartialPivLU<Eigen::MatrixXd> eigen(m.A);
    const Eigen::MatrixXd eigen_L = Eigen::MatrixXd(eigen.matrixLU().triangularView<Eigen::UnitLower>());
    const Eigen::MatrixXd eigen_U = Eigen::MatrixXd(eigen.matrixLU().triangularView<Eigen::Upper>());
    for (bool stepped : {false, true}) {
      INFO(m.name << (stepped ? ", stepped" : ", fast path"));
      const Factors f = factor(m.A, stepped);
      REQUIRE(f.status == Status::converged);
      CHECK(f.columns == m.A.rows());
      CHECK(scaled_factor_error(m.A, f) <= 4.0);
      // L unit lower triangular with |l_ik| <= 1 (partial pivoting), U upper triangular.
      CHECK(f.L.diagonal().isOnes());
      CHECK(f.L.triangularView<Eigen::StrictlyUpper>().toDenseMatrix().isZero(0.0));
      CHECK(f.U.triangularView<Eigen::StrictlyLower>().toDenseMatrix().isZero(0.0));
      CHECK(f.L.cwiseAbs().maxCoeff() <= 1.0);
      // The same pivots as Eigen's, and factors that agree to rounding in the growth.
      CHECK(f.permutation == eigen.permutationP().indices());
      const double tolerance = 100.0 * static_cast<double>(m.A.rows()) * eps * std::max(f.growth, 1.0);
      CHECK((f.L - eigen_L).cwiseAbs().maxCoeff() <= tolerance);
      CHECK((f.U - eigen_U).cwiseAbs().maxCoeff() <= tolerance * m.A.cwiseAbs().maxCoeff());
    }
  }
}

TEST_CASE("GEPP's factors: stepped and fast paths keep the same L, U and P bit for bit", "[gepp][factors]") {
  for (const Named& m : nonsingular_matrices()) {
    INFO(m.name);
    const Factors fast = factor(m.A, false);
    const Factors stepped = factor(m.A, true);
    CHECK(fast.L == stepped.L);
    CHECK(fast.U == stepped.U);
    CHECK(fast.permutation == stepped.permutation);
    CHECK(fast.growth == stepped.growth);
  }
}

TEST_CASE("GEPP's factors on a singular matrix: PA = L R where it stopped, no solve with them", "[gepp][factors]") {
  Eigen::MatrixXd rank_two(4, 4);  // row 4 = row 1 + row 2, row 3 = 2 row 1 - row 2
  rank_two << 1, 2, 3, 4, -2, 1, 0, 5, 4, 3, 6, 3, -1, 3, 3, 9;
  for (const Eigen::MatrixXd& A : {rank_two, singular_matrix(6, 2)}) {
    const Eigen::PartialPivLU<Eigen::MatrixXd> eigen(A);
    for (bool stepped : {false, true}) {
      INFO("n = " << A.rows() << (stepped ? ", stepped" : ", fast path"));
      const Factors f = factor(A, stepped);
      REQUIRE(f.status == Status::singular);
      REQUIRE(f.columns < A.rows());
      // P A = L R holds where the elimination stopped; R's column below the stop is negligible.
      CHECK(scaled_factor_error(A, f) <= 4.0);
      const int k = f.columns;
      CHECK(f.U.col(k).tail(A.rows() - k).cwiseAbs().maxCoeff() <= A.rows() * eps * A.cwiseAbs().maxCoeff());
      // Eigen goes on past the zero pivot; its U has the same first k rows, up to rounding.
      const Eigen::MatrixXd eigen_U = Eigen::MatrixXd(eigen.matrixLU().triangularView<Eigen::Upper>());
      CHECK((f.U.topRows(k) - eigen_U.topRows(k)).cwiseAbs().maxCoeff() <=
            100.0 * A.rows() * eps * A.cwiseAbs().maxCoeff());
    }
    GaussElimination<Eigen::Dynamic> gepp;
    gepp.solve(A, Eigen::VectorXd::Ones(A.rows()));
    CHECK_FALSE(gepp.factored());
    CHECK_THROWS_AS(gepp.solve_with_factors(Eigen::VectorXd::Ones(A.rows())), std::logic_error);
  }
}

TEMPLATE_TEST_CASE_SIG("GEPP factors once and solves many: each x is a fresh solve's, bit for bit", "[gepp][factors]",
                       ((int N), N), 3, 8, Eigen::Dynamic) {
  const int n = N == Eigen::Dynamic ? 23 : N;
  const Matrix<N> A = random_matrix(n, 7);
  for (bool stepped : {false, true}) {
    INFO((stepped ? "stepped" : "fast path"));
    GaussElimination<N> factored;
    const Vector<N> b0 = Vector<N>::Ones(n);
    if (stepped) {
      factored.start(A, b0);
      while (factored.step()) {
      }
    } else {
      factored.solve(A, b0);
    }
    REQUIRE(factored.factored());
    for (unsigned seed = 1; seed <= 5; ++seed) {
      const Vector<N> b = random_matrix(n, 100 + seed).col(0);
      const LinearResult<N> fresh = GaussElimination<N>().solve(A, b);
      const LinearResult<N> reused = factored.solve_with_factors(b);
      REQUIRE(fresh.status == Status::converged);
      CHECK(reused.status == Status::converged);
      CHECK(reused.x == fresh.x);
    }
  }
}
