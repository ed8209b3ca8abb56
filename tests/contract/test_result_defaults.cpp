// Results start as `running`, never `converged` by default: a verdict is always set by the method.
// A default-constructed result says running; every solver's result after a solve says something
// else (here on easy problems, where that verdict is converged).

#include <catch2/catch.hpp>
#include <cmath>
#include <string>

#include "numlab/linalg/eigen_reference.hpp"
#include "numlab/linalg/gauss_elimination.hpp"
#include "numlab/linalg/gauss_seidel.hpp"
#include "numlab/linalg/gsl_reference.hpp"
#include "numlab/linalg/inverse2x2.hpp"
#include "numlab/linalg/matrix_generators.hpp"
#include "numlab/mechanisms/jansen_leg.hpp"
#include "numlab/mechanisms/jansen_solvers.hpp"
#include "numlab/mechanisms/mustang_solvers.hpp"
#include "numlab/mechanisms/mustang_sweep.hpp"
#include "numlab/nonlinear/linear_step.hpp"
#include "numlab/nonlinear/newton.hpp"

using namespace numlab;

TEST_CASE("A default-constructed result says running", "[contract][status]") {
  CHECK(linalg::LinearResult<3>{}.status == Status::running);
  CHECK(linalg::LinearResult<Eigen::Dynamic>{}.status == Status::running);
  CHECK(nonlinear::NewtonCounts{}.status == Status::running);
  CHECK(nonlinear::NewtonResult<2>{}.status == Status::running);
  CHECK(mechanisms::PoseOutcome{}.status == Status::running);
  CHECK(mechanisms::JansenSweepAngles{}.status == Status::running);
  CHECK(mechanisms::JansenSweep{}.status == Status::running);
  CHECK(mechanisms::MustangSweep{}.status == Status::running);
}

TEST_CASE("Every linear method's result after a solve has a verdict", "[contract][status]") {
  const linalg::GeneratedSystem system = linalg::generate_system("diag-dominant", 4);
  const linalg::Matrix<4> A = system.A;
  const linalg::Vector<4> b = system.b;
  CHECK(linalg::GaussElimination<4>().solve(A, b).status == Status::converged);
  CHECK(linalg::GaussElimination<4>().solve_prechecked(A, b).status == Status::converged);
  CHECK(linalg::GaussElimination<Eigen::Dynamic>().solve(system.A, system.b).status == Status::converged);
  linalg::GaussSeidelOptions plain;
  plain.system = linalg::GaussSeidelOptions::System::plain;
  CHECK(linalg::GaussSeidel<4>(plain).solve(A, b).status == Status::converged);
  CHECK(linalg::gsl_lu_solve(system.A, system.b).status == Status::converged);
  CHECK(linalg::gsl_qr_solve(system.A, system.b).status == Status::converged);
  CHECK(linalg::EigenLu<4>().solve(A, b).status == Status::converged);

  Eigen::Matrix2d A2;
  A2 << 4, 3, 6, 3;
  const Eigen::Vector2d b2(7, 9);
  CHECK(linalg::solve2x2(A2, b2).status == Status::converged);
  CHECK(linalg::ClosedForm2x2().solve_prechecked(A2, b2).status == Status::converged);
  for (const std::string& method : nonlinear::newton_linear_methods()) {
    INFO(method);
    const int n = method == "inverse2x2" ? 2 : 4;
    const Eigen::MatrixXd M = n == 2 ? Eigen::MatrixXd(A2) : system.A;
    const Eigen::VectorXd v = n == 2 ? Eigen::VectorXd(b2) : system.b;
    CHECK(nonlinear::RuntimeLinearStep(method, n).solve(M, v).status != Status::running);
  }
}

TEST_CASE("Every pose solver's outcome and both sweeps' results have a verdict", "[contract][status]") {
  using namespace numlab::mechanisms;
  for (const std::string& name : jansen_solver_names()) {
    INFO("jansen " << name);
    const auto solver = make_jansen_solver(JansenModel::eight_equations, name, "gepp", {});
    Eigen::VectorXd x = jansen_seed_estimates(JansenModel::eight_equations, JansenLeg{});
    CHECK(solver->solve(1.57, x).status == Status::converged);
  }
  const MustangStart start = mustang_seed_start();
  REQUIRE(start.status == Status::converged);
  for (const std::string& name : mustang_solver_names()) {
    INFO("mustang " << name);
    const auto solver = make_mustang_solver(name, "gepp", {});
    MustangAngles x = start.x;
    CHECK(solver->solve(45.0 * M_PI / 180.0, x).status == Status::converged);
  }
  const auto jansen = make_jansen_solver(JansenModel::eight_equations, "full", "gepp", {});
  CHECK(crank_sweep(JansenModel::eight_equations, *jansen, 0.0, 60.0, 30.0).status == Status::converged);
  CHECK(solve_crank_sweep(JansenModel::eight_equations, *jansen, 0.0, 60.0, 30.0).status == Status::converged);
  const auto mustang = make_mustang_solver("full", "gepp", {});
  CHECK(MustangSweepStepper(*mustang).solve(30.0, 50.0, 10.0).status == Status::converged);
}
