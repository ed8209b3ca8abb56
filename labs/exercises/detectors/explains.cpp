#include "exercises/detectors/explains.hpp"

#include <fmt/format.h>
#include <limits>

namespace numlab::exercises::detectors {

double relative_distance(const Eigen::MatrixXd& x, const Eigen::MatrixXd& y) {
  if (x.rows() != y.rows() || x.cols() != y.cols() || x.size() == 0) return std::numeric_limits<double>::infinity();
  if (!x.allFinite() || !y.allFinite()) return std::numeric_limits<double>::infinity();
  const double difference = (x - y).cwiseAbs().maxCoeff();
  const double scale = y.cwiseAbs().maxCoeff();
  return scale > 0.0 ? difference / scale : difference;
}

std::string measured(double value) { return fmt::format("{:.2g}", value); }

}  // namespace numlab::exercises::detectors
