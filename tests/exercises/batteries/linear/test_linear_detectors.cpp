// The linear exercises' detectors (labs/exercises/detectors/): answers built with one known mistake
// are diagnosed with that mistake's cause, and a right answer with none. Each wrong answer is made
// here, independently of the detectors' own replays where the mistake is a closed form (the
// inverse's, the polynomial's), and by the replay with the mistake where it is a whole elimination
// or iteration (the replay with no mistake being checked against numlab's solvers first).

#include <catch2/catch.hpp>
#include <Eigen/LU>
#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <utility>

#include "exercises/detectors/explains.hpp"
#include "exercises/detectors/gauss_seidel_detectors.hpp"
#include "exercises/detectors/gepp_detectors.hpp"
#include "exercises/detectors/inverse2x2_detectors.hpp"
#include "exercises/detectors/polyfit_detectors.hpp"
#include "exercises/nist_polynomial_sets.hpp"
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
  // The same "singular" with a trace that records the column where it stopped (row 0, pivot 1e-20),
  // as tests/exercises/mutants/.../gepp_no_pivoting.py does, and without that column.
  const d::GeppRun stopped = d::replay_gepp(T, ones, d::GeppMistake::no_pivoting);
  REQUIRE((stopped.singular && stopped.stopped_column == 0 && stopped.stopped_row == 0));
  d::GeppAnswer recorded = gepp_answer(stopped);
  recorded.trace->push_back({stopped.stopped_row, stopped.stopped_pivot});
  CHECK(gepp_cause(T, ones, recorded) == "no_pivoting");
  recorded.trace->back().pivot = 1.0;  // not the pivot it stopped at: no longer its trace
  CHECK(gepp_cause(T, ones, recorded) != "no_pivoting");
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

// GEPP written here with the swap of numpy rows, `A[k], A[p] = A[p], A[k]` (views): row p is copied
// over row k and kept. b's entries are swapped (numpy scalars), or copied too (a swap without a
// temporary). "singular" comes without a trace, as the corpus's student sends it.
d::GeppAnswer gepp_copying_swap(Eigen::MatrixXd a, Eigen::VectorXd b, bool copies_b) {
  const int n = static_cast<int>(a.rows());
  const double small = n * std::numeric_limits<double>::epsilon() * a.cwiseAbs().maxCoeff();
  d::GeppAnswer answer;
  std::vector<d::GeppTraceEntry> trace;
  for (int k = 0; k < n; ++k) {
    Eigen::Index p = 0;
    a.col(k).tail(n - k).cwiseAbs().maxCoeff(&p);
    p += k;
    a.row(k) = a.row(p);
    if (copies_b) {
      b(k) = b(p);
    } else {
      std::swap(b(k), b(p));
    }
    if (std::abs(a(k, k)) <= small) {
      answer.singular = true;
      return answer;
    }
    trace.push_back({p, a(k, k)});
    for (int i = k + 1; i < n; ++i) {
      const double l = a(i, k) / a(k, k);
      a.row(i) -= l * a.row(k);
      b(i) -= l * b(k);
    }
  }
  Eigen::VectorXd x(n);
  for (int i = n - 1; i >= 0; --i) x(i) = (b(i) - a.row(i).tail(n - 1 - i).dot(x.tail(n - 1 - i))) / a(i, i);
  answer.x = x;
  answer.trace = trace;
  return answer;
}

TEST_CASE("gepp detectors: a row swap that copies row p over row k (numpy row views) is a partial row swap") {
  for (const auto& [n, seed] : {std::pair{3, 7u}, std::pair{8, 11u}}) {
    const auto system = numlab::linalg::generate_system("random", n, seed);
    for (const bool copies_b : {false, true}) {
      INFO("n = " << n << ", seed " << seed << ", b copied too: " << copies_b);
      const d::GeppAnswer answer = gepp_copying_swap(system.A, system.b, copies_b);
      REQUIRE(answer.singular);  // the copied row is eliminated to 0: a zero pivot later on
      CHECK(gepp_cause(system.A, system.b, answer) == "partial_row_swap");
    }
  }
  // Where no row is swapped, the copy changes nothing and nothing is blamed.
  const Eigen::MatrixXd dominant = numlab::linalg::diagonally_dominant_matrix(6, 5).transpose();
  const Eigen::VectorXd b = dominant * Eigen::VectorXd::Ones(6);
  CHECK(gepp_cause(dominant, b, gepp_copying_swap(dominant, b, false)) == "(none)");
}

