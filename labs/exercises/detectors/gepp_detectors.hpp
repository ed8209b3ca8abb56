#pragma once
// The gepp exercise's detectors (docs/exercises.md, "Diagnosis"): each known mistake is replayed on
// the request (elimination without pivoting, with the signed pivot, the inverted multiplier, ...)
// and named when its replay explains the student's x, pivot trace or singular verdict better than
// numlab's GEPP does.

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "exercises/diagnosis.hpp"

namespace numlab::exercises::detectors {

enum class GeppMistake {
  none,                      // numlab's GEPP, as the task asks
  no_pivoting,               // row k is always the pivot row
  signed_pivot,              // the largest a_ik instead of the largest |a_ik|
  search_skips_diagonal,     // the largest |a_ik| for i > k only: row k itself is never kept
  inverted_multiplier,       // l = a_kk / a_ik instead of a_ik / a_kk
  swap_without_b,            // rows of A swapped, b left as it was
  swap_leaves_last_column,   // the swap moves columns k ... n-2, the last stays behind
  swap_only_pivot_column,    // the swap moves column k only
  swap_copies_row,           // row p copied over row k, row p kept (numpy's A[k], A[p] = A[p], A[k]); b swapped
  swap_copies_row_and_b,     // the same for b: a swap without a temporary, A(k,:) = A(p,:); A(p,:) = A(k,:)
  back_substitution_skips_next,  // x_i's sum starts at j = i+2
  back_substitution_skips_last,  // x_i's sum stops at j = n-2
};

// One elimination of A x = b, as a student's code with `mistake` runs it.
struct GeppRun {
  bool singular = false;
  int stopped_column = -1;                // where |pivot| <= n*eps*max|a_ij| stopped it, when singular
  double stopped_pivot = 0.0;             // a_kk there, after the swap
  int stopped_row = -1;                   // the row it took as the pivot there
  std::vector<int> rows;                  // the pivot row at each column (0-based, before the swap)
  std::vector<double> pivots;             // a_kk after the swap
  std::vector<Eigen::VectorXd> candidates;  // a_ik, i = k ... n-1, before the swap
  Eigen::VectorXd x;                      // empty when singular
  double growth = 1.0;                    // max(1, max|u_ij| / max|a_ij|)
};

GeppRun replay_gepp(const Eigen::MatrixXd& A, const Eigen::VectorXd& b, GeppMistake mistake);

struct GeppTraceEntry {
  long long row;
  double pivot;
};

// What the student replied: "singular", or x; and the pivot trace when there is one.
struct GeppAnswer {
  bool singular = false;
  std::optional<Eigen::VectorXd> x;
  std::optional<std::vector<GeppTraceEntry>> trace;
};

// The most specific detector that fires on this failing reply to A x = b (kappa: kappa_1 of A).
std::optional<Diagnosis> diagnose_gepp(const Eigen::MatrixXd& A, const Eigen::VectorXd& b, double kappa,
                                       const GeppAnswer& answer);

}  // namespace numlab::exercises::detectors
