#include "lessons/forcing_sentences.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <tuple>

#include "lessons/lab_sentences.hpp"

namespace numlab::cli {

namespace {
bool converged(const ForcingRun& run, double tolerance) {
  return run.status == "converged" && run.residual <= tolerance;
}

std::string cost(const ForcingRun& run) {
  return fmt::format("{} ({} iterations, {} sweeps)", run.forcing, run.iterations, run.sweeps);
}
}  // namespace

std::string forcing_tradeoff_sentence(const std::vector<ForcingRun>& runs, double tolerance) {
  std::vector<ForcingRun> solved;
  for (const ForcingRun& run : runs) {
    if (converged(run, tolerance)) solved.push_back(run);
  }
  std::string text = fmt::format("{} choices converge to ||f||_inf <= {:.3g}.",
                                 count_of(static_cast<int>(solved.size()), static_cast<int>(runs.size())), tolerance);
  if (!solved.empty()) {
    const ForcingRun& fewest_outer = *std::min_element(solved.begin(), solved.end(), [](const auto& a, const auto& b) {
      return std::tie(a.iterations, a.sweeps) < std::tie(b.iterations, b.sweeps);
    });
    const ForcingRun& fewest_inner = *std::min_element(solved.begin(), solved.end(), [](const auto& a, const auto& b) {
      return std::tie(a.sweeps, a.iterations) < std::tie(b.sweeps, b.iterations);
    });
    if (fewest_outer.forcing == fewest_inner.forcing) {
      text += fmt::format(" {} needs both the fewest outer iterations and the fewest inner sweeps.", cost(fewest_outer));
    } else {
      const int more = fewest_inner.iterations - fewest_outer.iterations;
      text += fmt::format(" The fewest outer iterations: {}; the fewest inner sweeps: {}, {:.1f}x fewer sweeps for {} "
                          "more iteration{}.",
                          cost(fewest_outer), cost(fewest_inner),
                          static_cast<double>(fewest_outer.sweeps) / std::max(fewest_inner.sweeps, 1), more,
                          more == 1 ? "" : "s");
    }
  }
  for (const ForcingRun& run : runs) {
    if (converged(run, tolerance)) continue;
    text += fmt::format(" {} ends {} after {} iterations at ||f||_inf = {:.3g}, {} the tolerance.", run.forcing,
                        run.status, run.iterations, run.residual, run.residual > tolerance ? "above" : "within");
  }
  return text;
}

}  // namespace numlab::cli