TEST_CASE("explains: agreement to less than three digits is no evidence, however far numlab's answer lies") {
  // A replay on Hilbert(10) (tolerance 100 n kappa eps ~ 7.7) that lies 4.9e11 from numlab's x.
  CHECK_FALSE(d::explains(1.0, 4.9e11, 7.7, 1e-2));
  CHECK_FALSE(d::explains(2e-3, 4.9e11, 7.7, 1e-2));
  CHECK(d::explains(5e-4, 4.9e11, 7.7, 1e-2));
  CHECK_FALSE(d::explains(1e-10, 1e-3, 1e-8, 1e-2));  // the mistake does not change the answer
  CHECK_FALSE(d::explains(5e-4, 1e-2, 1e-2, 1e-3));   // not a hundred times closer to the replay
}

// A student's GEPP whose pivot search looks at rows k+1 ... n-1 only, written here on its own.
d::GeppAnswer gepp_search_below_diagonal(Eigen::MatrixXd a, Eigen::VectorXd b) {
  const int n = static_cast<int>(a.rows());
  std::vector<d::GeppTraceEntry> trace;
  for (int k = 0; k < n; ++k) {
    int p = k;
    if (k + 1 < n) a.col(k).tail(n - k - 1).cwiseAbs().maxCoeff(&p), p += k + 1;
    a.row(k).swap(a.row(p));
    std::swap(b(k), b(p));
    trace.push_back({p, a(k, k)});
    for (int i = k + 1; i < n; ++i) {
      const double l = a(i, k) / a(k, k);
      a.row(i) -= l * a.row(k);
      b(i) -= l * b(k);
    }
  }
  d::GeppAnswer answer;
  answer.x = a.triangularView<Eigen::Upper>().solve(b);
  answer.trace = trace;
  return answer;
}

TEST_CASE("gepp detectors: a pivot search that skips the diagonal row is named") {
  int differed = 0;
  for (const auto& [n, seed] : {std::pair{3, 7u}, std::pair{8, 11u}, std::pair{50, 3u}}) {
    INFO("n = " << n << ", seed " << seed);
    const auto system = numlab::linalg::generate_system("random", n, seed);
    const d::GeppAnswer answer = gepp_search_below_diagonal(system.A, system.b);
    const d::GeppRun right = d::replay_gepp(system.A, system.b, d::GeppMistake::none);
    bool same_rows = true;  // where the diagonal never held the largest |a_ik|, the mistake changes nothing
    for (std::size_t k = 0; k < right.rows.size(); ++k) same_rows = same_rows && (*answer.trace)[k].row == right.rows[k];
    const auto diagnosis = d::diagnose_gepp(system.A, system.b, numlab::linalg::condition_estimate(system.A), answer);
    if (same_rows) {
      CHECK(cause_of(diagnosis) == "(none)");
    } else {
      CHECK(cause_of(diagnosis) == "pivot_search_skips_diagonal");
      if (diagnosis) CHECK_THAT(diagnosis->evidence, Catch::Matchers::Contains("the search starts at row k"));
    }
    differed += same_rows ? 0 : 1;
  }
  CHECK(differed >= 2);  // the mistake shows on the 8x8 and the 50x50
}

