// The linear exercises' detectors (labs/exercises/detectors/): answers built with one known mistake
// are diagnosed with that mistake's cause, and a right answer with none. Each wrong answer is made
// here, independently of the detectors' own replays where the mistake is a closed form (the
// inverse's, the polynomial's), and by the replay with the mistake where it is a whole elimination
// or iteration (the replay with no mistake being checked against numlab's solvers first).

#include <catch2/catch.hpp>
#include <Eigen/LU>
#include <Eigen/QR>
#include <cmath>
#include <limits>
#include <optional>
#include <string>

#include "exercises/detectors/gauss_seidel_detectors.hpp"
#include "exercises/detectors/gepp_detectors.hpp"
#include "exercises/detectors/inverse2x2_detectors.hpp"
#include "exercises/detectors/polyfit_detectors.hpp"
#include "numlab/fitting/reference_fits.hpp"
#include "numlab/linalg/gauss_elimination.hpp"
#include "numlab/linalg/gauss_seidel.hpp"
#include "numlab/linalg/matrix_generators.hpp"
#include "numlab/linalg/measures.hpp"

namespace {

namespace d = numlab::exercises::detectors;
using numlab::exercises::Diagnosis;

std::string cause_of(const std::optional<Diagnosis>& diagnosis) { return diagnosis ? diagnosis->cause : "(none)"; }

// --- gepp ---

d::GeppAnswer gepp_answer(const d::GeppRun& run) {
  d::GeppAnswer answer;
  answer.singular = run.singular;
  if (!run.singular) answer.x = run.x;
  std::vector<d::GeppTraceEntry> trace;
  for (std::size_t k = 0; k < run.rows.size(); ++k) trace.push_back({run.rows[k], run.pivots[k]});
  answer.trace = trace;
  return answer;
}

std::string gepp_cause(const Eigen::MatrixXd& A, const Eigen::VectorXd& b, d::GeppAnswer answer) {
  return cause_of(d::diagnose_gepp(A, b, numlab::linalg::condition_estimate(A), answer));
}

Eigen::MatrixXd tiny_leading_pivot() {
  return (Eigen::MatrixXd(4, 4) << 1e-20, 1, 2, -1, -3, 1, 1, 2, -1, 2, -1, 1, 0.5, -2, 3, 1).finished();
}

TEST_CASE("gepp detectors: the replay without a mistake is numlab's GEPP, and a right answer has no diagnosis") {
  const auto system = numlab::linalg::generate_system("random", 8, 2);
  const d::GeppRun right = d::replay_gepp(system.A, system.b, d::GeppMistake::none);
  const auto numlab = numlab::linalg::gauss_elimination<Eigen::Dynamic>(system.A, system.b);
  CHECK((right.x - numlab.x).cwiseAbs().maxCoeff() <= 1e-12 * numlab.x.cwiseAbs().maxCoeff());
  CHECK(gepp_cause(system.A, system.b, gepp_answer(right)) == "(none)");
  const Eigen::MatrixXd T = tiny_leading_pivot();
  const Eigen::VectorXd ones = T * Eigen::VectorXd::Ones(4);
  CHECK(gepp_cause(T, ones, gepp_answer(d::replay_gepp(T, ones, d::GeppMistake::none))) == "(none)");
}

TEST_CASE("gepp detectors: each replayed mistake is named by its own cause") {
  const auto system = numlab::linalg::generate_system("random", 8, 11);
  const Eigen::MatrixXd T = tiny_leading_pivot();
  const Eigen::VectorXd ones = T * Eigen::VectorXd::Ones(4);
  const auto cause = [&](d::GeppMistake mistake, bool tiny, bool with_trace) {
    const Eigen::MatrixXd& A = tiny ? T : system.A;
    const Eigen::VectorXd& b = tiny ? ones : system.b;
    d::GeppAnswer answer = gepp_answer(d::replay_gepp(A, b, mistake));
    if (!with_trace) answer.trace.reset();
    return gepp_cause(A, b, answer);
  };
  CHECK(cause(d::GeppMistake::no_pivoting, false, true) == "no_pivoting");
  CHECK(cause(d::GeppMistake::no_pivoting, true, false) == "no_pivoting");  // "singular" at a_00 = 1e-20
  CHECK(cause(d::GeppMistake::signed_pivot, true, true) == "signed_pivot");
  CHECK(cause(d::GeppMistake::inverted_multiplier, false, true) == "inverted_multiplier");
  CHECK(cause(d::GeppMistake::inverted_multiplier, false, false) == "inverted_multiplier");
  CHECK(cause(d::GeppMistake::swap_without_b, false, false) == "swap_without_b");
  CHECK(cause(d::GeppMistake::swap_leaves_last_column, false, true) == "partial_row_swap");
  CHECK(cause(d::GeppMistake::back_substitution_skips_next, false, false) == "back_substitution");
  CHECK(cause(d::GeppMistake::back_substitution_skips_last, false, true) == "back_substitution");
}

TEST_CASE("gepp detectors: the singular thresholds") {
  // kappa 1e10: numlab's last pivot is ~1e-9 of max|a_ij|, far above n*eps*max|a_ij|.
  const Eigen::MatrixXd nearly = numlab::linalg::matrix_with_condition(8, 1e10, 3);
  const Eigen::VectorXd b = nearly * Eigen::VectorXd::Ones(8);
  d::GeppAnswer stopped = gepp_answer(d::replay_gepp(nearly, b, d::GeppMistake::none));
  REQUIRE(!stopped.singular);
  REQUIRE(std::abs(stopped.trace->back().pivot) < 1e-6 * nearly.cwiseAbs().maxCoeff());
  stopped.trace->pop_back();  // "singular" at the last column, as an absolute threshold 1e-8 says
  stopped.singular = true;
  stopped.x.reset();
  CHECK(gepp_cause(nearly, b, stopped) == "absolute_singular_threshold");
  // Singular to working precision: a trace that divides by the rounding-noise pivot.
  const Eigen::MatrixXd S = (Eigen::MatrixXd(3, 3) << 0.1, 0.7, 0.3, 0.3, 0.2, 0.9, 0.4, 0.9, 1.2).finished();
  const Eigen::VectorXd s1 = S * Eigen::VectorXd::Ones(3);
  const d::GeppRun numlab_run = d::replay_gepp(S, s1, d::GeppMistake::none);
  REQUIRE(numlab_run.singular);
  d::GeppAnswer divided;
  divided.x = Eigen::VectorXd::Constant(3, 1e15);
  divided.trace = std::vector<d::GeppTraceEntry>{{numlab_run.rows[0], numlab_run.pivots[0]},
                                                 {numlab_run.rows[1], numlab_run.pivots[1]},
                                                 {2, numlab_run.stopped_pivot}};
  CHECK(gepp_cause(S, s1, divided) == "no_singular_test");
  // A right "singular" has no diagnosis.
  CHECK(gepp_cause(S, s1, gepp_answer(numlab_run)) == "(none)");
}

// --- gauss-seidel ---

d::GaussSeidelProblem gs_problem(Eigen::MatrixXd A, bool normal, double tolerance, int max_iterations,
                                 double start = 0.0) {
  d::GaussSeidelProblem p;
  p.b = A * Eigen::VectorXd::Ones(A.cols());
  p.x0 = Eigen::VectorXd::Constant(A.cols(), start);
  p.A = std::move(A);
  p.tolerance = tolerance;
  p.max_iterations = max_iterations;
  p.normal_equations = normal;
  return p;
}

d::GaussSeidelAnswer gs_answer(const d::GaussSeidelRun& run, bool with_trace) {
  d::GaussSeidelAnswer answer{run.status, run.sweeps(), run.xs.back(), std::nullopt};
  if (with_trace) {
    std::vector<d::GaussSeidelSweep> trace;
    for (std::size_t s = 0; s < run.xs.size(); ++s) trace.push_back({run.xs[s], run.updates[s]});
    answer.trace = trace;
  }
  return answer;
}

std::string gs_cause(const d::GaussSeidelProblem& p, d::SweptSystem system, d::SweepKind kind, d::StopRule stop,
                     bool with_trace) {
  return cause_of(d::diagnose_gauss_seidel(p, gs_answer(d::replay_gauss_seidel(p, system, kind, stop), with_trace)));
}

TEST_CASE("gauss-seidel detectors: the replay without a mistake is numlab's stepper, and has no diagnosis") {
  const auto p = gs_problem(numlab::linalg::diagonally_dominant_matrix(10, 3), false, 1e-10, 200);
  const d::GaussSeidelRun run =
      d::replay_gauss_seidel(p, d::SweptSystem::asked, d::SweepKind::gauss_seidel, d::StopRule::stated);
  numlab::linalg::GaussSeidelOptions options;
  options.system = numlab::linalg::GaussSeidelOptions::System::plain;
  options.tolerance = p.tolerance;
  options.max_iterations = p.max_iterations;
  numlab::linalg::GaussSeidel<> stepper(options);
  const auto result = stepper.solve(p.A, p.b, p.x0);
  CHECK(run.status == "converged");
  CHECK(run.sweeps() == result.iterations);
  CHECK((run.xs.back() - result.x).cwiseAbs().maxCoeff() <= 1e-12);
  for (const bool trace : {true, false}) {
    CHECK(gs_cause(p, d::SweptSystem::asked, d::SweepKind::gauss_seidel, d::StopRule::stated, trace) == "(none)");
  }
}

TEST_CASE("gauss-seidel detectors: wrong sweeps, from the trace and from the whole run") {
  using d::StopRule;
  using d::SweepKind;
  using d::SweptSystem;
  const auto plain = gs_problem(numlab::linalg::diagonally_dominant_matrix(10, 3), false, 1e-10, 200);
  const auto normal_random = gs_problem(numlab::linalg::random_matrix(4, 8), true, 1e-10, 5000);
  const auto normal_diverging = gs_problem(numlab::linalg::gauss_seidel_divergence_example(), true, 1e-10, 2000);
  // Without a trace, the reverse order ends as numlab's does (the same sweeps, x to 1e-10) and is not
  // blamed; its first sweep gives it away.
  CHECK(gs_cause(plain, SweptSystem::asked, SweepKind::reverse, StopRule::stated, true) == "reverse_order");
  CHECK(gs_cause(plain, SweptSystem::asked, SweepKind::reverse, StopRule::stated, false) == "(none)");
  for (const bool trace : {true, false}) {
    INFO("with trace: " << trace);
    CHECK(gs_cause(plain, SweptSystem::asked, SweepKind::jacobi, StopRule::stated, trace) == "jacobi_sweep");
    CHECK(gs_cause(plain, SweptSystem::asked, SweepKind::no_update, StopRule::stated, trace) == "x_never_updated");
    CHECK(gs_cause(plain, SweptSystem::normal, SweepKind::gauss_seidel, StopRule::stated, trace) ==
          "normal_when_plain_asked");
    CHECK(gs_cause(normal_random, SweptSystem::a_at, SweepKind::gauss_seidel, StopRule::stated, trace) ==
          "a_at_instead_of_at_a");
    CHECK(gs_cause(normal_diverging, SweptSystem::plain, SweepKind::gauss_seidel, StopRule::stated, trace) ==
          "plain_when_normal_asked");
  }
}

TEST_CASE("gauss-seidel detectors: wrong stop rules, the limit and the extra sweep") {
  using d::StopRule;
  using d::SweepKind;
  using d::SweptSystem;
  const auto from_above = gs_problem(numlab::linalg::diagonally_dominant_matrix(10, 3), false, 1e-9, 200, 10.0);
  const auto capped = gs_problem(numlab::linalg::hilbert_matrix(6), true, 1e-12, 25);
  CHECK(gs_cause(from_above, SweptSystem::asked, SweepKind::gauss_seidel, StopRule::signed_change, true) == "stop_test");
  CHECK(gs_cause(capped, SweptSystem::asked, SweepKind::gauss_seidel, StopRule::limit_converged, false) ==
        "limit_reported_converged");
  CHECK(gs_cause(capped, SweptSystem::asked, SweepKind::gauss_seidel, StopRule::extra_sweep, true) ==
        "one_iteration_too_many");
  // A stop rule that changes nothing on this problem is not blamed.
  CHECK(gs_cause(capped, SweptSystem::asked, SweepKind::gauss_seidel, StopRule::absolute, true) == "(none)");
}

// --- inverse2x2 ---

std::string inverse_cause(const Eigen::Matrix2d& A, std::optional<Eigen::Matrix2d> inverse) {
  d::InverseAnswer answer;
  answer.singular = !inverse.has_value();
  answer.inverse = inverse;
  return cause_of(d::diagnose_inverse2x2(A, answer));
}

TEST_CASE("inverse2x2 detectors: wrong closed forms, scaling and thresholds") {
  const Eigen::Matrix2d A = (Eigen::Matrix2d() << 4, 7, 2, 6).finished();
  const Eigen::Matrix2d adjugate = (Eigen::Matrix2d() << 6, -7, -2, 4).finished();  // det = 10
  CHECK(inverse_cause(A, Eigen::Matrix2d(adjugate / 10.0)) == "(none)");
  CHECK(inverse_cause(A, Eigen::Matrix2d(adjugate.transpose() / 10.0)) == "transposed");
  CHECK(inverse_cause(A, Eigen::Matrix2d(adjugate / -10.0)) == "determinant_sign");
  CHECK(inverse_cause(A, adjugate) == "no_scaling");
  // Symmetric: the transposed inverse is the inverse, and nothing is blamed.
  const Eigen::Matrix2d swap = (Eigen::Matrix2d() << 0, 1, 1, 0).finished();
  CHECK(inverse_cause(swap, swap) == "(none)");
  // 1e-170 A unscaled: a d and b c underflow to 0, and the singular test fires.
  CHECK(inverse_cause(Eigen::Matrix2d(A * 1e-170), std::nullopt) == "no_scaling");
  // det = 2^-40 (kappa ~ 7e12, invertible): "singular" from a fixed threshold 1e-12.
  CHECK(inverse_cause((Eigen::Matrix2d() << 1, 2, 0.5, 1 + 0x1p-40).finished(), std::nullopt) ==
        "absolute_singular_threshold");
  // det = 2^-51 <= eps ||A||_F^2: an inverse is the missing singular test; "singular" is right.
  const Eigen::Matrix2d noise = (Eigen::Matrix2d() << 1, 2, 0.5, 1 + 0x1p-51).finished();
  CHECK(inverse_cause(noise, Eigen::Matrix2d(Eigen::Matrix2d::Constant(4e15))) == "no_singular_test");
  CHECK(inverse_cause(noise, std::nullopt) == "(none)");
}

// --- polyfit ---

Eigen::VectorXd least_squares(const Eigen::VectorXd& x, const Eigen::VectorXd& y, int degree) {
  const Eigen::MatrixXd V = numlab::fitting::vandermonde(x, degree);
  const Eigen::VectorXd scale = V.colwise().norm().transpose();
  const Eigen::MatrixXd U = V * scale.cwiseInverse().asDiagonal();
  return (U.colPivHouseholderQr().solve(y).array() / scale.array()).matrix();
}

std::string polyfit_cause(const d::PolyfitProblem& p, const Eigen::VectorXd& got) {
  return cause_of(d::diagnose_polyfit(p, got));
}

TEST_CASE("polyfit detectors: each wrong fit is named by its own cause") {
  Eigen::VectorXd x(12), y(12);
  for (int i = 0; i < 12; ++i) {
    x(i) = -1.0 + 0.25 * i;
    y(i) = 1.5 - 2.0 * x(i) + 0.5 * std::pow(x(i), 3) + 0.1 * std::sin(7.0 * x(i));
  }
  const int D = 3;
  const d::PolyfitProblem p{x, y, D, least_squares(x, y, D), 1e-12};
  CHECK(polyfit_cause(p, p.expected) == "(none)");
  CHECK(polyfit_cause(p, p.expected.reverse()) == "powers_reversed");
  CHECK(polyfit_cause(p, least_squares(x, y, D - 1)) == "degree_off_by_one");
  CHECK(polyfit_cause(p, least_squares(x.array() - x.mean(), y, D)) == "missing_unscale");
  const Eigen::MatrixXd V4 = numlab::fitting::vandermonde(x.head(D + 1), D);
  CHECK(polyfit_cause(p, V4.fullPivLu().solve(y.head(D + 1))) == "interpolation");
  // The normal equations with the moments sum x^(j+1) y: built here in long double.
  Eigen::MatrixXd N(D + 1, D + 1);
  Eigen::VectorXd r(D + 1);
  for (int j = 0; j <= D; ++j) {
    long double moment = 0.0L;
    for (int i = 0; i < 12; ++i) moment += std::pow(static_cast<long double>(x(i)), j + 1) * y(i);
    r(j) = static_cast<double>(moment);
    for (int k = 0; k <= D; ++k) N(j, k) = x.array().pow(j + k).sum();
  }
  CHECK(polyfit_cause(p, N.fullPivLu().solve(r)) == "normal_equations_wrong");
}

TEST_CASE("polyfit detectors: reversed powers are never blamed where reversal changes nothing") {
  // Wampler1's shape: y = 1 + x + ... + x^5 exactly, certified coefficients all 1.
  Eigen::VectorXd x(21), y(21);
  for (int i = 0; i < 21; ++i) {
    x(i) = i;
    y(i) = 0.0;
    for (int k = 5; k >= 0; --k) y(i) = y(i) * x(i) + 1.0;
  }
  const d::PolyfitProblem p{x, y, 5, Eigen::VectorXd::Ones(6), 1e-9};
  Eigen::VectorXd off = Eigen::VectorXd::Ones(6);
  off(5) += 1e-7;  // an inaccurate fit, as the power-sum normal equations give
  CHECK(polyfit_cause(p, off) != "powers_reversed");
  CHECK(polyfit_cause(p, off.reverse()) != "powers_reversed");
}

}  // namespace
