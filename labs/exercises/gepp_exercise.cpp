// The `gepp` exercise: the student's Gaussian elimination with partial pivoting, checked against
// GSL LU (x), numlab's GaussElimination stepper (the pivot trace and the singular verdict) and the
// matrix's condition number (the tolerances).

#include <Eigen/Core>
#include <cmath>
#include <fmt/format.h>
#include <optional>

#include "exercises/detectors/gepp_detectors.hpp"
#include "exercises/exercise_list.hpp"
#include "exercises/linear_checks.hpp"
#include "exercises/numbers.hpp"
#include "exercises/reply_fields.hpp"
#include "exercises/session.hpp"
#include "exercises/task_texts.hpp"
#include "numlab/linalg/gauss_elimination.hpp"
#include "numlab/linalg/gsl_reference.hpp"
#include "numlab/linalg/matrix_generators.hpp"
#include "numlab/linalg/measures.hpp"

namespace numlab::exercises {

namespace {

using linear::eps;
using linear::sci;

struct System {
  std::string label;
  Eigen::MatrixXd A;
  Eigen::VectorXd b;
};

// A random matrix's label names its seed, so that the failure can be made again by hand
// (numlab's generate_system(kind, n, seed)).
System generated(const std::string& label, std::string_view kind, int n, unsigned seed = 1) {
  linalg::GeneratedSystem system = linalg::generate_system(kind, n, seed);
  const bool random = kind == "random" || kind == "singular";
  return {random ? fmt::format("{}, seed {}", label, seed) : label, std::move(system.A), std::move(system.b)};
}

System given(const std::string& label, Eigen::MatrixXd A) {
  const Eigen::VectorXd b = A * Eigen::VectorXd::Ones(A.cols());
  return {label, std::move(A), b};
}

// Column k of numlab's elimination: the rows it could pivot on and the one it chose.
struct PivotChoice {
  int row;                    // 0-based, in the matrix as it stands at column k
  double pivot;               // a_kk after the swap
  Eigen::VectorXd candidates; // a_ik for i = k ... n-1, before the swap
};

class PivotRecorder final : public linalg::GaussElimination<>::Observer {
 public:
  explicit PivotRecorder(const Eigen::MatrixXd& A) : candidates_(A.col(0)) {}

  StepControl on_step(const linalg::GaussElimination<>& stepper, const linalg::EliminationRecord& record) override {
    if (record.event == linalg::EliminationEvent::row_swap) swapped_with_ = record.other_row;
    if (record.event != linalg::EliminationEvent::elimination) return StepControl::proceed;
    const int k = record.column;
    choices.push_back({swapped_with_ < 0 ? k : swapped_with_, record.value, candidates_});
    swapped_with_ = -1;
    const int n = stepper.size();
    if (k + 1 < n) candidates_ = stepper.reduced_matrix().col(k + 1).tail(n - k - 1);
    return StepControl::proceed;
  }

  std::vector<PivotChoice> choices;

