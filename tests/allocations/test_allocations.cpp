// Heap allocations inside the solve loops, counted two ways:
//  - Eigen's own (EIGEN_RUNTIME_NO_MALLOC: every Eigen heap allocation asks is_malloc_allowed());
//  - everything else, through a counting global operator new (release build only; see
//    counting_operator_new.hpp for ASan).
// This file is its own executable and compiles inverse2x2.cpp (and the closures) itself, so that every Eigen function
// it runs is built with the hook (the library is not linked); count_eigen_allocations.hpp is
// force-included into both.

#include "counting_operator_new.hpp"

#include <catch2/catch.hpp>

#include "numlab/linalg/eigen_reference.hpp"
#include "numlab/linalg/gauss_elimination.hpp"
#include "numlab/linalg/gauss_seidel.hpp"
#include "numlab/linalg/inverse2x2.hpp"
#include "numlab/mechanisms/dyad_block.hpp"
#include "numlab/mechanisms/dyad_newton.hpp"
#include "numlab/mechanisms/jansen_closure.hpp"
#include "numlab/mechanisms/mustang_closure.hpp"
#include "numlab/nonlinear/newton.hpp"
#include "../nonlinear/small_systems.hpp"

using namespace numlab;
using namespace numlab::linalg;

namespace {

struct AllocationCount {
  long eigen;
  long other;
};

// Runs `work` with Eigen's heap forbidden and operator new counted; returns what was attempted.
template <typename Work>
AllocationCount allocations_during(Work&& work) {
  refused_eigen_allocations = 0;
  numlab::testing::operator_new_calls = 0;
  Eigen::internal::set_is_malloc_allowed(false);
  numlab::testing::counting_operator_new = true;
  work();
  numlab::testing::counting_operator_new = false;
  Eigen::internal::set_is_malloc_allowed(true);
  return {refused_eigen_allocations.load(), numlab::testing::operator_new_calls.load()};
}

template <int N>
Matrix<N> diagonally_dominant() {
  Matrix<N> A = Matrix<N>::Constant(0.5);
  A.diagonal().setConstant(N + 1.0);
  A(0, N - 1) = -0.25;
  return A;
}

}  // namespace

TEST_CASE("The counter sees allocations (so a zero below means something)", "[allocations]") {
  const AllocationCount counted = allocations_during([] {
    Eigen::VectorXd dynamic(64);
    dynamic.setZero();
    static int* volatile boxed = nullptr;  // volatile: the compiler may not elide the new
    boxed = new int(3);
    delete boxed;
  });
  CHECK(counted.eigen >= 1);
  if (counts_operator_new) CHECK(counted.other == 1);
}

TEMPLATE_TEST_CASE_SIG("Fixed-size GEPP allocates nothing", "[allocations][gepp]", ((int N), N), 2, 8, 10) {
  const Matrix<N> A = diagonally_dominant<N>();
  const Vector<N> b = A * Vector<N>::Ones();
  GaussElimination<N> solver;
  LinearResult<N> result;
  const AllocationCount counted = allocations_during([&] {
    for (int repeat = 0; repeat < 100; ++repeat) result = solver.solve(A, b);
  });
  REQUIRE(result.status == Status::converged);
  CHECK(counted.eigen == 0);
  CHECK(counted.other == 0);
}