TEST_CASE("gepp detectors: \"singular\" for a well-scaled matrix whose entries are all tiny is an absolute threshold") {
  // Diagonally dominant by columns (GEPP swaps no row), times 2^-70: max|a_ij| ~ 1e-20.
  const Eigen::MatrixXd dominant = numlab::linalg::diagonally_dominant_matrix(6, 5).transpose();
  const d::GeppRun unscaled = d::replay_gepp(dominant, dominant * Eigen::VectorXd::Ones(6), d::GeppMistake::none);
  for (std::size_t k = 0; k < unscaled.rows.size(); ++k) REQUIRE(unscaled.rows[k] == static_cast<int>(k));
  const Eigen::MatrixXd tiny = std::ldexp(1.0, -70) * dominant;
  REQUIRE(tiny.cwiseAbs().maxCoeff() < 1e-18);
  const Eigen::VectorXd b = tiny * Eigen::VectorXd::Ones(6);
  d::GeppAnswer singular;
  singular.singular = true;
  CHECK(gepp_cause(tiny, b, singular) == "absolute_singular_threshold");
  // The right x (x = 1, as for the unscaled system: the scaling is exact) has no diagnosis.
  d::GeppAnswer solved;
  solved.x = Eigen::VectorXd::Ones(6);
  CHECK(gepp_cause(tiny, b, solved) == "(none)");
  // Entries of order 1e-3: no plausible fixed threshold is above its pivots, and no cause is named.
  const Eigen::MatrixXd small = 1e-3 * dominant;
  CHECK(gepp_cause(small, small * Eigen::VectorXd::Ones(6), singular) == "(none)");
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

// Gauss-Seidel written here, with the stop test on a residual in place of the update: of the swept
// system (c - M x) or of A x = b itself, in the inf-norm or the 2-norm.
d::GaussSeidelAnswer gs_residual_stop(const d::GaussSeidelProblem& p, bool of_original, bool two_norm) {
  const Eigen::MatrixXd M = p.normal_equations ? Eigen::MatrixXd(p.A.transpose() * p.A) : p.A;
  const Eigen::VectorXd c = p.normal_equations ? Eigen::VectorXd(p.A.transpose() * p.b) : p.b;
  Eigen::VectorXd x = p.x0;
  d::GaussSeidelAnswer answer{"max_iterations", 0, x, std::vector<d::GaussSeidelSweep>{}};
  double first = -1.0;
  for (int count = 1; count <= p.max_iterations; ++count) {
    const Eigen::VectorXd old = x;
    for (Eigen::Index i = 0; i < x.size(); ++i) {
      double sum = c(i);
      for (Eigen::Index j = 0; j < x.size(); ++j) {
        if (j != i) sum -= M(i, j) * x(j);
      }
      x(i) = sum / M(i, i);
    }
    const double update = (x - old).cwiseAbs().maxCoeff();
    if (first < 0.0) first = update;
    answer.trace->push_back({x, update});
    answer.iterations = count;
    answer.x = x;
    const Eigen::VectorXd r = of_original ? Eigen::VectorXd(p.b - p.A * x) : Eigen::VectorXd(c - M * x);
    if ((two_norm ? r.norm() : r.cwiseAbs().maxCoeff()) <= p.tolerance) {
      answer.status = "converged";
      break;
    }
    if (update > 1e8 * std::max(first, p.tolerance)) {
      answer.status = "diverged";
      break;
    }
  }
  return answer;
}

TEST_CASE("gauss-seidel detectors: a stop test on the residual, of M x = c or of A x = b, in either norm") {
  using d::StopRule;
  using d::SweepKind;
  using d::SweptSystem;
  const auto from_above = gs_problem(numlab::linalg::diagonally_dominant_matrix(10, 3), false, 1e-9, 200, 10.0);
  const auto normal_random = gs_problem(numlab::linalg::random_matrix(4, 8), true, 1e-10, 5000);
  for (const auto* p : {&from_above, &normal_random}) {
    const d::GaussSeidelRun numlab_run =
        d::replay_gauss_seidel(*p, SweptSystem::asked, SweepKind::gauss_seidel, StopRule::stated);
    for (const bool of_original : {false, true}) {
      for (const bool two_norm : {false, true}) {
        for (const bool with_trace : {true, false}) {
          d::GaussSeidelAnswer answer = gs_residual_stop(*p, of_original, two_norm);
          INFO("normal equations: " << p->normal_equations << ", residual of A x = b: " << of_original
                                    << ", 2-norm: " << two_norm << ", trace: " << with_trace << ", sweeps "
                                    << answer.iterations << " (numlab's " << numlab_run.sweeps() << ")");
          if (!with_trace) answer.trace.reset();
          // A residual test that ends where numlab's ends changes nothing and is not blamed; without
          // a trace, one sweep more or less is not evidence enough (x agrees to the tolerance).
          const long long apart = std::abs(answer.iterations - numlab_run.sweeps());
          const bool changes = answer.status != numlab_run.status || apart > (with_trace ? 0 : 1);
          CHECK(cause_of(d::diagnose_gauss_seidel(*p, answer)) == (changes ? "stop_test" : "(none)"));
        }
      }
    }
  }
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

// 12 points of 1.5 - 2 x + 0.5 x^3 + 0.1 sin(7 x) on [-1, 1.75].
std::pair<Eigen::VectorXd, Eigen::VectorXd> noisy_cubic() {
  Eigen::VectorXd x(12), y(12);
  for (int i = 0; i < 12; ++i) {
    x(i) = -1.0 + 0.25 * i;
    y(i) = 1.5 - 2.0 * x(i) + 0.5 * std::pow(x(i), 3) + 0.1 * std::sin(7.0 * x(i));
  }
  return {x, y};
}

TEST_CASE("polyfit detectors: each wrong fit is named by its own cause") {
  const auto [x, y] = noisy_cubic();
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

double column_weighted(const Eigen::VectorXd& got, const Eigen::VectorXd& h, const Eigen::VectorXd& x, int degree) {
  const Eigen::VectorXd S = numlab::fitting::vandermonde(x, degree).colwise().norm().transpose();
  return (S.array() * (got - h).array()).abs().maxCoeff() / (S.array() * h.array()).abs().maxCoeff();
}

// The check's tolerance: 10 m eps (kappa + kappa^2 tan theta), kappa of V with unit columns.
double check_allowance(const Eigen::VectorXd& x, const Eigen::VectorXd& y, const Eigen::VectorXd& h) {
  const Eigen::MatrixXd V = numlab::fitting::vandermonde(x, static_cast<int>(h.size()) - 1);
  const double kappa = numlab::fitting::two_norm_condition(numlab::fitting::unit_columns(V));
  const double tan_theta = (y - V * h).norm() / (V * h).norm();
  return 10.0 * static_cast<double>(x.size()) * std::numeric_limits<double>::epsilon() *
         (kappa + kappa * kappa * tan_theta);
}

TEST_CASE("polyfit detectors: the scales not divided out, a change of variable solved from the coefficients") {
  const auto [x, y] = noisy_cubic();
  const int D = 3;
  const d::PolyfitProblem p{x, y, D, least_squares(x, y, D), 1e-12};
  const Eigen::MatrixXd V = numlab::fitting::vandermonde(x, D);
  // Columns scaled by their 2-norm, their largest |entry| or their 1-norm, the solution not divided
  // by the scales (or multiplied by them once more).
  const Eigen::VectorXd two = V.colwise().norm().transpose(), largest = V.cwiseAbs().colwise().maxCoeff().transpose(),
                        one = V.cwiseAbs().colwise().sum().transpose();
  CHECK(polyfit_cause(p, p.expected.cwiseProduct(two)) == "missing_unscale");
  CHECK(polyfit_cause(p, p.expected.cwiseProduct(largest)) == "missing_unscale");
  CHECK(polyfit_cause(p, p.expected.cwiseProduct(one)) == "missing_unscale");
  CHECK(polyfit_cause(p, p.expected.cwiseProduct(two).cwiseProduct(two)) == "missing_unscale");
  // A fit in t = (x - 0.3) / 1.7, a centre and scale none of the data's statistics give.
  CHECK(polyfit_cause(p, least_squares((x.array() - 0.3) / 1.7, y, D)) == "missing_unscale");
  // Degree 1: any two coefficients are some line's in some t = (x - c) / s; nothing is guessed.
  const d::PolyfitProblem line{x, y, 1, least_squares(x, y, 1), 1e-12};
  CHECK(polyfit_cause(line, least_squares((x.array() - 0.3) / 1.7, y, 1)) == "(none)");
}

TEST_CASE("polyfit detectors: the unstable methods, told apart by what they lose on the same data") {
  // The normal equations from power sums, built and solved here (Eigen's LU): x = 0 ... 20, y the
  // polynomial with all 8 coefficients 1 (exact in double).
  Eigen::VectorXd x(21), y(21);
  for (int i = 0; i < 21; ++i) {
    x(i) = i;
    y(i) = 0.0;
    for (int k = 7; k >= 0; --k) y(i) = y(i) * x(i) + 1.0;
  }
  const Eigen::VectorXd ones = Eigen::VectorXd::Ones(8);
  Eigen::MatrixXd N(8, 8);
  Eigen::VectorXd r(8);
  for (int j = 0; j <= 7; ++j) {
    r(j) = (x.array().pow(j) * y.array()).sum();
    for (int k = 0; k <= 7; ++k) N(j, k) = x.array().pow(j + k).sum();
  }
  const Eigen::VectorXd normal = N.partialPivLu().solve(r);
  const d::PolyfitProblem wampler_like{x, y, 7, ones, check_allowance(x, y, ones)};
  REQUIRE(column_weighted(normal, ones, x, 7) > wampler_like.allowed);  // it fails the check
  CHECK(polyfit_cause(wampler_like, normal) == "normal_equations_wrong");
  // numpy.linalg.lstsq(V, y) on Pontius with V's columns as they are (numpy 1.24.2, OpenBLAS).
  int found = 0;
  for (const numlab::fitting::DataSet& set : numlab::exercises::nist_polynomial_sets()) {
    if (set.name != "Pontius") continue;
    ++found;
    const Eigen::VectorXd certified = Eigen::Map<const Eigen::VectorXd>(set.certified->parameters.data(), 3);
    const d::PolyfitProblem pontius{set.x, set.y, 2, certified, check_allowance(set.x, set.y, certified)};
    const Eigen::VectorXd lstsq = (Eigen::VectorXd(3) << 0.0006735661810141453, 7.320591602278815e-07,
                                   -3.1608187450393667e-15).finished();
    REQUIRE(column_weighted(lstsq, certified, set.x, 2) > pontius.allowed);
    CHECK(polyfit_cause(pontius, lstsq) == "unscaled_vandermonde");
    // The stable fit (QR of V with unit columns) passes and has no diagnosis.
    CHECK(polyfit_cause(pontius, least_squares(set.x, set.y, 2)) == "(none)");
  }
  CHECK(found == 1);
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
