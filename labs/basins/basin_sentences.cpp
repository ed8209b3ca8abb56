#include "basins/basin_sentences.hpp"

#include <fmt/format.h>

#include <cmath>

namespace numlab::basins {

namespace {
std::string starts_fail(int count) { return count == 1 ? "1 start fails" : fmt::format("{} starts fail", count); }
std::string radians(double value) { return std::isfinite(value) ? fmt::format("{:.3g} rad", value) : "none"; }
}  // namespace

std::string percent(int count, int total) {
  return fmt::format("{:.1f}%", total > 0 ? 100.0 * count / total : 0.0);
}

std::string seed_position_sentence(double distance, bool reaches_seed_mode, const std::string& seed_label) {
  return fmt::format("Seed 000's estimates sit {} from the solution in this slice; Newton from the grid point "
                     "nearest them reaches {}.",
                     radians(distance), reaches_seed_mode ? "the seed's branch (" + seed_label + ")" :
                                                            "another branch than the seed's (" + seed_label + ")");
}

std::string stray_sentence(const std::string& method, double to_other_mode, double to_failure, double grid_step) {
  const std::string other = std::isfinite(to_other_mode)
                                ? fmt::format("the nearest start that lands on another branch is {} from the solution",
                                              radians(to_other_mode))
                                : "no start on the slice lands on another branch";
  const std::string failure = std::isfinite(to_failure)
                                  ? fmt::format("the nearest start that fails is {} away", radians(to_failure))
                                  : "no start fails";
  return fmt::format("{}: {}, and {} (grid step {}).", method, other, failure, radians(grid_step));
}

std::string damping_sentence(int plain_home, int damped_home, int total, int plain_failed, int damped_failed) {
  const std::string change = damped_home > plain_home   ? "raises"
                             : damped_home < plain_home ? "lowers"
                                                        : "keeps";
  const std::string fewer = damped_failed < plain_failed   ? "fewer"
                            : damped_failed > plain_failed ? "more"
                                                           : "as many";
  return fmt::format("Damping {} the share of the slice that reaches the seed's branch from {} to {}, with {} "
                     "failing starts ({} against {}).",
                     change, percent(plain_home, total), percent(damped_home, total), fewer, damped_failed,
                     plain_failed);
}

std::string fractal_sentence(int root1, int root2, int root3, int failed, int total) {
  return fmt::format("Of {} starts, {} reach z = 1, {} reach e^(2 pi i/3) and {} reach e^(-2 pi i/3); {}. "
                     "The three basins meet in the fractal boundary, where a small change of start changes the root.",
                     total, percent(root1, total), percent(root2, total), percent(root3, total), starts_fail(failed));
}

std::string four_bar_sentence(int mode_plus, int mode_minus, int singular, int failed, int total) {
  return fmt::format("Of {} starts, {} reach mode B+ and {} reach mode B-; {}, {} of them on a singular "
                     "Jacobian (a start on a toggle line, coupler and rocker in line).",
                     total, percent(mode_plus, total), percent(mode_minus, total), starts_fail(failed), singular);
}

}  // namespace numlab::basins
