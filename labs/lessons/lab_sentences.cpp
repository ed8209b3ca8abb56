#include "lessons/lab_sentences.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>

namespace numlab::cli {

namespace {
constexpr double eps = std::numeric_limits<double>::epsilon();

// The parts separated by ", ", the last by `last_separator`.
std::string joined(const std::vector<std::string>& parts, const std::string& last_separator) {
  std::string text;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    if (i > 0) text += i + 1 == parts.size() ? last_separator : ", ";
    text += parts[i];
  }
  return text;
}

// The sentence with its first letter in upper case.
std::string capitalized(std::string sentence) {
  if (!sentence.empty()) sentence[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(sentence[0])));
  return sentence;
}
}  // namespace

std::string count_of(int count, int total) {
  if (count == 0) return fmt::format("none of the {}", total);
  if (count == total) return fmt::format("all {}", total);
  return fmt::format("{} of {}", count, total);
}

std::string speed_ratio_phrase(double time, double other_time) {
  const double ratio = other_time / time;  // > 1: `time` is the faster
  if (std::abs(ratio - 1.0) < 0.01) return "as fast as";
  return ratio > 1.0 ? fmt::format("{:.2f}x faster than", ratio) : fmt::format("{:.2f}x slower than", 1.0 / ratio);
}

std::string block_newton_sentence(const SolverCost& sequential, const SolverCost& full, int unknowns) {
  // 1. Which is faster, and by how much.
  std::string text = fmt::format("{} is {} {} ({:.3g} s against {:.3g} s per cycle). ", capitalized(sequential.name),
                                 speed_ratio_phrase(sequential.time_s, full.time_s), full.name, sequential.time_s,
                                 full.time_s);
  // 2. Why: the number of iterations against the cost of each.
  const double per_sequential = sequential.time_s / sequential.iterations, per_full = full.time_s / full.iterations;
  const double more_iterations = static_cast<double>(sequential.iterations) / full.iterations;
  text += fmt::format("It takes {:.1f}x as many iterations ({} block iterations against {}), ", more_iterations,
                      sequential.iterations, full.iterations);
  text += per_sequential < per_full
              ? fmt::format("but each costs {:.1f}x less: ", per_full / per_sequential)
              : fmt::format("and each costs {:.1f}x more, although ", per_sequential / per_full);
  text += fmt::format("one iteration of a 2x2 block evaluates 4 Jacobian entries and solves them in closed form, "
                      "where one iteration of {} evaluates all {} entries of the {}x{} Jacobian and eliminates it "
                      "by GEPP (about n^3/3 = {} multiply-adds).",
                      full.name, unknowns * unknowns, unknowns, unknowns, unknowns * unknowns * unknowns / 3);
  return text;
}

std::string same_method_sentence(const SolverCost& mine, const SolverCost& library) {
  std::string text = fmt::format("{} is {} {} ({:.3g} s against {:.3g} s). ", capitalized(mine.name),
                                 speed_ratio_phrase(mine.time_s, library.time_s), library.name, mine.time_s,
                                 library.time_s);
  const double iteration_ratio = static_cast<double>(library.iterations) / mine.iterations;
  if (std::abs(iteration_ratio - 1.0) <= 0.05) {
    return text + fmt::format("Both take about the same iterations ({} and {}), so the difference is the cost of "
                              "each iteration, not the method.",
                              mine.iterations, library.iterations);
  }
  return text + fmt::format("They take {} and {} iterations; per iteration, {} is {} {}.", mine.iterations,
                            library.iterations, mine.name,
                            speed_ratio_phrase(mine.time_s / mine.iterations, library.time_s / library.iterations),
                            library.name);
}

std::string closed_form_sentence(const SolverCost& newton, const SolverCost& closed_form, int poses) {
  return fmt::format("{} is {} {}: warm-started from the poses before, it needs {:.2f} iterations per pose ({} "
                     "for {} poses), each a linear solve, where {} computes every pose directly.",
                     capitalized(newton.name), speed_ratio_phrase(newton.time_s, closed_form.time_s), closed_form.name,
                     static_cast<double>(newton.iterations) / poses, newton.iterations, poses, closed_form.name);
}