 private:
  Eigen::VectorXd candidates_;
  int swapped_with_ = -1;
};

// What numlab's stepper and GSL make of one system.
struct Reference {
  int n = 0;
  bool singular = false;
  std::vector<PivotChoice> pivots;
  int stopped_column = 0;          // where numlab's GEPP stopped, when singular
  double stopped_pivot = 0.0;      // |pivot| there
  double negligible_pivot = 0.0;   // n * eps * max|a_ij|
  double smallest_pivot = 0.0;     // min |pivot| over the columns, when not singular
  double growth = 1.0;             // max(1, growth factor)
  double scale = 0.0;              // max|a_ij|
  double kappa = 0.0;              // kappa_1 estimate
  Eigen::VectorXd gsl_x;
};

Reference reference_for(const System& system, linear::ReferenceTimes& times) {
  Reference reference;
  reference.n = static_cast<int>(system.A.rows());
  linalg::GaussElimination<> stepper;
  PivotRecorder recorder(system.A);
  stepper.set_observer(&recorder);
  stepper.start(system.A, system.b);
  while (stepper.step()) {
  }
  const linalg::LinearResult<Eigen::Dynamic> result = stepper.result();
  reference.singular = result.status == Status::singular;
  reference.pivots = recorder.choices;
  reference.stopped_column = stepper.iterations();
  if (reference.singular) {
    reference.stopped_pivot = std::abs(stepper.reduced_matrix()(stepper.iterations(), stepper.iterations()));
  }
  reference.negligible_pivot = stepper.negligible_pivot();
  reference.smallest_pivot = std::numeric_limits<double>::infinity();
  for (const PivotChoice& choice : recorder.choices) {
    reference.smallest_pivot = std::min(reference.smallest_pivot, std::abs(choice.pivot));
  }
  if (!reference.singular) reference.growth = std::max(1.0, result.growth_factor);
  reference.scale = system.A.cwiseAbs().maxCoeff();
  reference.kappa = linalg::condition_estimate(system.A);
  linalg::GslLu gsl(reference.n);
  reference.gsl_x = gsl.solve(system.A, system.b).x;
  times.time("numlab GEPP", [&] { linalg::gauss_elimination<Eigen::Dynamic>(system.A, system.b); });
  times.time("GSL LU", [&] { gsl.solve(system.A, system.b); });
  return reference;
}

nlohmann::json request_for(const System& system) { return {{"A", to_json(system.A)}, {"b", to_json(system.b)}}; }

bool replied_singular(const nlohmann::json& reply) { return optional_status(reply) == std::optional<std::string>("singular"); }

std::string not_singular_message(const System& system, const Reference& reference) {
  return fmt::format("{}: you replied \"singular\"; numlab's GEPP solves it: its smallest |pivot| {} is above "
                     "n*eps*max|a_ij| = {}",
                     system.label, sci(reference.smallest_pivot), sci(reference.negligible_pivot));
}

const char* const singular_threshold_hint =
    "only a pivot with |pivot| <= n*eps*max|a_ij| (max over the original A), after the swap to the largest |a_ik|, "
    "means singular: without pivoting (or pivoting on the signed value) a tiny a_kk looks singular";

struct Departure {
  std::string message;
  std::string hint;
  std::size_t column = 0;  // where the trace departs (0-based)
};

// True when every entry of the trace pivots on its own column's row: no row was ever swapped in.
bool never_swaps(const nlohmann::json& trace) {
  for (const nlohmann::json& entry : trace) {
    if (!entry.is_object() || entry.value("pivot_row", -1LL) != entry.value("column", -2LL)) return false;
  }
  return true;
}

// What the student replied, for the detectors: a trace or an x that does not read is left out.
detectors::GeppAnswer answer_of(const nlohmann::json& reply, int n) {
  detectors::GeppAnswer answer;
  answer.singular = replied_singular(reply);
  try {
    if (!answer.singular) answer.x = vector_field(reply, "x", n);
  } catch (const ReplyError&) {
  }
  try {
    if (const nlohmann::json* trace = linear::optional_trace(reply)) {
      std::vector<detectors::GeppTraceEntry> entries;
      for (std::size_t k = 0; k < trace->size(); ++k) {
        const nlohmann::json& entry = linear::trace_entry(*trace, k);
        entries.push_back({integer_field(entry, "pivot_row"), number_field(entry, "pivot")});
      }
      answer.trace = std::move(entries);
    }
  } catch (const ReplyError&) {
  }
  return answer;
}

std::optional<Diagnosis> diagnosis_for(const System& system, const Reference& reference, const nlohmann::json& reply) {
  return detectors::diagnose_gepp(system.A, system.b, reference.kappa, answer_of(reply, reference.n));
}

// The first column where the student's trace leaves numlab's pivot choices, if any.
std::optional<Departure> first_departure(const nlohmann::json& trace, const Reference& reference) {
  const double pivot_tolerance = 10.0 * reference.n * eps * reference.growth * reference.scale;
  const std::size_t columns = reference.pivots.size();
  for (std::size_t k = 0; k < columns; ++k) {
    if (k >= trace.size()) {
      return Departure{fmt::format("the trace stops after {} columns; numlab's GEPP pivots on {}", trace.size(), columns),
                       "give one trace entry per column, 0 ... n-1", k};
    }
    const nlohmann::json& entry = linear::trace_entry(trace, k);
    const long long column = integer_field(entry, "column");
    const long long row = integer_field(entry, "pivot_row");
    const double pivot = number_field(entry, "pivot");
    const PivotChoice& expected = reference.pivots[k];
    if (column != static_cast<long long>(k)) {
      return Departure{fmt::format("trace[{}] is for column {}; expected column {}", k, column, k),
                       "one trace entry per column, in order, columns counted from 0", k};
    }
    if (row != expected.row) {
      if (row < static_cast<long long>(k) || row >= reference.n) {
        return Departure{fmt::format("column {}: pivot_row {} is not a row at or below the diagonal ({} ... {})", k,
                                     row, k, reference.n - 1),
                         "pivot_row is the 0-based row of the matrix as it stands at that column", k};
      }
      const Eigen::VectorXd& candidates = expected.candidates;
      const double yours = candidates(row - static_cast<long long>(k));
      std::string hint;
      if (row == static_cast<long long>(k) && never_swaps(trace)) {
        hint = "no pivoting: at each column, swap in the row with the largest |a_ik| on or below the diagonal";
      } else if (yours == candidates.maxCoeff()) {
        hint = "pivoting on the signed value: compare |a_ik|, not a_ik (a large negative entry is a good pivot)";
      }
      return Departure{fmt::format("column {}: you pivoted on row {} (|a| = {}); the largest on or below the diagonal is row "
                                   "{} (|a| = {})",
                                   k, row, sci(std::abs(yours)), expected.row,
                                   sci(std::abs(candidates(expected.row - static_cast<int>(k))))),
                       hint, k};
    }
    if (std::abs(pivot - expected.pivot) > pivot_tolerance) {
      return Departure{fmt::format("column {}: your pivot on row {} is {}; numlab's is {} ({}), allowed difference {} "
                                   "(10*n*eps*growth*max|a_ij|)",
                                   k, row, digits17(pivot), digits17(expected.pivot),
                                   difference(pivot, expected.pivot), sci(pivot_tolerance)),
                       "the right row but another value: an earlier column left different numbers below it "
                       "(a swap of only part of the row, or a wrong elimination update)", k};
    }
  }
  if (trace.size() > columns) {
    return Departure{fmt::format("the trace has {} entries; numlab's GEPP pivots on {} columns", trace.size(), columns),
                     "", columns};
  }
  return std::nullopt;
}

// The known mistake that fits a wrong x, from the trace when there is one.
std::string hint_for_wrong_x(const nlohmann::json& reply, const Reference& reference) {
  const nlohmann::json* trace = linear::optional_trace(reply);
  if (trace == nullptr) {
    return "known mistakes that give this: no pivoting, pivoting on the signed value, a swap of only part of a row "
           "(or of A but not b), an off-by-one in back substitution; send a trace to see the column that departs";
  }
  if (const auto departure = first_departure(*trace, reference)) {
    return departure->message + (departure->hint.empty() ? "" : ": " + departure->hint);
  }
  return "your pivots match numlab's, so the error comes after the pivot choice: a swap that leaves part of a row (or "
         "b) behind, or back substitution's index range (x_i = (c_i - sum_{j=i+1}^{n-1} u_ij x_j) / u_ii)";
}

// Where x first goes wrong, counting up from x[n-1] as back substitution does (for the message).
std::string where_x_departs(const Eigen::VectorXd& x, const Eigen::VectorXd& reference, double allowed) {
  const double scale = std::max(reference.cwiseAbs().maxCoeff(), 1e-300);
  for (Eigen::Index i = x.size() - 1; i >= 0; --i) {
    if (std::abs(x(i) - reference(i)) > allowed * scale) {
      const std::string values = fmt::format("x[{}] = {}, GSL LU's {} ({})", i, digits17(x(i)), digits17(reference(i)),
                                             difference(x(i), reference(i)));
      return i == x.size() - 1
                 ? fmt::format("; x[{}] is already wrong: {}", i, values)
                 : fmt::format("; counting up from the last unknown, x[{}] is the first wrong entry: {}", i, values);
    }
  }
  return "";
}

// Task 1: x to the accuracy the condition number and the growth factor allow, forward and backward.
Verdict solves_accurately(Session& session, const std::vector<System>& systems) {
  linear::ReferenceTimes times;
  for (const System& system : systems) {
    const Reference reference = reference_for(system, times);
    const nlohmann::json reply = session.ask(request_for(system));
    const double n = reference.n;
    const double allowed = 10.0 * n * reference.kappa * eps * reference.growth;
    session.expect({system.label, {{"x", to_json(reference.gsl_x)}},
                    fmt::format("x within {} (relative, inf-norm) of GSL LU's x above, and a relative residual within "
                                "{} (10*n*eps*growth)",
                                sci(allowed), sci(10.0 * n * eps * reference.growth))});
    if (replied_singular(reply)) {
      return Verdict::fail(not_singular_message(system, reference), diagnosis_for(system, reference, reply),
                           singular_threshold_hint, times.medians());
    }
    const Eigen::VectorXd x = vector_field(reply, "x", reference.n);
    const double forward = linear::relative_error(x, reference.gsl_x);
    if (!(forward <= allowed)) {
      return Verdict::fail(
          fmt::format("{}: x differs from GSL LU by {} (relative, inf-norm), allowed {} (10*n*kappa*eps*growth; n = {}, "
                      "kappa = {}, growth = {}){}",
                      system.label, sci(forward), sci(allowed), reference.n, sci(reference.kappa), sci(reference.growth),
                      where_x_departs(x, reference.gsl_x, allowed)),
          diagnosis_for(system, reference, reply), hint_for_wrong_x(reply, reference), times.medians());
    }
    const double backward = linalg::relative_residual(system.A, system.b, x);
    const double allowed_backward = 10.0 * n * eps * reference.growth;
    if (!(backward <= allowed_backward)) {
      return Verdict::fail(fmt::format("{}: the relative residual ||b - A x|| / (||A|| ||x||) is {}, allowed {} "
                                       "(10*n*eps*growth: GEPP is backward stable; n = {}, growth = {})",
                                       system.label, sci(backward), sci(allowed_backward), reference.n,
                                       sci(reference.growth)),
                           diagnosis_for(system, reference, reply), hint_for_wrong_x(reply, reference),
                           times.medians());
    }
  }
  return Verdict::pass(times.medians());
}

// Task 2: "singular" exactly where numlab's GEPP finds a negligible pivot.
Verdict reports_singular(Session& session, const std::vector<System>& systems) {
  linear::ReferenceTimes times;
  for (const System& system : systems) {
    const Reference reference = reference_for(system, times);
    const nlohmann::json reply = session.ask(request_for(system));
    session.expect({system.label, {{"status", "singular"}},
                    fmt::format("\"status\": \"singular\": numlab's GEPP stops at column {}, |pivot| {} <= "
                                "n*eps*max|a_ij| = {}",
                                reference.stopped_column, sci(reference.stopped_pivot), sci(reference.negligible_pivot))});
    if (!replied_singular(reply)) {
      return Verdict::fail(
          fmt::format("{}: your reply has no \"status\": \"singular\"; numlab's GEPP stops at column {}: |pivot| = {} "
                      "<= n*eps*max|a_ij| = {} (n = {}, max|a_ij| = {})",
                      system.label, reference.stopped_column, sci(reference.stopped_pivot),
                      sci(reference.negligible_pivot), reference.n, sci(reference.scale)),
          diagnosis_for(system, reference, reply),
          "missing singular test: before dividing by a pivot (after the swap), compare |pivot| with n*eps*max|a_ij|",
          times.medians());
    }
  }
  return Verdict::pass(times.medians());
}

// The student's pivot trace beside numlab's for trace.html (trace_comparison.hpp).
TraceComparison pivots_side_by_side(const System& system, const Reference& reference, const nlohmann::json& trace,
                                    std::size_t parting) {
  std::vector<int> rows;
  std::vector<double> pivots;
  std::vector<Eigen::VectorXd> candidates;
  for (const PivotChoice& choice : reference.pivots) {
    rows.push_back(choice.row);
    pivots.push_back(choice.pivot);
    candidates.push_back(choice.candidates);
  }
  return pivot_comparison(system.label, trace, rows, pivots, candidates, parting);
}

// Task 3: the pivot trace, column by column, against numlab's stepper.
Verdict pivots_like_numlab(Session& session, const std::vector<System>& systems) {
  linear::ReferenceTimes times;
  for (const System& system : systems) {
    const Reference reference = reference_for(system, times);
    const nlohmann::json reply = session.ask(request_for(system));
    nlohmann::json expected_trace = nlohmann::json::array();
    for (std::size_t k = 0; k < reference.pivots.size(); ++k) {
      expected_trace.push_back({{"column", k}, {"pivot_row", reference.pivots[k].row}, {"pivot", reference.pivots[k].pivot}});
    }
    session.expect({system.label, {{"trace", expected_trace}},
                    fmt::format("the trace: each column's pivot_row as numlab's, its pivot within "
                                "10*n*eps*growth*max|a_ij| = {} (x as for task 1)",
                                sci(10.0 * reference.n * eps * reference.growth * reference.scale))});
    const nlohmann::json* trace = linear::optional_trace(reply);
    if (trace == nullptr) {
      return Verdict::fail(system.label + ": no trace in the reply",
                           "add \"trace\": one {\"column\", \"pivot_row\", \"pivot\"} per column", times.medians());
    }
    if (replied_singular(reply)) {
      return Verdict::fail(not_singular_message(system, reference), diagnosis_for(system, reference, reply),
                           singular_threshold_hint, times.medians());
    }
    if (const auto departure = first_departure(*trace, reference)) {
      Verdict verdict = Verdict::fail(system.label + ": " + departure->message, diagnosis_for(system, reference, reply),
                                      departure->hint, times.medians());
      verdict.trace = pivots_side_by_side(system, reference, *trace, departure->column);
      return verdict;
    }
  }
  return Verdict::pass(times.medians());
}

// Large entries negative and a tiny leading entry: no pivoting, or pivoting on the signed value,
// divides by 1e-20.
Eigen::MatrixXd tiny_leading_pivot() {
  return (Eigen::MatrixXd(4, 4) << 1e-20, 1, 2, -1,  //
          -3, 1, 1, 2,                                //
          -1, 2, -1, 1,                               //
          0.5, -2, 3, 1)
      .finished();
}

// The last row is the sum of the first two, up to a change far below rounding: GEPP's last pivot
// is rounding noise, a few eps times max|a_ij|, and not exactly 0.
Eigen::MatrixXd singular_to_working_precision() {
  return (Eigen::MatrixXd(3, 3) << 0.1, 0.7, 0.3,  //
          0.3, 0.2, 0.9,                            //
          0.4, 0.9, 1.2)
      .finished();
}

// Strictly diagonally dominant by columns (GEPP swaps no row; kappa_1 5.5), times 2^-70 (max|a_ij|
// 5.1e-21, the smallest pivot 3.4e-21): scaling by a power of two is exact, so x is the unscaled
// system's. Every pivot is a fair share of max|a_ij| and far below any fixed threshold (1e-12, eps,
// even 1e-20): only a test relative to A's size solves it.
Eigen::MatrixXd tiny_entries() {
  const Eigen::MatrixXd dominant = (Eigen::MatrixXd(5, 5) << 4, -1, 2, 0.5, -1,  //
                                    -1, 5, -1, 1, 2,                             //
                                    1, 2, -6, 1, 0.5,                            //
                                    0.5, -1, 1, 4, -1,                           //
                                    1, 0.5, 1, -1, 5)
                                       .finished();
  return std::ldexp(1.0, -70) * dominant;
}

// Whether numlab's GEPP stops at a pivot <= n*eps*max|a_ij| on generate_system(kind, n, seed).
bool numlab_finds_singular(std::string_view kind, int n, unsigned seed) {
  const linalg::GeneratedSystem system = linalg::generate_system(kind, n, seed);
  return linalg::gauss_elimination<Eigen::Dynamic>(system.A, system.b).status == Status::singular;
}

// Every random matrix's seed comes from the variant (its base seed without one), re-drawn until it
// is in the check's family: a "random" system numlab solves, a "singular" one numlab finds singular
// (kappa 1e10 is 1e10 whatever the seed).
std::vector<Check> gepp_battery(const Variant& variant) {
  const auto seed = [&variant](unsigned base) { return variant.seed(base); };
  const auto random_seed = [&variant](int n, unsigned base) {
    return variant.seed_where(base, [n](unsigned s) { return !numlab_finds_singular("random", n, s); });
  };
  const unsigned singular_seed =
      variant.seed_where(4, [](unsigned s) { return numlab_finds_singular("singular", 6, s); });
  const unsigned random3 = random_seed(3, 7), random8 = random_seed(8, 2), random50 = random_seed(50, 5);
  const unsigned trace8 = random_seed(8, 11), trace12 = random_seed(12, 6);
  const Eigen::MatrixXd nearly = linalg::matrix_with_condition(8, 1e10, seed(3));
  const std::string nearly_label =
      variant.active() ? fmt::format("kappa 1e10 8x8, matrix_with_condition(8, 1e10, {})", seed(3)) : "kappa 1e10 8x8";
  return {
      {"GEPP solves random systems (n = 3, 8, 50) to the accuracy their condition allows", 1,
       [=](Session& s) {
         return solves_accurately(s, {generated("random 3x3", "random", 3, random3),
                                      generated("random 8x8", "random", 8, random8),
                                      generated("random 50x50", "random", 50, random50)});
       }},
      {"GEPP is accurate when the leading entry is tiny (1e-20) and the large entries are negative", 1,
       [](Session& s) { return solves_accurately(s, {given("tiny leading pivot 4x4", tiny_leading_pivot())}); }},
      {"GEPP on Hilbert(10) (kappa ~ 3.5e13) is backward stable and as accurate as kappa allows", 1,
       [](Session& s) { return solves_accurately(s, {generated("Hilbert 10x10", "hilbert", 10)}); }},
      {"GEPP on Wilkinson's growth matrix (n = 20, growth 2^19) stays within kappa*eps*growth", 1,
       [](Session& s) { return solves_accurately(s, {generated("Wilkinson 20x20", "wilkinson", 20)}); }},
      {"GEPP solves a nearly singular system (kappa = 1e10) that is not singular to working precision", 1,
       [nearly, nearly_label](Session& s) { return solves_accurately(s, {given(nearly_label, nearly)}); }},
      {"GEPP solves a well-conditioned system whose entries are all tiny (times 2^-70): \"singular\" is relative to "
       "max|a_ij|",
       2, [](Session& s) { return solves_accurately(s, {given("column-dominant 5x5 times 2^-70", tiny_entries())}); }},
      {"GEPP reports an exactly singular matrix as singular", 2,
       [](Session& s) {
         return reports_singular(s, {given("zero matrix 3x3", Eigen::MatrixXd::Zero(3, 3)),
                                     given("singular 2x2 [[1, 2], [2, 4]]",
                                           (Eigen::MatrixXd(2, 2) << 1, 2, 2, 4).finished())});
       }},
      {"GEPP reports a matrix singular to working precision (a pivot <= n*eps*max|a_ij|) as singular", 2,
       [singular_seed](Session& s) {
         return reports_singular(s, {given("row 3 = row 1 + row 2, 3x3", singular_to_working_precision()),
                                     generated("singular 6x6 (last row = row 1 + row 2)", "singular", 6, singular_seed)});
       }},
      {"GEPP's pivot choices (trace) match numlab's partial pivoting, column by column", 3,
       [=](Session& s) {
         return pivots_like_numlab(s, {generated("random 8x8", "random", 8, trace8),
                                       given("tiny leading pivot 4x4", tiny_leading_pivot()),
                                       generated("random 12x12", "random", 12, trace12)});
       }},
  };
}

}  // namespace

Exercise gepp_exercise() {
  Exercise exercise;
  exercise.name = "gepp";
  exercise.summary = "Gaussian elimination with partial pivoting: x, the singular verdict, the pivot trace";
  exercise.task = task_text("gepp");
  exercise.stubs.python = "    raise NotImplementedError(\"not implemented: GEPP (reply x, or status singular)\")\n";
  exercise.stubs.cpp = "  throw std::runtime_error(\"not implemented: GEPP (reply x, or status singular)\");\n";
  exercise.stubs.octave = "  error('not implemented: GEPP (reply x, or status singular)');\n";
  exercise.battery = gepp_battery;
  return exercise;
}

}  // namespace numlab::exercises
