#pragma once
// Pieces shared by the linkage exercises (jansen-jacobian, jansen-newton, mustang-newton): angles
// compared modulo whole turns, the conditioning that sets a tolerance, numlab's Newton trace from
// a start, the comparison of a student's trace with it, and the time a reference takes.

#include <Eigen/Dense>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "numlab/nonlinear/newton.hpp"

namespace numlab::exercises {

// a - b brought into (-pi, pi]: angles that differ by whole turns are the same pose.
double angle_difference(double a, double b);
// max_k |angle_difference(got_k, expected_k)| and the k where it is largest.
double worst_angle_error(const Eigen::VectorXd& got, const Eigen::VectorXd& expected, int& worst);

// ||J^-1||_inf and kappa_inf(J) = ||J||_inf ||J^-1||_inf (infinite for a singular J).
double inverse_inf_norm(const Eigen::MatrixXd& J);
double kappa_inf(const Eigen::MatrixXd& J);

// Central differences of a closure's f at theta (step cbrt(eps) max(1, |theta_k|)): the
// independent reference shown beside its analytic Jacobian in the Jacobian exercises' messages.
template <typename Closure>
Eigen::MatrixXd central_differences(const Closure& closure, const typename Closure::Vector& theta) {
  Eigen::MatrixXd J(Closure::size, Closure::size);
  for (int k = 0; k < Closure::size; ++k) {
    const double h = std::cbrt(std::numeric_limits<double>::epsilon()) * std::max(1.0, std::abs(theta(k)));
    typename Closure::Vector up = theta, down = theta, f_up, f_down;
    up(k) += h;
    down(k) -= h;
    closure.residual(up, f_up);
    closure.residual(down, f_down);
    J.col(k) = (f_up - f_down) / (2.0 * h);
  }
  return J;
}

// The angle whose column k a student's column k is, if any: the closure's J with theta_k replaced
// by theta_j, for each j != k, within `tolerance` (the mark of a column from the wrong angle).
template <typename Closure>
std::optional<int> column_from_angle(const Closure& closure, const Eigen::MatrixXd& got,
                                     const typename Closure::Vector& theta, int k, double tolerance) {
  for (int j = 0; j < Closure::size; ++j) {
    if (j == k) continue;
    typename Closure::Vector swapped = theta;
    swapped(k) = theta(j);
    typename Closure::Matrix other;
    closure.jacobian(swapped, other);
    if ((got.col(k) - other.col(k)).cwiseAbs().maxCoeff() <= tolerance) return j;
  }
  return std::nullopt;
}

// One iteration of a Newton trace: ||f||_inf after the step and ||step||_inf.
struct TraceRow {
  double residual_inf = 0.0;
  double step_inf = 0.0;
};

// numlab's Newton (GEPP inner solve, no damping) on `closure` from x0: its rows and its result.
template <typename Closure>
std::vector<TraceRow> newton_trace(const Closure& closure, const typename Closure::Vector& x0,
                                   const nonlinear::NewtonOptions& options,
                                   nonlinear::NewtonResult<Closure::size>* result = nullptr) {
  using Stepper = nonlinear::Newton<Closure>;
  struct Recorder : Stepper::Observer {
    std::vector<TraceRow> rows;
    StepControl on_step(const Stepper&, const nonlinear::NewtonRecord& record) override {
      rows.push_back({record.residual_norm, record.step_norm});
      return StepControl::proceed;
    }
  } recorder;
  Stepper newton(closure, options);
  newton.set_observer(&recorder);
  const auto solved = newton.solve(x0);
  if (result != nullptr) *result = solved;
  return recorder.rows;
}

// The reply's "trace" as rows; ReplyError when an entry lacks a finite residual_inf or step_inf.
// Nothing when the reply has no trace.
std::optional<std::vector<TraceRow>> read_trace(const nlohmann::json& reply);

// Where a student's Newton trace first leaves numlab's from the same start, or nothing.
// A row departs when residual_inf or step_inf differs from numlab's by more than `relative`
// (relative to numlab's value), while numlab's residual is above `residual_floor` (below it both
// are rounding noise). The message names the iteration and both values; `hint` the mistake that
// fits (the residual recorded before the step, a sign error when the step's size agrees and the
// residual grew, a wrong Jacobian when convergence is no longer quadratic). start_residual: ||f(x0)||_inf.
struct TraceDeparture {
  std::string message;
  std::string hint;
  std::size_t iteration = 0;  // the row that departs (0-based)
};
std::optional<TraceDeparture> first_departure(const std::vector<TraceRow>& student, const std::vector<TraceRow>& reference,
                                              double relative, double residual_floor, double step_floor,
                                              double start_residual);

// The number of iterations the task's stop rule gives from a start, when it gives it beyond doubt:
// test max |f_i| <= tolerance before each step, stop at max_iterations. `reference` is numlab's
// trace from that start (`start_residual` = ||f(x0)||_inf, `converged` its ending). A correct
// Newton's residuals differ from numlab's by at most `relative` of them plus `noise`; when every
// residual, at the start and after each step, is more than a factor 2 from the tolerance beyond
// that, each test goes the same way in both and the count is numlab's. Nothing when one is that
// close, or numlab stopped for another reason (singular J, no progress).
std::optional<long long> decided_iterations(const std::vector<TraceRow>& reference, double start_residual,
                                            double tolerance, long long max_iterations, bool converged,
                                            double relative, double noise);

// A start whose residual is exactly `target` (to rounding): numlab's Newton on f(x) - target from
// the root x_root. Used to build starts on which a wrong stop test passes (components that cancel
// in pairs, or that are all negative).
// f(x) - target: its roots have residual `target` under the closure.
template <typename Closure>
struct ShiftedClosure : nonlinear::EvaluatesTogether<ShiftedClosure<Closure>, Closure::size> {
  static constexpr int size = Closure::size;
  const Closure* closure = nullptr;
  typename Closure::Vector target;
  int dimension() const { return size; }
  void residual_and_jacobian(const typename Closure::Vector& x, typename Closure::Vector& f,
                             typename Closure::Matrix& J) const {
    closure->residual_and_jacobian(x, f, J);
    f -= target;
  }
};

template <typename Closure>
typename Closure::Vector start_with_residual(const Closure& closure, const typename Closure::Vector& x_root,
                                             const typename Closure::Vector& target) {
  ShiftedClosure<Closure> shifted;
  shifted.closure = &closure;
  shifted.target = target;
  nonlinear::NewtonOptions options;
  options.residual_tolerance = 1e-13;
  options.max_iterations = 50;
  options.damped = true;
  return nonlinear::Newton<ShiftedClosure<Closure>>(shifted, options).solve(x_root).x;
}

// Median seconds per call of `run` over `repeats` calls (for ReferenceTime).
template <typename Run>
double median_seconds(Run&& run, int repeats = 5) {
  std::vector<double> times;
  for (int i = 0; i < repeats; ++i) {
    const auto start = std::chrono::steady_clock::now();
    run();
    times.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  std::sort(times.begin(), times.end());
  return times[times.size() / 2];
}

// Median seconds per evaluation of f and J together by `closure` at theta (for ReferenceTime).
template <typename Closure>
double residual_and_jacobian_seconds(const Closure& closure, const typename Closure::Vector& theta) {
  typename Closure::Vector f;
  typename Closure::Matrix J;
  volatile double sink = 0.0;
  const double seconds = median_seconds([&] {
    for (int i = 0; i < 1000; ++i) {
      closure.residual_and_jacobian(theta, f, J);
      sink = sink + J(0, 0);
    }
  });
  return seconds / 1000.0;
}

// "1.2e-03" style numbers for messages.
std::string sci(double value);

}  // namespace numlab::exercises
