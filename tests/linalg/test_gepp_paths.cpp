// The textbook GEPP stepper and the fast path give bit-identical answers (gepp_paths.hpp).

#include <catch2/catch.hpp>
#include <cmath>

#include "gepp_paths.hpp"
#include "numlab/linalg/matrix_generators.hpp"

using namespace numlab;
using namespace numlab::linalg;
using numlab::test::check_gepp_paths_agree;

namespace {
GaussEliminationOptions no_pivoting() {
  GaussEliminationOptions options;
  options.pivoting = Pivoting::none;
  return options;
}
}  // namespace

TEMPLATE_TEST_CASE_SIG("GEPP's two paths agree bit for bit on random systems, fixed sizes", "[gepp][paths]",
                       ((int N), N), 1, 2, 3, 4, 8, 10, 16) {
  for (unsigned seed = 1; seed <= 25; ++seed) {
    const GeneratedSystem system = generate_system("random", N, seed);
    const Matrix<N> A = system.A;
    const Vector<N> b = system.b;
    INFO("n = " << N << ", seed " << seed);
    CHECK(check_gepp_paths_agree<N>(A, b).status == Status::converged);
    check_gepp_paths_agree<N>(A, b, no_pivoting());
  }
}

TEST_CASE("GEPP's two paths agree bit for bit on random systems, dynamic sizes", "[gepp][paths]") {
  for (int n : {1, 2, 3, 5, 8, 13, 21, 34, 55, 100, 200}) {
    for (unsigned seed = 1; seed <= 3; ++seed) {
      const GeneratedSystem system = generate_system("random", n, seed);
      INFO("n = " << n << ", seed " << seed);
      CHECK(check_gepp_paths_agree<Eigen::Dynamic>(system.A, system.b).status == Status::converged);
      check_gepp_paths_agree<Eigen::Dynamic>(system.A, system.b, no_pivoting());
    }
  }
}

TEST_CASE("GEPP's two paths agree bit for bit on Hilbert matrices, up to the singular n = 13", "[gepp][paths]") {
  for (int n = 1; n <= 13; ++n) {
    const GeneratedSystem system = generate_system("hilbert", n);
    INFO("n = " << n);
    const auto stepped = check_gepp_paths_agree<Eigen::Dynamic>(system.A, system.b);
    CHECK(stepped.status == (n == 13 ? Status::singular : Status::converged));
  }
  const GeneratedSystem eight = generate_system("hilbert", 8);
  check_gepp_paths_agree<8>(Matrix<8>(eight.A), Vector<8>(eight.b));
  const GeneratedSystem ten = generate_system("hilbert", 10);
  check_gepp_paths_agree<10>(Matrix<10>(ten.A), Vector<10>(ten.b));
}

TEST_CASE("GEPP's two paths agree on Wilkinson's growth, singular matrices and overflow", "[gepp][paths][failure]") {
  for (int n : {2, 10, 30, 55, 60}) {
    const GeneratedSystem system = generate_system("wilkinson", n);
    INFO("Wilkinson n = " << n);
    const auto stepped = check_gepp_paths_agree<Eigen::Dynamic>(system.A, system.b);
    CHECK(stepped.growth_factor == std::ldexp(1.0, n - 1));
  }
  int singular = 0;
  for (int n = 2; n <= 30; ++n) {
    const GeneratedSystem system = generate_system("singular", n, static_cast<unsigned>(n));
    INFO("singular n = " << n);
    if (check_gepp_paths_agree<Eigen::Dynamic>(system.A, system.b).status == Status::singular) ++singular;
  }
  CHECK(singular >= 20);  // most of them are caught by the pivot test (test_gauss_elimination.cpp)
  const GeneratedSystem system = generate_system("singular", 8, 8);
  check_gepp_paths_agree<8>(Matrix<8>(system.A), Vector<8>(system.b));

  // A pivot overflows during elimination; an unknown overflows during back substitution.
  Eigen::MatrixXd huge(2, 2);
  huge << 1e308, 1e308, -1e308, 1e308;
  CHECK(check_gepp_paths_agree<Eigen::Dynamic>(huge, Eigen::VectorXd::Ones(2)).status == Status::non_finite);
  const Eigen::Matrix2d tiny = 1e-10 * Eigen::Matrix2d::Identity();
  const auto overflowed = check_gepp_paths_agree<2>(tiny, Eigen::Vector2d(1e300, 1.0));
  CHECK(overflowed.status == Status::non_finite);
  CHECK(overflowed.iterations == 2);
}
