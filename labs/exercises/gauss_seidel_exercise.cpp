// The `gauss-seidel` exercise: the student's Gauss-Seidel sweeps, plain (M = A) or on seed 001's
// normal equations (M = A^T A, c = A^T b), checked against numlab's GaussSeidel stepper (status,
// sweep count and the trace, sweep by sweep) and GSL LU or Eigen's QR least squares (x).

#include <Eigen/Core>
#include <cmath>
#include <Eigen/QR>
#include <fmt/format.h>
#include <optional>

#include "exercises/detectors/gauss_seidel_detectors.hpp"
#include "exercises/exercise_list.hpp"
#include "exercises/linear_checks.hpp"
#include "exercises/numbers.hpp"
#include "exercises/reply_fields.hpp"
#include "exercises/session.hpp"
#include "exercises/task_texts.hpp"
#include "numlab/linalg/gauss_seidel.hpp"
#include "numlab/linalg/gsl_reference.hpp"
#include "numlab/linalg/matrix_generators.hpp"
#include "numlab/linalg/measures.hpp"

namespace numlab::exercises {

namespace {

using linear::eps;
using linear::sci;

struct Problem {
  std::string label;
  Eigen::MatrixXd A;
  Eigen::VectorXd b;
  Eigen::VectorXd x0;
  double tolerance = 1e-9;
  int max_iterations = 100;
  bool normal_equations = false;
};

Problem problem(std::string label, Eigen::MatrixXd A, bool normal_equations, double tolerance, int max_iterations,
                double start = 0.0) {
  Problem p;
  p.label = std::move(label);
  p.b = A * Eigen::VectorXd::Ones(A.cols());
  p.x0 = Eigen::VectorXd::Constant(A.cols(), start);
  p.A = std::move(A);
  p.tolerance = tolerance;
  p.max_iterations = max_iterations;
  p.normal_equations = normal_equations;
  return p;
}

nlohmann::json request_for(const Problem& p) {
  return {{"A", to_json(p.A)},         {"b", to_json(p.b)},
          {"x0", to_json(p.x0)},       {"tolerance", p.tolerance},
          {"max_iterations", p.max_iterations}, {"normal_equations", p.normal_equations}};
}

class SweepRecorder final : public linalg::GaussSeidel<>::Observer {
 public:
  StepControl on_step(const linalg::GaussSeidel<>& stepper, const linalg::SweepRecord& record) override {
    xs.push_back(stepper.x());
    updates.push_back(record.step_norm);
    return StepControl::proceed;
  }
  std::vector<Eigen::VectorXd> xs;
  std::vector<double> updates;
};

// numlab's stepper on the system the request asks to sweep, and the exact solution.
struct Reference {
  Eigen::MatrixXd M;  // A, or A^T A
  Eigen::VectorXd c;  // b, or A^T b
  Status status = Status::running;
  int sweeps = 0;
  std::vector<Eigen::VectorXd> xs;  // x after each sweep
  std::vector<double> updates;      // ||x_k - x_{k-1}||_inf
  Eigen::VectorXd exact;            // GSL LU (square A) or Eigen's QR least squares (A^T A x = A^T b)
  double error = 0.0;               // numlab's relative error against `exact`
  double kappa = 0.0;               // kappa_1 of M (estimate)
};

Reference reference_for(const Problem& p, linear::ReferenceTimes& times) {
  Reference reference;
  reference.M = p.normal_equations ? Eigen::MatrixXd(p.A.transpose() * p.A) : p.A;
  reference.c = p.normal_equations ? Eigen::VectorXd(p.A.transpose() * p.b) : p.b;
  linalg::GaussSeidelOptions options;
  options.system = linalg::GaussSeidelOptions::System::plain;  // M and c are already the swept system
  options.tolerance = p.tolerance;
  options.max_iterations = p.max_iterations;
  linalg::GaussSeidel<> stepper(options);
  SweepRecorder recorder;
  stepper.set_observer(&recorder);
  stepper.start(reference.M, reference.c, p.x0);
  while (stepper.step()) {
  }
  reference.status = stepper.status();
  reference.sweeps = stepper.iterations();
  reference.xs = recorder.xs;
  reference.updates = recorder.updates;
  if (p.A.rows() == p.A.cols()) {
    linalg::GslLu gsl(static_cast<int>(p.A.rows()));
    reference.exact = gsl.solve(p.A, p.b).x;
    times.time("GSL LU", [&] { gsl.solve(p.A, p.b); });
  } else {
    reference.exact = p.A.colPivHouseholderQr().solve(p.b);
  }
  reference.error = linear::relative_error(stepper.x(), reference.exact);
  reference.kappa = linalg::condition_estimate(reference.M);
  times.time("numlab Gauss-Seidel", [&] {
    linalg::GaussSeidel<> timed(options);
    timed.solve(reference.M, reference.c, p.x0);
  });
  return reference;
}

// The most specific known mistake that explains the reply (gauss_seidel_detectors.hpp); a field
// that does not read is left out of the evidence.
std::optional<Diagnosis> diagnosis_for(const Problem& p, const nlohmann::json& reply) {
  detectors::GaussSeidelAnswer answer;
  try {
    answer.status = string_field(reply, "status");
    answer.iterations = integer_field(reply, "iterations");
  } catch (const ReplyError&) {
    return std::nullopt;
  }
  try {
    answer.x = vector_field(reply, "x", p.A.cols());
  } catch (const ReplyError&) {
  }
  try {
    if (const nlohmann::json* trace = linear::optional_trace(reply)) {
      std::vector<detectors::GaussSeidelSweep> sweeps;
      for (std::size_t s = 0; s < trace->size(); ++s) {
        const nlohmann::json& entry = linear::trace_entry(*trace, s);
        sweeps.push_back({vector_field(entry, "x", p.A.cols()), number_field(entry, "update_inf")});
      }
      answer.trace = std::move(sweeps);
    }
  } catch (const ReplyError&) {
  }
  return detectors::diagnose_gauss_seidel({p.A, p.b, p.x0, p.tolerance, p.max_iterations, p.normal_equations}, answer);
}

std::string status_name(Status status) { return std::string(numlab::to_string(status)); }

const char* const stop_test_hint =
    "the stop test is max_i |x_i(new) - x_i(old)| <= tolerance * max(1, max_i |x_i(new)|), with the absolute value";

const char* const normal_equations_hint =
    "with normal_equations true, sweep M = A^T A and c = A^T b, not A and b (plain GS may diverge on A)";

// The status and sweep count numlab's stepper reached, in words.
std::string numlab_ending(const Problem& p, const Reference& reference) {
  const std::string system = p.normal_equations ? "on A^T A" : "on A";
  switch (reference.status) {
    case Status::converged: return fmt::format("numlab's Gauss-Seidel {} converges in {} sweeps", system, reference.sweeps);
    case Status::diverged:
      return fmt::format("numlab's Gauss-Seidel {} diverges: update_inf reaches {} at sweep {}, 1e8 times the first "
                         "sweep's {}",
                         system, sci(reference.updates.back()), reference.sweeps, sci(reference.updates.front()));
    default:
      return fmt::format("numlab's Gauss-Seidel {} ends with {} after {} sweeps", system, status_name(reference.status),
                         reference.sweeps);
  }
}

// numlab's reply to p, for the replay file: its status, sweeps and last x (the check allows a sweep
// more or less, and x to numlab's accuracy).
Expectation expectation(const Problem& p, const Reference& reference) {
  nlohmann::json reply = {{"status", std::string(to_string(reference.status))}, {"iterations", reference.sweeps}};
  if (!reference.xs.empty()) reply["x"] = to_json(reference.xs.back());
  return {p.label, reply,
          numlab_ending(p, reference) + " (your sweeps within 1 of it; x and a trace sweep by sweep as numlab's, to "
                                        "100*sweep*n*eps*max(1,|x|))"};
}

// Problem p asked: numlab's reference (timed into `times`), the student's reply, and numlab's
// expectation sent beside it (results.json shows it by the reply).
struct Asked {
  Reference reference;
  nlohmann::json reply;
};
Asked ask_problem(Session& session, const Problem& p, linear::ReferenceTimes& times) {
  Reference reference = reference_for(p, times);
  nlohmann::json reply = session.ask(request_for(p));
  session.expect(expectation(p, reference));
  return {std::move(reference), std::move(reply)};
}

// Tasks 1 and 3: converged, in numlab's number of sweeps (+-1 for rounding at the stop test), to
// numlab's accuracy.
Verdict converges_accurately(Session& session, const std::vector<Problem>& problems) {
  linear::ReferenceTimes times;
  for (const Problem& p : problems) {
    const auto [reference, reply] = ask_problem(session, p, times);
    const std::string status = string_field(reply, "status");
    const long long sweeps = integer_field(reply, "iterations");
    if (status != "converged") {
      return Verdict::fail(fmt::format("{}: status \"{}\" after {} sweeps; {}", p.label, status, sweeps,
                                       numlab_ending(p, reference)),
                           diagnosis_for(p, reply),
                           p.normal_equations && status == "diverged" ? normal_equations_hint : stop_test_hint,
                           times.medians());
    }
    if (std::abs(sweeps - reference.sweeps) > 1) {
      return Verdict::fail(fmt::format("{}: converged after {} sweeps; {} with the same stop test (allowed +-1)",
                                       p.label, sweeps, numlab_ending(p, reference)),
                           diagnosis_for(p, reply), stop_test_hint, times.medians());
    }
    const Eigen::VectorXd x = vector_field(reply, "x", p.A.cols());
    const double error = linear::relative_error(x, reference.exact);
    const double floor = std::max({reference.error, p.tolerance, p.A.cols() * reference.kappa * eps});
    const double allowed = 10.0 * floor;
    if (!(error <= allowed)) {
      return Verdict::fail(fmt::format("{}: x differs from {} by {} (relative, inf-norm), allowed {} (10 x max(numlab's "
                                       "Gauss-Seidel error {}, tolerance, n*kappa*eps))",
                                       p.label, p.A.rows() == p.A.cols() ? "GSL LU" : "Eigen's QR least squares",
                                       sci(error), sci(allowed), sci(reference.error)),
                           diagnosis_for(p, reply), p.normal_equations ? normal_equations_hint : "", times.medians());
    }
  }
  return Verdict::pass(times.medians());
}

// Task 2: an ending other than convergence, as numlab's stepper reaches it.
Verdict ends_without_converging(Session& session, const Problem& p) {
  linear::ReferenceTimes times;
  const auto [reference, reply] = ask_problem(session, p, times);
  const std::string status = string_field(reply, "status");
  const long long sweeps = integer_field(reply, "iterations");
  if (reference.status == Status::max_iterations) {
    if (status != "max_iterations" || sweeps != reference.sweeps) {
      return Verdict::fail(fmt::format("{}: status \"{}\" after {} sweeps; {} (max_iterations = {})", p.label, status,
                                       sweeps, numlab_ending(p, reference), p.max_iterations),
                           diagnosis_for(p, reply),
                           "after each sweep: converged if the stop test passes, else max_iterations once the sweep "
                           "count reaches max_iterations",
                           times.medians());
    }
  } else if (status != "diverged" && status != "max_iterations") {
    return Verdict::fail(fmt::format("{}: status \"{}\" after {} sweeps; expected \"diverged\" or \"max_iterations\": {}",
                                     p.label, status, sweeps, numlab_ending(p, reference)),
                         diagnosis_for(p, reply),
                         status == "converged" ? std::string("a divergent iteration reported as converged: ") +
                                                     stop_test_hint
                                               : "",
                         times.medians());
  }
  return Verdict::pass(times.medians());
}

// One Gauss-Seidel sweep of M x = c from `x`, in the given order; Jacobi uses only the old values.
Eigen::VectorXd sweep(const Eigen::MatrixXd& M, const Eigen::VectorXd& c, Eigen::VectorXd x, bool jacobi) {
  const Eigen::VectorXd old = x;
  for (Eigen::Index i = 0; i < x.size(); ++i) {
    const Eigen::VectorXd& used = jacobi ? old : x;
    x(i) = (c(i) - M.row(i).dot(used) + M(i, i) * used(i)) / M(i, i);
  }
  return x;
}

// The known mistake that explains a departing sweep: Jacobi, or the plain system where A^T A was asked.
std::string departure_hint(const Problem& p, const Reference& reference, std::size_t s, const Eigen::VectorXd& yours,
                           double allowed) {
  const Eigen::VectorXd& previous = s == 0 ? p.x0 : reference.xs[s - 1];
  if (p.normal_equations && p.A.rows() == p.A.cols() &&
      (yours - sweep(p.A, p.b, previous, false)).cwiseAbs().maxCoeff() <= allowed) {
    return "you swept A x = b: " + std::string(normal_equations_hint);
  }
  if ((yours - sweep(reference.M, reference.c, previous, true)).cwiseAbs().maxCoeff() <= allowed) {
    return "this is a Jacobi sweep: in Gauss-Seidel equation i uses the new x_0 ... x_{i-1} of the same sweep";
  }
  return "";
}

Verdict missing_trace(const Problem& p, const linear::ReferenceTimes& times) {
  return Verdict::fail(p.label + ": no trace in the reply", "add \"trace\": one {\"x\", \"update_inf\"} per sweep",
                       times.medians());
}

// The student's sweeps beside numlab's for trace.html (trace_comparison.hpp); the check's tolerance
// on x at the parting sweep.
TraceComparison sweeps_side_by_side(const Problem& p, const Reference& reference, const nlohmann::json& trace,
                                    std::size_t parting, double largest) {
  const double allowed = 100.0 * static_cast<double>(parting + 1) * static_cast<double>(p.A.cols()) * eps * largest;
  return sweep_comparison(p.label, trace, reference.xs, reference.updates, parting, allowed);
}

Verdict with_trace(Verdict verdict, TraceComparison comparison) {
  verdict.trace = std::move(comparison);
  return verdict;
}

// Task 4: the trace, sweep by sweep, against numlab's stepper.
Verdict sweeps_like_numlab(Session& session, const std::vector<Problem>& problems) {
  linear::ReferenceTimes times;
  for (const Problem& p : problems) {
    const auto [reference, reply] = ask_problem(session, p, times);
    const nlohmann::json* trace = linear::optional_trace(reply);
    if (trace == nullptr) return missing_trace(p, times);
    double largest = 1.0;
    for (const Eigen::VectorXd& x : reference.xs) largest = std::max(largest, x.cwiseAbs().maxCoeff());
    const double n = static_cast<double>(p.A.cols());
    for (std::size_t s = 0; s < reference.xs.size(); ++s) {
      if (s >= trace->size()) {
        return with_trace(Verdict::fail(fmt::format("{}: your trace ends at sweep {}; {}: at sweep {} its update_inf {} "
                                                    "is above tolerance*max(1,|x|)",
                                                    p.label, trace->size(), numlab_ending(p, reference), s,
                                                    s == 0 ? std::string("-") : sci(reference.updates[s - 1])),
                                        diagnosis_for(p, reply), stop_test_hint, times.medians()),
                          sweeps_side_by_side(p, reference, *trace, s, largest));
      }
      const nlohmann::json& entry = linear::trace_entry(*trace, s);
      const Eigen::VectorXd x = vector_field(entry, "x", p.A.cols());
      const double update = number_field(entry, "update_inf");
      const double allowed = 100.0 * static_cast<double>(s + 1) * n * eps * largest;
      const Eigen::VectorXd& expected = reference.xs[s];
      Eigen::Index i = 0;
      const double difference = (x - expected).cwiseAbs().maxCoeff(&i);
      if (difference > allowed) {
        return with_trace(Verdict::fail(fmt::format("{}: sweep {}: x[{}] = {}, numlab's sweep gives {} ({}; allowed {} "
                                                    "= 100*sweep*n*eps*max(1,|x|))",
                                                    p.label, s + 1, i, digits17(x(i)), digits17(expected(i)),
                                                    exercises::difference(x(i), expected(i)), sci(allowed)),
                                        diagnosis_for(p, reply), departure_hint(p, reference, s, x, allowed),
                                        times.medians()),
                          sweeps_side_by_side(p, reference, *trace, s, largest));
      }
      if (std::abs(update - reference.updates[s]) > 2.0 * allowed) {
        return with_trace(Verdict::fail(fmt::format("{}: sweep {}: update_inf {}, numlab's {} ({}; allowed difference {})",
                                                    p.label, s + 1, digits17(update), digits17(reference.updates[s]),
                                                    exercises::difference(update, reference.updates[s]), sci(2.0 * allowed)),
                                        diagnosis_for(p, reply), "update_inf is max_i |x_i(new) - x_i(old)| over the sweep",
                                        times.medians()),
                          sweeps_side_by_side(p, reference, *trace, s, largest));
      }
    }
    if (trace->size() > reference.xs.size()) {
      return with_trace(Verdict::fail(fmt::format("{}: your trace goes on to sweep {}; {} (status {} there)", p.label,
                                                  trace->size(), numlab_ending(p, reference), status_name(reference.status)),
                                      diagnosis_for(p, reply), stop_test_hint, times.medians()),
                        sweeps_side_by_side(p, reference, *trace, reference.xs.size(), largest));
    }
  }
  return Verdict::pass(times.medians());
}

// Task 1 (with the trace): the sweep a "converged" reply stopped at passes the stop test.
Verdict converged_claims_hold(Session& session, const std::vector<Problem>& problems) {
  linear::ReferenceTimes times;
  for (const Problem& p : problems) {
    const auto [reference, reply] = ask_problem(session, p, times);
    const nlohmann::json* trace = linear::optional_trace(reply);
    if (trace == nullptr) return missing_trace(p, times);
    if (string_field(reply, "status") != "converged") continue;
    if (trace->empty()) {
      return Verdict::fail(p.label + ": status converged with an empty trace; " + numlab_ending(p, reference),
                           diagnosis_for(p, reply), "", times.medians());
    }
    const std::size_t last = trace->size() - 1;
    const Eigen::VectorXd x = vector_field(linear::trace_entry(*trace, last), "x", p.A.cols());
    const Eigen::VectorXd before = last == 0 ? p.x0 : vector_field(linear::trace_entry(*trace, last - 1), "x", p.A.cols());
    const Eigen::VectorXd change = x - before;
    const double update = change.cwiseAbs().maxCoeff();
    const double threshold = p.tolerance * std::max(1.0, x.cwiseAbs().maxCoeff());
    if (update > threshold) {
      const bool signed_test = change.maxCoeff() < p.tolerance;
      return Verdict::fail(fmt::format("{}: sweep {}: update_inf {} reported as converged with tolerance {}{}; {}",
                                       p.label, last + 1, sci(update), sci(p.tolerance),
                                       signed_test ? "; your stop test lets a negative change pass" : "",
                                       numlab_ending(p, reference)),
                           diagnosis_for(p, reply), stop_test_hint, times.medians());
    }
  }
  return Verdict::pass(times.medians());
}

Eigen::MatrixXd overdetermined(unsigned seed) { return linalg::random_matrix(8, seed).leftCols(3); }

// Whether numlab's Gauss-Seidel converges on `p` within half its max_iterations (a variant's matrix
// stays one the check's "converges" holds for, with room to spare).
bool converges_with_room(const Problem& p) {
  linear::ReferenceTimes unused;
  const Reference reference = reference_for(p, unused);
  return reference.status == Status::converged && 2 * reference.sweeps <= p.max_iterations;
}

// A random matrix's seed in a label, with a variant (its base seed without one is the label as always).
std::string seeded(const Variant& variant, const std::string& label, const std::string& generator, unsigned seed) {
  return variant.active() ? fmt::format("{} ({} seed {})", label, generator, seed) : label;
}

// Every random matrix (and the start above the solution) from the variant; a variant's matrices are
// re-drawn until numlab's stepper converges with room to spare where the check says it converges.
std::vector<Check> gauss_seidel_battery(const Variant& variant) {
  const unsigned dominant_seed = variant.seed(3);
  const Eigen::MatrixXd dominant = linalg::diagonally_dominant_matrix(10, dominant_seed);
  const Eigen::MatrixXd diverging = linalg::gauss_seidel_divergence_example();
  const std::string dominant_label = seeded(variant, "diagonally dominant 10x10", "diagonally_dominant_matrix", dominant_seed);
  const Problem plain = problem(dominant_label + ", plain", dominant, false, 1e-10, 200);
  const double above = variant.active() ? std::round(variant.stream(10).uniform(5.0, 20.0) * 100.0) / 100.0 : 10.0;
  const Problem from_above = problem(fmt::format("{}, plain, x0 = {:g} (above the solution)", dominant_label, above),
                                     dominant, false, 1e-9, 200, above);
  const Problem normal_diverging = problem("[[1,2,4],[2,1,2],[4,2,1]], normal equations", diverging, true, 1e-10, 2000);
  const unsigned random_seed = variant.seed_where(8, [](unsigned s) {
    return converges_with_room(problem("", linalg::random_matrix(4, s), true, 1e-10, 5000));
  });
  const Problem normal_random =
      problem(seeded(variant, "random 4x4 (not symmetric), normal equations", "random_matrix", random_seed),
              linalg::random_matrix(4, random_seed), true, 1e-10, 5000);
  const unsigned tall_seed = variant.seed_where(
      21, [](unsigned s) { return converges_with_room(problem("", overdetermined(s), true, 1e-10, 500)); });
  const Problem normal_tall = problem(seeded(variant, "random 8x3 least squares, normal equations",
                                             "first 3 columns of random_matrix(8)", tall_seed),
                                      overdetermined(tall_seed), true, 1e-10, 500);
  // The same system with the solution 1000 (1, ..., 1): the stop test's max(1, |x|) now matters.
  Problem large = problem(dominant_label + ", plain, solution 1000 (1, ..., 1)", dominant, false, 1e-10, 200);
  large.b *= 1000.0;
  const Problem plain_diverging = problem("[[1,2,4],[2,1,2],[4,2,1]], plain", diverging, false, 1e-9, 100);
  const Problem capped = problem("Hilbert 6x6, normal equations, max_iterations = 25", linalg::hilbert_matrix(6), true,
                                 1e-12, 25);
  return {
      {"Gauss-Seidel converges on a diagonally dominant 10x10 system, in numlab's sweep count, to the accuracy its "
       "tolerance allows",
       1, [=](Session& s) { return converges_accurately(s, {plain}); }},
      {"Gauss-Seidel stops when the update is small, not when it is negative (x0 above the solution)", 1,
       [=](Session& s) { return converges_accurately(s, {from_above}); }},
      {"A converged claim passes the stop test on its last sweep's update (trace)", 1,
       [=](Session& s) { return converged_claims_hold(s, {from_above, plain, normal_tall}); }},
      {"The stop test is relative to |x|: a solution of size 1000 converges in numlab's sweep count", 1,
       [=](Session& s) { return converges_accurately(s, {large}); }},
      {"plain Gauss-Seidel on [[1,2,4],[2,1,2],[4,2,1]] (not diagonally dominant) ends diverged or max_iterations, "
       "never converged",
       2, [=](Session& s) { return ends_without_converging(s, plain_diverging); }},
      {"Gauss-Seidel stops with status max_iterations after exactly max_iterations sweeps when the tolerance is not met",
       2, [=](Session& s) { return ends_without_converging(s, capped); }},
      {"Gauss-Seidel on the normal equations A^T A x = A^T b converges on matrices that are not diagonally dominant "
       "([[1,2,4],[2,1,2],[4,2,1]], on which plain GS diverges; a random 4x4)",
       3, [=](Session& s) { return converges_accurately(s, {normal_diverging, normal_random}); }},
      {"Gauss-Seidel on the normal equations solves an overdetermined 8x3 least-squares system", 3,
       [=](Session& s) { return converges_accurately(s, {normal_tall}); }},
      {"Gauss-Seidel's sweeps (trace) match numlab's stepper, sweep by sweep", 4,
       [=](Session& s) { return sweeps_like_numlab(s, {plain, normal_diverging, normal_tall}); }},
  };
}

}  // namespace

Exercise gauss_seidel_exercise() {
  Exercise exercise;
  exercise.name = "gauss-seidel";
  exercise.summary = "Gauss-Seidel sweeps, plain or on A^T A: status, sweep count, x and the sweep trace";
  exercise.task = task_text("gauss-seidel");
  exercise.stubs.python = "    raise NotImplementedError(\"not implemented: Gauss-Seidel (reply x, status, iterations)\")\n";
  exercise.stubs.cpp = "  throw std::runtime_error(\"not implemented: Gauss-Seidel (reply x, status, iterations)\");\n";
  exercise.stubs.octave = "  error('not implemented: Gauss-Seidel (reply x, status, iterations)');\n";
  exercise.battery = gauss_seidel_battery;
  return exercise;
}

}  // namespace numlab::exercises