std::string condition_limit_sentence(const std::vector<ConditionRow>& rows) {
  const auto exceeds = std::find_if(rows.begin(), rows.end(), [](const ConditionRow& r) { return r.kappa * eps > 1.0; });
  const auto singular = std::find_if(rows.begin(), rows.end(), [](const ConditionRow& r) { return r.singular; });
  const int last = rows.empty() ? 0 : rows.back().n;
  // 1. Where kappa passes 1/eps.
  std::string text = exceeds == rows.end()
                         ? fmt::format("Up to n = {} kappa stays below 1/eps = {:.2g}.", last, 1.0 / eps)
                         : fmt::format("kappa first exceeds 1/eps = {:.2g} at n = {} (kappa {:.3g}).", 1.0 / eps,
                                       exceeds->n, exceeds->kappa);
  // 2. Where the solver first says singular.
  text += singular == rows.end() ? fmt::format(" GEPP never says 'singular' up to n = {}.", last)
                                 : fmt::format(" GEPP first says 'singular' at n = {}: a pivot falls below "
                                               "n*eps*max|a_ij|.",
                                               singular->n);
  // 3. The rows in between: an answer with no guaranteed digit.
  if (exceeds != rows.end() && exceeds < singular) {
    text += fmt::format(" At n = {} it still returns an answer, but with kappa*eps > 1 not one of its digits is guaranteed.",
                        exceeds->n);
  }
  return text;
}

std::string lu_factors_sentence(double max_difference, double matrix_max, int n, double growth) {
  if (max_difference == 0.0) {
    return "P A = L U exactly: every entry of L U equals the entry of P A (max|PA - LU| = 0).";
  }
  const double relative = max_difference / matrix_max;
  const double bound = n * eps * std::max(growth, 1.0);
  if (relative <= bound) {
    return fmt::format("P A = L U to rounding: max|PA - LU| / max|a_ij| = {:.2g}, within n*eps*growth = {:.2g}; the "
                       "kept L, U and P solve any other right-hand side without eliminating again.",
                       relative, bound);
  }
  return fmt::format("P A = L U only to {:.2g} relative (max|PA - LU| / max|a_ij|), beyond n*eps*growth = {:.2g}: "
                     "more than rounding separates the factors from A.",
                     relative, bound);
}

double digits_lost(double forward_error) { return std::max(0.0, std::log10(forward_error / eps)); }

std::string digits_lost_sentence(const std::string& method, double worst_error, const std::string& where,
                                 double kappa) {
  if (!(worst_error > eps)) return fmt::format("{}'s forward error stays within eps everywhere: no digit lost.", method);
  const double bound = kappa * eps;
  return fmt::format("{}'s worst forward error is {:.3g}, at {}: {:.1f} digits lost (log10(error / eps)), {} the "
                     "kappa * eps = {:.2g} there.",
                     method, worst_error, where, digits_lost(worst_error),
                     worst_error <= bound ? "within" : "beyond", bound);
}

std::string loop_stops_sentence(int loop, const std::vector<LoopOutcome>& outcomes, int iteration_limit) {
  std::vector<std::string> stops;
  int failed = 0, ran_out = 0;
  for (const LoopOutcome& outcome : outcomes) {
    if (!outcome.stopped) {
      ++failed;
      ran_out += outcome.iterations >= iteration_limit ? 1 : 0;
      continue;
    }
    stops.push_back(fmt::format("{:.2f} deg (after {} iterations, with max(|f_i|, |f_j|) = {:.2g}: {})",
                                outcome.theta_deg, outcome.iterations, outcome.residual,
                                outcome.residual <= 1e-2 ? "a root" : "not a root"));
  }
  // 1. Where it did not stop.
  const int total = static_cast<int>(outcomes.size());
  std::string text = ran_out == failed
                         ? fmt::format("Loop {} uses all {} iterations without stopping at {} angles", loop,
                                       iteration_limit, count_of(failed, total))
                         : fmt::format("Loop {} fails at {} angles ({} of them after all {} iterations)", loop,
                                       count_of(failed, total), ran_out, iteration_limit);
  // 2. Where it stopped, and whether there is a root there.
  if (stops.empty()) return text + ": it never stops on this grid.";
  return text + fmt::format(", and stops only at {}.", joined(stops, " and at "));
}

std::string trend_phrase(const std::vector<double>& values) {
  int rises = 0;
  for (std::size_t i = 1; i < values.size(); ++i) rises += values[i] > values[i - 1] ? 1 : 0;
  const int steps = static_cast<int>(values.size()) - 1;
  if (values.size() < 2) return "has one value";
  const bool overall_down = values.back() < values.front();
  if (rises == 0) return fmt::format("falls at every step, from {:.3g} to {:.3g}", values.front(), values.back());
  if (rises == steps) return fmt::format("rises at every step, from {:.3g} to {:.3g}", values.front(), values.back());
  return fmt::format("{} overall, from {:.3g} to {:.3g}, rising at {} of {} steps", overall_down ? "falls" : "rises",
                     values.front(), values.back(), rises, steps);
}

}  // namespace numlab::cli
