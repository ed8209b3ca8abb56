#include "exercises/detectors/entry_mismatches.hpp"

#include <cmath>
#include <utility>

namespace numlab::exercises::detectors {

std::vector<Entry> differing(const Eigen::MatrixXd& got, const Eigen::MatrixXd& expected, double tolerance) {
  std::vector<Entry> entries;
  for (int i = 0; i < got.rows(); ++i) {
    for (int k = 0; k < got.cols(); ++k) {
      if (std::abs(got(i, k) - expected(i, k)) > tolerance) entries.push_back({i, k});
    }
  }
  return entries;
}

std::optional<std::vector<Entry>> negated_entries(const Eigen::MatrixXd& got, const Eigen::MatrixXd& expected,
                                                  double tolerance) {
  std::vector<Entry> wrong = differing(got, expected, tolerance);
  for (const Entry& entry : wrong) {
    if (std::abs(got(entry.row, entry.col) + expected(entry.row, entry.col)) > tolerance) return std::nullopt;
  }
  return wrong;
}

std::optional<double> transposed_within(const Eigen::MatrixXd& got, const Eigen::MatrixXd& expected, double tolerance) {
  if (got.rows() != got.cols() || got.rows() != expected.cols() || got.cols() != expected.rows()) return std::nullopt;
  const double worst = (got - expected.transpose()).cwiseAbs().maxCoeff();
  if (!(worst <= tolerance)) return std::nullopt;
  return worst;
}

bool swapped_pair(const Eigen::MatrixXd& got, const Eigen::MatrixXd& expected, Entry pair, double tolerance) {
  Eigen::MatrixXd swapped = expected;
  std::swap(swapped(pair.row, pair.col), swapped(pair.col, pair.row));
  return (got - swapped).cwiseAbs().maxCoeff() <= tolerance;
}

}  // namespace numlab::exercises::detectors
