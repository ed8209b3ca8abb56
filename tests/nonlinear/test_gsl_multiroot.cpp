#include <catch2/catch.hpp>
#include <map>

#include "numlab/nonlinear/gsl_multiroot.hpp"
#include "small_systems.hpp"
#include "numlab/nonlinear/mgh_problems.hpp"

using namespace numlab;
using namespace numlab::nonlinear;

using test::lab_options;

TEST_CASE("All eight GSL types reach the known root on the well-behaved problems", "[gsl][mgh]") {
  for (const std::string name : {"rosenbrock", "helical-valley", "powell-singular"}) {
    const TestProblem problem = make_test_problem(name);
    for (const std::string& type : gsl_multiroot_types()) {
      const auto result = gsl_multiroot_solve(*problem.system, problem.standard_start, type, lab_options());
      INFO(name << " with " << type << ": " << result.message);
      REQUIRE(result.status == Status::converged);
      // Powell singular's root is only linearly approached: error ~ sqrt(||f||) (see test_newton.cpp).
      const double allowed = name == "powell-singular" ? 1e-5 : 1e-9;
      CHECK((result.x - *problem.known_root).lpNorm<Eigen::Infinity>() <= allowed);
    }
  }
}

TEST_CASE("Derivative-free GSL types never evaluate the Jacobian, the others do", "[gsl]") {
  const TestProblem problem = make_test_problem("rosenbrock");
  for (const std::string& type : gsl_multiroot_types()) {
    const auto result = gsl_multiroot_solve(*problem.system, problem.standard_start, type, lab_options());
    const bool uses_jacobian = type == "hybridsj" || type == "hybridj" || type == "newton" || type == "gnewton";
    INFO(type);
    CHECK((result.jacobian_evaluations > 0) == uses_jacobian);
    CHECK(result.function_evaluations > 0);
  }
}

TEST_CASE("The hard cases, pinned as GSL 2.7 behaves on them", "[gsl][mgh][failure]") {
  // status of each type from the standard start (tolerance 1e-10, 100 iterations)
  const std::map<std::string, std::map<std::string, Status>> expected = {
      {"powell-badly-scaled",
       {{"hybrids", Status::max_iterations}, {"hybrid", Status::max_iterations}, {"dnewton", Status::converged},
        {"broyden", Status::converged}, {"hybridsj", Status::max_iterations}, {"hybridj", Status::max_iterations},
        {"newton", Status::converged}, {"gnewton", Status::converged}}},
      {"freudenstein-roth",
       {{"hybrids", Status::no_progress}, {"hybrid", Status::no_progress}, {"dnewton", Status::converged},
        {"broyden", Status::max_iterations}, {"hybridsj", Status::no_progress}, {"hybridj", Status::no_progress},
        {"newton", Status::converged}, {"gnewton", Status::max_iterations}}},
      {"trigonometric",
       {{"hybrids", Status::no_progress}, {"hybrid", Status::no_progress}, {"dnewton", Status::converged},
        {"broyden", Status::converged}, {"hybridsj", Status::no_progress}, {"hybridj", Status::no_progress},
        {"newton", Status::converged}, {"gnewton", Status::converged}}},
  };
  for (const auto& [name, statuses] : expected) {
    const TestProblem problem = make_test_problem(name);
    for (const auto& [type, status] : statuses) {
      const auto result = gsl_multiroot_solve(*problem.system, problem.standard_start, type, lab_options());
      INFO(name << " with " << type << ": " << to_string(result.status) << " " << result.message);
      CHECK(result.status == status);
      if (status == Status::converged && problem.known_root && name != "trigonometric") {
        CHECK((result.x - *problem.known_root).lpNorm<Eigen::Infinity>() <= 1e-8);
      }
      if (status == Status::no_progress) {
        CHECK(result.residual_norm > 1e-3);  // stuck away from a root, and reported so
        CHECK_FALSE(result.message.empty());
      }
    }
  }
}

TEST_CASE("The GSL adapter rejects bad input", "[gsl][bad-input]") {
  using Catch::Matchers::Contains;
  const TestProblem problem = make_test_problem("wood");
  CHECK_THROWS_WITH(gsl_multiroot_solve(*problem.system, problem.standard_start, "lm"),
                    Contains("unknown GSL multiroot type 'lm'"));
  CHECK_THROWS_WITH(gsl_multiroot_solve(*problem.system, Eigen::VectorXd::Ones(2), "hybrids"),
                    Contains("2 entries but the system has 4"));
}

TEST_CASE("GSL's types refuse damping, which only numlab's Newton does", "[gsl][input]") {
  const TestProblem problem = make_test_problem("rosenbrock");
  NewtonOptions damped = lab_options();
  damped.damped = true;
  CHECK_THROWS_AS(GslMultiroot(*problem.system, "newton", damped), std::invalid_argument);
  CHECK_THROWS_AS(gsl_multiroot_solve(*problem.system, problem.standard_start, "hybridsj", damped), std::invalid_argument);
}