TEST_CASE("Fixed-size Gauss-Seidel, the 2x2 closed form and fixed Eigen LU allocate nothing", "[allocations]") {
  const Matrix<8> A = diagonally_dominant<8>();
  const Vector<8> b = A * Vector<8>::Ones();
  GaussSeidelOptions plain;
  plain.system = GaussSeidelOptions::System::plain;
  GaussSeidel<8> normal_equations, plain_sweeps(plain);
  EigenLu<8> eigen_lu;
  const Eigen::Matrix2d A2 = diagonally_dominant<2>();
  LinearResult<8> r1, r2, r3;
  LinearResult<2> r4;
  const AllocationCount counted = allocations_during([&] {
    for (int repeat = 0; repeat < 20; ++repeat) {
      r1 = normal_equations.solve(A, b);
      r2 = plain_sweeps.solve(A, b);
      r3 = eigen_lu.solve(A, b);
      r4 = solve2x2(A2, Eigen::Vector2d(1, 2));
    }
  });
  REQUIRE(r1.status == Status::converged);
  REQUIRE(r2.status == Status::converged);
  REQUIRE(r4.status == Status::converged);
  CHECK(counted.eigen == 0);
  CHECK(counted.other == 0);
}

TEST_CASE("Dynamic sizes allocate in start(), never in step()", "[allocations]") {
  const Eigen::MatrixXd A = Eigen::MatrixXd(diagonally_dominant<10>());
  const Eigen::VectorXd b = A * Eigen::VectorXd::Ones(10);

  GaussElimination<Eigen::Dynamic> elimination;
  elimination.start(A, b);
  const AllocationCount in_elimination = allocations_during([&] {
    while (elimination.step()) {
    }
  });
  CHECK(elimination.status() == Status::converged);
  CHECK(in_elimination.eigen == 0);
  CHECK(in_elimination.other == 0);

  GaussSeidel<Eigen::Dynamic> sweeps;
  sweeps.start(A, b);
  const AllocationCount in_sweeps = allocations_during([&] {
    while (sweeps.step()) {
    }
  });
  CHECK(sweeps.status() == Status::converged);
  CHECK(in_sweeps.eigen == 0);
  CHECK(in_sweeps.other == 0);
}

TEST_CASE("Fixed-size Newton allocates nothing, in solve() or per iteration", "[allocations][newton]") {
  using numlab::mechanisms::JansenClosure;
  const JansenClosure closure(JansenClosure::seed_crank_angle);
  const JansenClosure::Vector start = JansenClosure::seed_estimates();
  nonlinear::NewtonOptions options;
  options.residual_tolerance = 1e-12;
  nonlinear::Newton<JansenClosure> full(closure, options);  // GEPP<8>
  // The sweep's closure, on the sine table (filled on first use: a static, not the heap).
  const numlab::mechanisms::JansenClosureOf<numlab::mechanisms::TableSines> tabled(JansenClosure::seed_crank_angle);
  nonlinear::Newton<numlab::mechanisms::JansenClosureOf<numlab::mechanisms::TableSines>> full_tabled(tabled, options);
  const test::FixedRosenbrock rosenbrock;  // Newton keeps a reference: a temporary here would dangle
  nonlinear::Newton<test::FixedRosenbrock, linalg::ClosedForm2x2> two_by_two(rosenbrock, options);
  nonlinear::NewtonResult<8> result8, tabled8;
  nonlinear::NewtonResult<2> result2;
  const AllocationCount counted = allocations_during([&] {
    for (int repeat = 0; repeat < 20; ++repeat) {
      result8 = full.solve(start);
      tabled8 = full_tabled.solve(start);
      result2 = two_by_two.solve(test::Vector2(-1.2, 1.0));
    }
  });
  REQUIRE(result8.status == Status::converged);
  REQUIRE(result8.iterations >= 2);
  REQUIRE(tabled8.status == Status::converged);
  REQUIRE(result2.status == Status::converged);
  CHECK(counted.eigen == 0);
  if (counts_operator_new) CHECK(counted.other == 0);
}

