#include "exercises/detectors/gepp_detectors.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <limits>
#include <string>

#include "exercises/detectors/explains.hpp"

namespace numlab::exercises::detectors {

namespace {

constexpr double eps = std::numeric_limits<double>::epsilon();

int pivot_row(const Eigen::MatrixXd& a, int k, GeppMistake mistake) {
  const int n = static_cast<int>(a.rows());
  if (mistake == GeppMistake::no_pivoting) return k;
  // The search starts at row k, or at row k+1 when the student's loop skips the diagonal.
  const int first = mistake == GeppMistake::search_skips_diagonal && k + 1 < n ? k + 1 : k;
  int best = first;
  for (int i = first + 1; i < n; ++i) {
    const bool larger = mistake == GeppMistake::signed_pivot ? a(i, k) > a(best, k)
                                                             : std::abs(a(i, k)) > std::abs(a(best, k));
    if (larger) best = i;
  }
  return best;
}

void swap_rows(Eigen::MatrixXd& a, Eigen::VectorXd& b, int k, int p, GeppMistake mistake) {
  if (p == k) return;
  if (mistake == GeppMistake::swap_copies_row || mistake == GeppMistake::swap_copies_row_and_b) {
    a.row(k) = a.row(p);  // the second assignment copies row k's new entries back: row p is kept
    if (mistake == GeppMistake::swap_copies_row_and_b) {
      b(k) = b(p);
    } else {
      std::swap(b(k), b(p));
    }
    return;
  }
  const int n = static_cast<int>(a.rows());
  const int first = mistake == GeppMistake::swap_leaves_last_column || mistake == GeppMistake::swap_only_pivot_column ? k : 0;
  const int last = mistake == GeppMistake::swap_leaves_last_column ? n - 2
                   : mistake == GeppMistake::swap_only_pivot_column ? k
                                                                    : n - 1;
  for (int j = first; j <= last; ++j) std::swap(a(k, j), a(p, j));
  if (mistake != GeppMistake::swap_without_b) std::swap(b(k), b(p));
}

Eigen::VectorXd back_substitution(const Eigen::MatrixXd& u, const Eigen::VectorXd& c, GeppMistake mistake) {
  const int n = static_cast<int>(u.rows());
  Eigen::VectorXd x = Eigen::VectorXd::Zero(n);
  for (int i = n - 1; i >= 0; --i) {
    int from = i + 1, to = n - 1;
    if (mistake == GeppMistake::back_substitution_skips_next) from = i + 2;
    if (mistake == GeppMistake::back_substitution_skips_last) to = n - 2;
    double sum = 0.0;
    for (int j = from; j <= to; ++j) sum += u(i, j) * x(j);
    x(i) = (c(i) - sum) / u(i, i);
  }
  return x;
}

const char* description(GeppMistake mistake) {
  switch (mistake) {
    case GeppMistake::no_pivoting: return "elimination without row swaps (row k is always the pivot row)";
    case GeppMistake::signed_pivot: return "pivoting on the largest signed a_ik";
    case GeppMistake::search_skips_diagonal: return "a pivot search over the rows below the diagonal only (i > k)";
    case GeppMistake::inverted_multiplier: return "elimination with the multiplier a_kk / a_ik";
    case GeppMistake::swap_without_b: return "row swaps of A that leave b as it was";
    case GeppMistake::swap_leaves_last_column: return "row swaps that leave the last column behind";
    case GeppMistake::swap_only_pivot_column: return "row swaps of column k only";
    case GeppMistake::swap_copies_row: return "row swaps that copy row p over row k and keep row p (b swapped)";
    case GeppMistake::swap_copies_row_and_b: return "row swaps that copy row p over row k and keep row p, in A and b";
    case GeppMistake::back_substitution_skips_next: return "back substitution whose sum starts at j = i+2";
    case GeppMistake::back_substitution_skips_last: return "back substitution whose sum stops at j = n-2";
    case GeppMistake::none: break;
  }
  return "numlab's GEPP";
}

const char* remedy(GeppMistake mistake) {
  switch (mistake) {
    case GeppMistake::no_pivoting:
      return "at each column swap in the row with the largest |a_ik| on or below the diagonal";
    case GeppMistake::signed_pivot: return "compare |a_ik|, not a_ik: a large negative entry is a good pivot";
    case GeppMistake::search_skips_diagonal:
      return "the search starts at row k: keep the diagonal entry when no |a_ik| below it is larger";
    case GeppMistake::inverted_multiplier: return "the multiplier is l_ik = a_ik / a_kk (the pivot divides)";
    case GeppMistake::swap_without_b: return "swap b_k and b_p together with the rows of A";
    case GeppMistake::swap_leaves_last_column:
    case GeppMistake::swap_only_pivot_column: return "swap whole rows (every column of A, and b)";
    case GeppMistake::swap_copies_row:
    case GeppMistake::swap_copies_row_and_b:
      return "row k's entries are lost when the first assignment overwrites them: swap through a copy (numpy: "
             "A[[k, p]] = A[[p, k]]; numpy rows A[k], A[p] are views, not copies), or a temporary row";
    case GeppMistake::back_substitution_skips_next:
    case GeppMistake::back_substitution_skips_last:
      return "x_i = (c_i - sum_{j=i+1}^{n-1} u_ij x_j) / u_ii";
    case GeppMistake::none: break;
  }
  return "";
}

struct Case {
  const Eigen::MatrixXd& A;
  double kappa;
  double scale;       // max|a_ij|
  double negligible;  // n*eps*max|a_ij|
  GeppRun reference;
};

// Whether the student's trace records the pivots `run` takes: the same row and pivot at every
// column it eliminates, and, when the run stops as singular, optionally the stopped column too
// (its row, and a pivot as negligible as the run's).
bool same_columns(const std::vector<GeppTraceEntry>& trace, const GeppRun& run, const Case& c) {
  const double n = static_cast<double>(c.A.rows());
  const bool with_stop = run.singular && trace.size() == run.rows.size() + 1;
  if (trace.size() != run.rows.size() && !with_stop) return false;
  for (std::size_t k = 0; k < run.rows.size(); ++k) {
    const double tolerance = std::max(1e-6 * std::abs(run.pivots[k]), 100.0 * n * eps * run.growth * c.scale);
    if (trace[k].row != run.rows[k] || !(std::abs(trace[k].pivot - run.pivots[k]) <= tolerance)) return false;
  }
  return !with_stop || (trace.back().row == run.stopped_row && std::abs(trace.back().pivot) <= c.negligible);
}

// Whether `run` explains the student's answer, and in which words; "" when it does not.
std::string explanation(const Case& c, const GeppRun& run, const GeppAnswer& answer) {
  const double n = static_cast<double>(c.A.rows());
  const GeppRun& reference = c.reference;
  std::vector<std::string> parts;
  bool distinguishes = false;
  if (answer.singular != run.singular) return "";
  if (answer.singular) {
    if (answer.trace && !same_columns(*answer.trace, run, c)) return "";
    if (!reference.singular) {
      distinguishes = true;
      parts.push_back(fmt::format("it stops as singular at column {} (|a_kk| = {} <= n*eps*max|a_ij| = {}) as you do, "
                                  "where numlab's GEPP swaps in a pivot of |a| = {} and solves",
                                  run.stopped_column, measured(std::abs(run.stopped_pivot)),
                                  measured(c.negligible), measured(std::abs(reference.pivots[run.stopped_column]))));
    }
  }
  if (answer.x) {
    if (run.x.size() == 0) return "";
    const double allowed = 10.0 * n * c.kappa * eps * reference.growth;
    const double separation = relative_distance(run.x, reference.x);
    const double distance = relative_distance(*answer.x, run.x);
    const double tolerance = 100.0 * n * c.kappa * eps * run.growth;
    if (explains(distance, separation, tolerance, allowed)) {
      distinguishes = true;
      parts.push_back(fmt::format("your x equals its x to {} (numlab's x differs from it by {})", measured(distance),
                                  measured(separation)));
    } else if (!(distance <= std::max(tolerance, allowed))) {
      return "";
    }
  }
  if (answer.trace && !run.rows.empty()) {
    const std::vector<GeppTraceEntry>& trace = *answer.trace;
    if (!same_columns(trace, run, c)) return "";
    for (std::size_t k = 0; k < run.rows.size() && k < reference.rows.size(); ++k) {
      if (reference.rows[k] != run.rows[k]) {
        const Eigen::VectorXd& candidates = reference.candidates[k];
        const auto at = [&](long long row) { return measured(std::abs(candidates(row - static_cast<long long>(k)))); };
        parts.push_back(fmt::format("your pivot rows are its rows at all {} columns; at column {} you pivot on row {} "
                                    "(|a| = {}) where numlab's GEPP takes row {} (|a| = {})",
                                    trace.size(), k, run.rows[k], at(run.rows[k]), reference.rows[k],
                                    at(reference.rows[k])));
        distinguishes = true;
        break;
      }
      const double allowed = 10.0 * n * eps * reference.growth * c.scale;
      if (std::abs(reference.pivots[k] - run.pivots[k]) > allowed) {
        parts.push_back(fmt::format("your pivots are its pivots at all {} columns; at column {} yours is {} where "
                                    "numlab's is {}",
                                    trace.size(), k, measured(trace[k].pivot), measured(reference.pivots[k])));
        distinguishes = true;
        break;
      }
    }
  }
  if (!distinguishes) return "";
  std::string joined;
  for (const std::string& part : parts) joined += (joined.empty() ? "" : "; ") + part;
  return joined;
}

}  // namespace

GeppRun replay_gepp(const Eigen::MatrixXd& A, const Eigen::VectorXd& b, GeppMistake mistake) {
  const int n = static_cast<int>(A.rows());
  Eigen::MatrixXd a = A;
  Eigen::VectorXd c = b;
  const double scale = A.cwiseAbs().maxCoeff();
  const double negligible = n * eps * scale;
  GeppRun run;
  for (int k = 0; k < n; ++k) {
    run.candidates.push_back(a.col(k).tail(n - k));
    const int p = pivot_row(a, k, mistake);
    swap_rows(a, c, k, p, mistake);
    if (!(std::abs(a(k, k)) > negligible)) {
      run.singular = true;
      run.stopped_column = k;
      run.stopped_pivot = a(k, k);
      run.stopped_row = p;
      return run;
    }
    run.rows.push_back(p);
    run.pivots.push_back(a(k, k));
    for (int i = k + 1; i < n; ++i) {
      const double l = mistake == GeppMistake::inverted_multiplier ? a(k, k) / a(i, k) : a(i, k) / a(k, k);
      a.row(i).tail(n - k) -= l * a.row(k).tail(n - k);
      c(i) -= l * c(k);
    }
  }
  const Eigen::MatrixXd u = a.triangularView<Eigen::Upper>();
  run.growth = scale > 0.0 ? std::max(1.0, u.cwiseAbs().maxCoeff() / scale) : 1.0;
  if (!std::isfinite(run.growth)) run.growth = std::numeric_limits<double>::infinity();
  run.x = back_substitution(a, c, mistake);
  return run;
}

std::optional<Diagnosis> diagnose_gepp(const Eigen::MatrixXd& A, const Eigen::VectorXd& b, double kappa,
                                       const GeppAnswer& answer) {
  const double scale = A.cwiseAbs().maxCoeff();
  const Case c{A, kappa, scale, static_cast<double>(A.rows()) * eps * scale, replay_gepp(A, b, GeppMistake::none)};
  const std::vector<std::pair<const char*, GeppMistake>> replayed = {
      {"no_pivoting", GeppMistake::no_pivoting},
      {"signed_pivot", GeppMistake::signed_pivot},
      {"pivot_search_skips_diagonal", GeppMistake::search_skips_diagonal},
      {"inverted_multiplier", GeppMistake::inverted_multiplier},
      {"swap_without_b", GeppMistake::swap_without_b},
      {"partial_row_swap", GeppMistake::swap_leaves_last_column},
      {"partial_row_swap", GeppMistake::swap_only_pivot_column},
      {"partial_row_swap", GeppMistake::swap_copies_row},
      {"partial_row_swap", GeppMistake::swap_copies_row_and_b},
      {"back_substitution", GeppMistake::back_substitution_skips_next},
      {"back_substitution", GeppMistake::back_substitution_skips_last},
  };
  std::vector<Detector> detectors;
  for (const auto& [cause, mistake] : replayed) {
    detectors.push_back({cause, Specificity::exact, [&c, &b, &answer, mistake = mistake]() -> std::optional<std::string> {
                           const std::string why = explanation(c, replay_gepp(c.A, b, mistake), answer);
                           if (why.empty()) return std::nullopt;
                           return fmt::format("{} explains your reply: {}: {}", description(mistake), why,
                                              remedy(mistake));
                         }});
  }
  // "singular" where numlab's GEPP solves, and no replayed pivoting explains it: the threshold.
  detectors.push_back({"absolute_singular_threshold", Specificity::family, [&]() -> std::optional<std::string> {
                         if (!answer.singular || c.reference.singular) return std::nullopt;
                         const std::size_t column = answer.trace ? answer.trace->size() : c.reference.pivots.size();
                         if (column >= c.reference.pivots.size()) return std::nullopt;
                         const double pivot = std::abs(c.reference.pivots[column]);
                         if (!(pivot < 1e-6 * scale)) return std::nullopt;
                         return fmt::format("you replied \"singular\"{}, where numlab's |pivot| is {}: far above "
                                            "n*eps*max|a_ij| = {}, but below a fixed threshold such as 1e-8: only "
                                            "|pivot| <= n*eps*max|a_ij| (max over the original A) means singular",
                                            answer.trace ? fmt::format(" at column {}", column) : std::string(),
                                            measured(pivot), measured(c.negligible));
                       }});
  // "singular" for a matrix that is well scaled relative to itself (every pivot a fair share of
  // max|a_ij|) but small in absolute terms: no relative test says singular, a fixed number does.
  detectors.push_back({"absolute_singular_threshold", Specificity::exact, [&]() -> std::optional<std::string> {
                         if (!answer.singular || c.reference.singular || c.reference.pivots.empty()) return std::nullopt;
                         double smallest = std::numeric_limits<double>::infinity();
                         for (const double pivot : c.reference.pivots) smallest = std::min(smallest, std::abs(pivot));
                         if (!(smallest >= 1e-4 * scale && smallest < 1e-6)) return std::nullopt;
                         return fmt::format("you replied \"singular\" for a matrix whose entries are all small "
                                            "(max|a_ij| = {}), where numlab's smallest |pivot| is {}: {} of max|a_ij|, "
                                            "far above n*eps*max|a_ij| = {}; only a fixed threshold (1e-12, eps, ...) "
                                            "calls it zero: test |pivot| <= n*eps*max|a_ij|, relative to A's size",
                                            measured(scale), measured(smallest), measured(smallest / scale),
                                            measured(c.negligible));
                       }});
  // x where numlab's GEPP stops: a division by a pivot that is rounding noise.
  detectors.push_back({"no_singular_test", Specificity::exact, [&]() -> std::optional<std::string> {
                         if (answer.singular || !c.reference.singular || !answer.trace) return std::nullopt;
                         const std::size_t k = static_cast<std::size_t>(c.reference.stopped_column);
                         if (answer.trace->size() <= k || !(std::abs((*answer.trace)[k].pivot) <= c.negligible)) {
                           return std::nullopt;
                         }
                         return fmt::format("your trace divides by the pivot {} at column {}, and |{}| <= "
                                            "n*eps*max|a_ij| = {}: it is rounding noise; test |pivot| before dividing "
                                            "and reply \"singular\"",
                                            measured((*answer.trace)[k].pivot), k, measured((*answer.trace)[k].pivot),
                                            measured(c.negligible));
                       }});
  detectors.push_back({"no_singular_test", Specificity::family, [&]() -> std::optional<std::string> {
                         if (answer.singular || !c.reference.singular) return std::nullopt;
                         return fmt::format("you sent x where numlab's GEPP finds |pivot| = {} <= n*eps*max|a_ij| = {} "
                                            "at column {}: test |pivot| against n*eps*max|a_ij| before dividing",
                                            measured(std::abs(c.reference.stopped_pivot)),
                                            measured(c.negligible), c.reference.stopped_column);
                       }});
  return diagnose(detectors);
}

}  // namespace numlab::exercises::detectors
