#include "bench/performance_profiles.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace numlab::cli {

namespace {

constexpr double infinity = std::numeric_limits<double>::infinity();

void check_table(const CostTable& costs) {
  for (const auto& row : costs) {
    if (row.size() != costs.front().size()) throw std::invalid_argument("profile table rows differ in length");
    for (double cost : row) {
      if (std::isnan(cost) || cost < 0.0) throw std::invalid_argument("profile cost must be >= 0 or +inf, got " + std::to_string(cost));
    }
  }
}

std::vector<double> sorted_unique(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  values.erase(std::unique(values.begin(), values.end()), values.end());
  return values;
}

}  // namespace

CostTable performance_ratios(const CostTable& costs) {
  check_table(costs);
  CostTable ratios = costs;
  for (auto& row : ratios) {
    const double best = row.empty() ? infinity : *std::min_element(row.begin(), row.end());
    for (double& cost : row) {
      // A problem nobody solved has no best cost: every ratio is infinite.
      cost = std::isinf(best) || std::isinf(cost) ? infinity : (best == 0.0 ? (cost == 0.0 ? 1.0 : infinity) : cost / best);
    }
  }
  return ratios;
}

double performance_profile(const CostTable& ratios, int solver, double tau) {
  if (ratios.empty()) return 0.0;
  const auto within = std::count_if(ratios.begin(), ratios.end(), [&](const auto& row) { return row.at(solver) <= tau; });
  return static_cast<double>(within) / static_cast<double>(ratios.size());
}

double data_profile(const CostTable& evaluations, const std::vector<int>& sizes, int solver, double kappa) {
  check_table(evaluations);
  if (sizes.size() != evaluations.size()) throw std::invalid_argument("data profile: one size per problem");
  if (evaluations.empty()) return 0.0;
  int within = 0;
  for (std::size_t p = 0; p < evaluations.size(); ++p) {
    if (evaluations[p].at(solver) <= kappa * (sizes[p] + 1)) ++within;
  }
  return static_cast<double>(within) / static_cast<double>(evaluations.size());
}

std::vector<double> ratio_breakpoints(const CostTable& ratios) {
  std::vector<double> points;
  for (const auto& row : ratios) {
    for (double ratio : row) {
      if (std::isfinite(ratio)) points.push_back(ratio);
    }
  }
  return sorted_unique(points);
}

std::vector<double> data_breakpoints(const CostTable& evaluations, const std::vector<int>& sizes) {
  if (sizes.size() != evaluations.size()) throw std::invalid_argument("data profile: one size per problem");
  std::vector<double> points;
  for (std::size_t p = 0; p < evaluations.size(); ++p) {
    for (double cost : evaluations[p]) {
      if (std::isfinite(cost)) points.push_back(cost / (sizes[p] + 1));
    }
  }
  return sorted_unique(points);
}

}  // namespace numlab::cli