TEST_CASE("Fixed-size inexact Newton (Gauss-Seidel inside, forcing terms) allocates nothing", "[allocations][newton]") {
  using numlab::mechanisms::JansenClosure;
  const JansenClosure closure(JansenClosure::seed_crank_angle);
  const JansenClosure::Vector start = JansenClosure::seed_estimates();
  nonlinear::NewtonOptions walker, constant;  // Eisenstat-Walker (the default) and a constant eta
  walker.residual_tolerance = constant.residual_tolerance = 1e-10;
  constant.forcing.kind = nonlinear::ForcingOptions::Kind::constant;
  GaussSeidelOptions inner;
  inner.max_iterations = 100000;
  nonlinear::Newton<JansenClosure, GaussSeidel<8>> by_walker(closure, walker, GaussSeidel<8>(inner));
  nonlinear::Newton<JansenClosure, GaussSeidel<8>> by_constant(closure, constant, GaussSeidel<8>(inner));
  nonlinear::NewtonResult<8> a, b;
  const AllocationCount counted = allocations_during([&] {
    for (int repeat = 0; repeat < 5; ++repeat) {
      a = by_walker.solve(start);
      b = by_constant.solve(start);
    }
  });
  REQUIRE(a.status == Status::converged);
  REQUIRE(b.status == Status::converged);
  CHECK(counted.eigen == 0);
  if (counts_operator_new) CHECK(counted.other == 0);
}

TEST_CASE("The Jansen dyad's Newton (sequential Newton's block) allocates nothing, fast and textbook",
          "[allocations][newton]") {
  numlab::nonlinear::NewtonOptions options;
  options.residual_tolerance = 1e-12;
  numlab::mechanisms::DyadNewton dyad(options);
  dyad.set_block(22.8, 38.0, 50.0, 41.5);  // seed 000's first block at crank angle pi/2
  // Its textbook form: the generic Newton on the block, with the closed-form 2x2 inverse.
  const numlab::mechanisms::DyadBlock block(22.8, 38.0, 50.0, 41.5);
  nonlinear::Newton<numlab::mechanisms::DyadBlock, linalg::ClosedForm2x2> textbook(block, options);
  Status status = Status::max_iterations;
  nonlinear::NewtonResult<2> result;
  const AllocationCount counted = allocations_during([&] {
    for (int repeat = 0; repeat < 20; ++repeat) {
      status = dyad.solve(2.62 + 1e-3 * repeat, 1.40);
      result = textbook.solve(Eigen::Vector2d(2.62 + 1e-3 * repeat, 1.40));
    }
  });
  REQUIRE(status == Status::converged);
  REQUIRE(result.status == Status::converged);
  CHECK(counted.eigen == 0);
  if (counts_operator_new) CHECK(counted.other == 0);
}

TEST_CASE("Mustang: full 8x8 Newton and a loop's 2x2 Newton allocate nothing", "[allocations][newton][mustang]") {
  using numlab::mechanisms::MustangClosure;
  const MustangClosure closure(0.5);
  MustangClosure::Vector start;  // near the pose at 0.5 rad on the seed's branch
  start << 0.16, 1.51, 1.14, 0.98, 0.77, 1.04, 0.22, 0.62;
  nonlinear::NewtonOptions options;
  options.residual_tolerance = 1e-12;
  nonlinear::Newton<MustangClosure> full(closure, options);  // GEPP<8>
  // Loop 1 as its own 2x2 system, solved with the closed-form inverse (as sequential Newton does).
  numlab::mechanisms::MustangLoop loop;
  loop.terms = closure.loop(0, start);
  nonlinear::Newton<numlab::mechanisms::MustangLoop, linalg::ClosedForm2x2> two_by_two(loop, options);
  nonlinear::NewtonResult<8> result8;
  nonlinear::NewtonResult<2> result2;
  const AllocationCount counted = allocations_during([&] {
    for (int repeat = 0; repeat < 20; ++repeat) {
      result8 = full.solve(start);
      result2 = two_by_two.solve(Eigen::Vector2d(0.16, 1.51));
    }
  });
  REQUIRE(result8.status == Status::converged);
  REQUIRE(result8.iterations >= 2);
  REQUIRE(result2.status == Status::converged);
  CHECK(counted.eigen == 0);
  if (counts_operator_new) CHECK(counted.other == 0);
}
