#pragma once
// Where a student's J (or f, a one-column matrix) differs from numlab's, entry by entry, and the
// plainest hypotheses about those entries: each negated, the whole matrix transposed, one pair
// J[i][k], J[k][i] swapped. The Jacobian exercises' detectors (mechanism_jacobian.hpp) and the
// linkage exercise's (linkage_detectors.hpp) both test them (docs/exercises.md, "Diagnosis").

#include <Eigen/Core>
#include <optional>
#include <vector>

namespace numlab::exercises::detectors {

struct Entry {
  int row;
  int col;
};

// The entries of `got` more than `tolerance` from `expected`, row by row.
std::vector<Entry> differing(const Eigen::MatrixXd& got, const Eigen::MatrixXd& expected, double tolerance);

// The differing entries when each is numlab's negated (to `tolerance`); nothing when one is not.
// An empty list: nothing differs.
std::optional<std::vector<Entry>> negated_entries(const Eigen::MatrixXd& got, const Eigen::MatrixXd& expected,
                                                  double tolerance);

// max |got - expected^T| when `got` is square and that is within `tolerance`; nothing otherwise.
std::optional<double> transposed_within(const Eigen::MatrixXd& got, const Eigen::MatrixXd& expected, double tolerance);

// `got` is `expected` with the entries at `pair` and at its mirror (col, row) exchanged, to `tolerance`.
bool swapped_pair(const Eigen::MatrixXd& got, const Eigen::MatrixXd& expected, Entry pair, double tolerance);

}  // namespace numlab::exercises::detectors
