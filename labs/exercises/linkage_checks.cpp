#include "exercises/linkage_checks.hpp"

#include <cmath>
#include <fmt/format.h>
#include <limits>
#include <numbers>

#include "exercises/numbers.hpp"
#include "exercises/reply_fields.hpp"

namespace numlab::exercises {

double angle_difference(double a, double b) {
  const double turn = 2.0 * std::numbers::pi;
  double d = std::fmod(a - b, turn);
  if (d > std::numbers::pi) d -= turn;
  if (d <= -std::numbers::pi) d += turn;
  return d;
}

double worst_angle_error(const Eigen::VectorXd& got, const Eigen::VectorXd& expected, int& worst) {
  double largest = -1.0;
  worst = 0;
  for (Eigen::Index k = 0; k < got.size(); ++k) {
    const double error = std::abs(angle_difference(got(k), expected(k)));
    if (error > largest) {
      largest = error;
      worst = static_cast<int>(k);
    }
  }
  return largest;
}

double inverse_inf_norm(const Eigen::MatrixXd& J) {
  const Eigen::FullPivLU<Eigen::MatrixXd> lu(J);
  if (!lu.isInvertible()) return std::numeric_limits<double>::infinity();
  return lu.inverse().cwiseAbs().rowwise().sum().maxCoeff();
}

double kappa_inf(const Eigen::MatrixXd& J) {
  return J.cwiseAbs().rowwise().sum().maxCoeff() * inverse_inf_norm(J);
}

std::optional<std::vector<TraceRow>> read_trace(const nlohmann::json& reply) {
  const auto found = reply.find("trace");
  if (found == reply.end()) return std::nullopt;
  if (!found->is_array()) throw ReplyError(fmt::format("\"trace\" is {}, not a list", found->type_name()));
  std::vector<TraceRow> rows;
  for (std::size_t i = 0; i < found->size(); ++i) {
    const nlohmann::json& entry = (*found)[i];
    if (!entry.is_object()) throw ReplyError(fmt::format("trace[{}] is {}, not an object", i, entry.type_name()));
    try {
      rows.push_back({number_field(entry, "residual_inf"), number_field(entry, "step_inf")});
    } catch (const ReplyError& error) {
      throw ReplyError(fmt::format("trace[{}]: {}", i, error.what()));
    }
  }
  return rows;
}

namespace {

// Newton near a root: r_{k+1} <= C r_k^2. Linear convergence (r_{k+1} / r_k about constant, well
// above r_k) from `from` on is the mark of a Jacobian that is not f's derivative.
bool converges_linearly(const std::vector<TraceRow>& rows, std::size_t from) {
  int linear = 0;
  for (std::size_t k = from + 1; k < rows.size(); ++k) {
    const double ratio = rows[k].residual_inf / rows[k - 1].residual_inf;
    if (ratio > 1e-3 && ratio < 1.0 && rows[k - 1].residual_inf < 1.0) ++linear;
  }
  return linear >= 2;
}

// What departs at iteration k, and the likely cause. Built in place in the optional it returns (one
// named return: no move of its strings, which GCC 12 at -O3 misreads as out of bounds).
std::optional<TraceDeparture> departure_at(const std::vector<TraceRow>& student, const std::vector<TraceRow>& reference,
                                           std::size_t k, double relative, double residual_floor, bool step_ok,
                                           double start_residual, const std::string& allowed) {
  const TraceRow& ref = reference[k];
  const TraceRow& got = student[k];
  std::optional<TraceDeparture> departure{std::in_place};
  departure->iteration = k;
  departure->message = fmt::format(
      "iteration {}: residual_inf = {}, step_inf = {}; numlab's Newton (GEPP, x <- x + dx with J dx = -f) from the same "
      "start has residual_inf = {} ({}), step_inf = {} ({}); {}",
      k + 1, digits17(got.residual_inf), digits17(got.step_inf), digits17(ref.residual_inf),
      difference(got.residual_inf, ref.residual_inf), digits17(ref.step_inf), difference(got.step_inf, ref.step_inf),
      allowed);
  const double before = k == 0 ? start_residual : reference[k - 1].residual_inf;
  if (std::abs(got.residual_inf - before) <= relative * before + residual_floor) {
    departure->hint = "residual_inf is the residual before the step: record ||f|| after x <- x + dx";
  } else if (step_ok && got.residual_inf > before) {
    departure->hint = "the step has Newton's length but the residual does not fall as it should: a sign error, such as "
                      "x <- x - dx where dx already solves J dx = -f";
  } else if (converges_linearly(student, k)) {
    departure->hint = "quadratic convergence is lost (the residual falls by a constant factor): J is not the derivative "
                      "of f -- an entry from the wrong link or a column from the wrong angle";
  } else {
    departure->hint = "the step is not Newton's: check that J is the derivative of f (each entry's link and angle) and "
                      "that the step solves J dx = -f";
  }
  return departure;
}

}  // namespace

std::optional<TraceDeparture> first_departure(const std::vector<TraceRow>& student, const std::vector<TraceRow>& reference,
                                              double relative, double residual_floor, double step_floor,
                                              double start_residual) {
  const std::string allowed = fmt::format("allowed {} relative plus rounding {} on residual_inf", sci(relative), sci(residual_floor));
  for (std::size_t k = 0; k < reference.size(); ++k) {
    const TraceRow& ref = reference[k];
    if (k > 0 && reference[k - 1].residual_inf <= residual_floor) break;  // rounding noise from here on
    if (k >= student.size()) {
      return TraceDeparture{
          fmt::format("iteration {}: your trace ends after {} iterations; numlab's Newton from the same start goes on "
                      "(residual_inf {} after iteration {})",
                      k + 1, student.size(), sci(reference[k].residual_inf), k + 1),
          "a stop test that passes too early (a sum of residuals that cancel, a signed test without abs), or a J that "
          "is singular where f's derivative is not (a column from the wrong angle can make it so)",
          k};
    }
    const TraceRow& got = student[k];
    const bool step_ok = std::abs(got.step_inf - ref.step_inf) <= relative * ref.step_inf + step_floor;
    const bool residual_ok = std::abs(got.residual_inf - ref.residual_inf) <= relative * ref.residual_inf + residual_floor;
    if (step_ok && residual_ok) continue;
    return departure_at(student, reference, k, relative, residual_floor, step_ok, start_residual, allowed);
  }
  return std::nullopt;
}

std::optional<long long> decided_iterations(const std::vector<TraceRow>& reference, double start_residual,
                                            double tolerance, long long max_iterations, bool converged,
                                            double relative, double noise) {
  const auto count = static_cast<long long>(reference.size());
  if (converged ? (count > 0 && reference.back().residual_inf > tolerance) : count != max_iterations) return std::nullopt;
  auto clear = [&](double residual) {
    const double spread = relative * residual + noise;
    return residual - spread > 2.0 * tolerance || residual + spread < 0.5 * tolerance;
  };
  if (!clear(start_residual)) return std::nullopt;
  for (const TraceRow& row : reference) {
    if (!clear(row.residual_inf)) return std::nullopt;
  }
  return count;
}

std::string sci(double value) { return fmt::format("{:.3g}", value); }

}  // namespace numlab::exercises
