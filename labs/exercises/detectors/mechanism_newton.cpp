#include "exercises/detectors/mechanism_newton.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <limits>
#include <numbers>

#include "exercises/numbers.hpp"

namespace numlab::exercises {

std::vector<TraceRow> simulate_newton(const ClosureEvaluator& evaluate, double driver, const Eigen::VectorXd& start,
                                      double tolerance, long long max_iterations, const NewtonLoop& loop,
                                      Eigen::VectorXd* end) {
  std::vector<TraceRow> rows;
  Eigen::VectorXd x = start;
  ClosureValues values = evaluate(driver, x);
  for (long long iteration = 0; iteration < max_iterations; ++iteration) {
    const double before = values.f.lpNorm<Eigen::Infinity>();
    if (!std::isfinite(before) || before <= tolerance) break;
    const Eigen::MatrixXd J = loop.jacobian ? loop.jacobian(x, values.J) : values.J;
    const Eigen::PartialPivLU<Eigen::MatrixXd> lu(J);
    if (std::abs(lu.determinant()) == 0.0) break;
    const Eigen::VectorXd dx = lu.solve(-values.f);
    if (!loop.never_update) x = loop.minus_step ? Eigen::VectorXd(x - dx) : Eigen::VectorXd(x + dx);
    values = evaluate(driver, x);
    rows.push_back({loop.record_before ? before : values.f.lpNorm<Eigen::Infinity>(), dx.lpNorm<Eigen::Infinity>()});
  }
  if (end != nullptr) *end = x;
  return rows;
}

namespace {

constexpr double pi = std::numbers::pi;
constexpr double eps = std::numeric_limits<double>::epsilon();

double residual_at(const NewtonEvidence& e, const Eigen::VectorXd& x) { return e.evaluate(e.driver, x).f.lpNorm<Eigen::Infinity>(); }

// ||f|| at the student's angles is above what the tolerance and rounding allow.
bool residual_too_large(const NewtonEvidence& e) { return residual_at(e, e.x) > e.tolerance + e.rounding; }

bool same_angles(const Eigen::VectorXd& a, const Eigen::VectorXd& b, double tolerance) {
  int worst = 0;
  return a.size() == b.size() && worst_angle_error(a, b, worst) <= tolerance;
}

// The student's trace follows `simulated` over its first `rows` rows (all of them when rows is 0),
// within `relative` (and rounding), by the same test as the trace check.
bool follows(const NewtonEvidence& e, std::vector<TraceRow> simulated, std::size_t rows, double relative) {
  if (!e.trace || e.trace->empty() || simulated.empty()) return false;
  if (rows > 0 && simulated.size() > rows) simulated.resize(rows);
  const ClosureValues at_start = e.evaluate(e.driver, e.start);
  const double step_floor = inverse_inf_norm(at_start.J) * e.rounding;
  return !first_departure(*e.trace, simulated, relative, e.rounding, step_floor, at_start.f.lpNorm<Eigen::Infinity>());
}

std::vector<TraceRow> simulate(const NewtonEvidence& e, const NewtonLoop& loop, const Eigen::VectorXd& start) {
  return simulate_newton(e.evaluate, e.driver, start, e.tolerance, e.max_iterations, loop);
}

std::string trace_text(const std::vector<TraceRow>& rows, std::size_t count) {
  std::string text;
  for (std::size_t k = 0; k < std::min(count, rows.size()); ++k) {
    text += fmt::format("{}{}", k == 0 ? "" : ", ", sci(rows[k].residual_inf));
  }
  return text;
}

std::optional<std::string> one_iteration_too_many(const NewtonEvidence& e) {
  const long long rows = e.trace ? static_cast<long long>(e.trace->size()) : 0;
  if (e.iterations == e.max_iterations + 1 || rows == e.max_iterations + 1) {
    return fmt::format("your loop made {} iterations where max_iterations was {}: it tests the limit after the step, "
                       "or with > where >= belongs; stop when the count reaches max_iterations",
                       std::max(e.iterations, rows), e.max_iterations);
  }
  // One step past a residual that already passed the test: numlab's count plus one, where the
  // stop rule decides the count, with numlab's Newton before it.
  if (!e.decided_iterations || e.status != "converged") return std::nullopt;
  const long long decided = *e.decided_iterations;
  if (decided < 1 || (e.iterations != decided + 1 && rows != decided + 1)) return std::nullopt;
  const auto reference = simulate(e, {}, e.start);
  if (static_cast<long long>(reference.size()) != decided || !follows(e, reference, 0, 1e-6)) return std::nullopt;
  return fmt::format("your Newton reports {} iterations and {} trace rows where numlab's takes {} from the same start: "
                     "your trace is numlab's for {} rows, and its residual_inf {} after iteration {} already passes "
                     "max |f_i| <= tolerance {}; test the residual at the current x before each step and stop as soon "
                     "as it passes (one step after the test passed is one iteration too many)",
                     e.iterations, rows, decided, decided, sci(reference.back().residual_inf), decided, sci(e.tolerance));
}

// Every row of the trace the same, residual above the tolerance and a step above rounding: Newton
// from the same x takes the same step, so the x it steps from never changes (the new angles kept
// in another variable, f and J evaluated at the old one).
std::optional<std::string> repeating_rows(const NewtonEvidence& e) {
  if (!e.trace || e.trace->size() < 2) return std::nullopt;
  const TraceRow first = e.trace->front();
  const double step_floor = inverse_inf_norm(e.evaluate(e.driver, e.start).J) * e.rounding;
  if (first.residual_inf <= e.tolerance + e.rounding || first.step_inf <= step_floor) return std::nullopt;
  for (const TraceRow& row : *e.trace) {
    if (std::abs(row.residual_inf - first.residual_inf) > 1e-9 * first.residual_inf ||
        std::abs(row.step_inf - first.step_inf) > 1e-9 * first.step_inf) {
      return std::nullopt;
    }
  }
  return fmt::format("every one of your {} trace rows repeats row 1 (residual_inf = {}, step_inf = {}): Newton from the "
                     "same x takes the same step, so the x each iteration starts from is never updated; store x <- x + "
                     "dx in the variable f and J are evaluated at",
                     e.trace->size(), digits17(first.residual_inf), digits17(first.step_inf));
}

std::optional<std::string> x_never_updated(const NewtonEvidence& e) {
  const double start_residual = residual_at(e, e.start);
  if (start_residual <= e.tolerance) return std::nullopt;
  const bool unmoved = e.iterations >= 1 && e.x.size() == e.start.size() &&
                       (e.x - e.start).cwiseAbs().maxCoeff() <= 4 * eps * (1.0 + e.start.cwiseAbs().maxCoeff());
  bool flat = e.trace && e.trace->size() >= 2;
  if (flat) {
    for (const TraceRow& row : *e.trace) flat = flat && std::abs(row.residual_inf - start_residual) <= 1e-9 * start_residual;
  }
  if (!unmoved && !flat) return repeating_rows(e);
  return fmt::format("the angles never move: {} after {} iterations{}, ||f(start)||_inf = {}: x <- x + dx must be stored "
                     "(in Python, x + dx makes a new array; x = x + dx or x += dx keeps it)",
                     unmoved ? "your reply's angles are the start's" : "your angles stay at the start",
                     e.iterations,
                     flat ? fmt::format(" and every trace row has residual_inf = {}", digits17(e.trace->front().residual_inf))
                          : "",
                     digits17(start_residual));
}

// A stop test that passed where max |f_i| <= tolerance does not: the residual's pattern names it.
// Only when the student's own trace ends above the tolerance (or is empty): their f agrees with
// numlab's, and their test let that residual pass.
std::optional<std::string> stop_test_pattern(const NewtonEvidence& e) {
  if (e.status != "converged" || !residual_too_large(e)) return std::nullopt;
  if (e.trace && !e.trace->empty() && e.trace->back().residual_inf <= e.tolerance) return std::nullopt;
  const Eigen::VectorXd f = e.evaluate(e.driver, e.x).f;
  const double r = f.lpNorm<Eigen::Infinity>();
  if (f.maxCoeff() <= e.tolerance) {
    return fmt::format("status \"converged\" at angles where every f_i <= tolerance {} but min f_i = {} (numlab's f): a "
                       "signed stop test, max f_i <= tolerance without abs; the test is max |f_i| <= tolerance",
                       sci(e.tolerance), digits17(f.minCoeff()));
  }
  if (f.minCoeff() >= -e.tolerance) {
    return fmt::format("status \"converged\" at angles where every f_i >= -tolerance but max f_i = {} (numlab's f): a "
                       "signed stop test without abs; the test is max |f_i| <= tolerance",
                       digits17(f.maxCoeff()));
  }
  if (f.size() % 2 == 0) {
    double pair_sum = 0.0;
    for (Eigen::Index i = 0; i + 1 < f.size(); i += 2) pair_sum = std::max(pair_sum, std::abs(f(i) + f(i + 1)));
    if (pair_sum <= e.tolerance) {
      return fmt::format("status \"converged\" at angles where each loop's pair f_(2i) + f_(2i+1) sums to at most {} "
                         "(tolerance {}) but max |f_i| = {} (f[0] = {}, f[1] = {}): the components cancel in the pair "
                         "sum; the test is max |f_i| <= tolerance, on every component",
                         sci(pair_sum), sci(e.tolerance), sci(r), digits17(f(0)), digits17(f(1)));
    }
  }
  return std::nullopt;
}

std::optional<std::string> converged_when_stopped(const NewtonEvidence& e) {
  if (e.status != "converged" || e.iterations != e.max_iterations || !residual_too_large(e)) return std::nullopt;
  return fmt::format("status \"converged\" after {} iterations = max_iterations, with ||f||_inf = {} (numlab's f at your "
                     "angles) above the tolerance {}: the loop stopped at the limit, and the status must then be "
                     "\"max_iterations\"",
                     e.iterations, sci(residual_at(e, e.x)), sci(e.tolerance));
}

// One reported angle measured from the other side: pi - a (from -x rather than +x) or -a.
std::optional<std::string> angle_from_other_axis(const NewtonEvidence& e) {
  if (!residual_too_large(e)) return std::nullopt;
  const double allowed = 10.0 * (e.tolerance + e.rounding);
  for (int k = 0; k < e.x.size(); ++k) {
    for (const bool mirrored : {true, false}) {
      Eigen::VectorXd other = e.x;
      other(k) = mirrored ? pi - e.x(k) : -e.x(k);
      const double r = residual_at(e, other);
      if (r > allowed) continue;
      return fmt::format("{} is reported as {}: with {} = {} in its place ||f||_inf = {} (your angles give {}); the "
                         "task measures {} as its equation does",
                         e.angle_name(k), mirrored ? "pi minus the angle (from +x where it is measured from -x)" : "minus the angle",
                         e.angle_name(k), digits17(other(k)), sci(r), sci(residual_at(e, e.x)), e.angle_name(k));
    }
  }
  return std::nullopt;
}

// Degrees where radians belong: the angles solve f with the units mixed (all angles, the driver,
// one angle), or the student's Newton is Newton's on a closure whose driver or constant angle is
// in degrees (its trace follows that Newton, or its angles solve that closure).
std::optional<std::string> degrees(const NewtonEvidence& e) {
  if (!residual_too_large(e)) return std::nullopt;
  const double allowed = 10.0 * (e.tolerance + e.rounding) + 1e-9 * e.links_sum;
  const auto units = angle_units(static_cast<int>(e.x.size()), e.angle_name);
  for (const AngleUnits& mix : units) {
    const double r = evaluate_in(mix, e.evaluate, e.driver, e.x).f.lpNorm<Eigen::Infinity>();
    if (r > allowed) continue;
    return fmt::format("your angles solve f with {}: ||f||_inf = {} there, {} at your angles in radians; the request's "
                       "angles are radians, and sin and cos take radians",
                       mix.what, sci(r), sci(residual_at(e, e.x)));
  }
  std::vector<SlippedClosure> worlds = e.constant_angle_slips;
  for (const AngleUnits& mix : units) {
    if (mix.driver_scale == 1.0 || (mix.angle_scales.array() != 1.0).any()) continue;  // the driver alone
    worlds.push_back({mix.what, [mix, evaluate = e.evaluate](double driver, const Eigen::VectorXd& x) {
                        return evaluate(driver * mix.driver_scale, x);
                      }});
  }
  for (const SlippedClosure& world : worlds) {
    const double r = world.evaluate(e.driver, e.x).f.lpNorm<Eigen::Infinity>();
    const bool traced = follows(e, simulate_newton(world.evaluate, e.driver, e.start, e.tolerance, e.max_iterations, {}), 3, 1e-6);
    if (r > allowed && !traced) continue;
    return fmt::format("your Newton solves the closure with {}: {}; the request's angles are radians, and sin and cos "
                       "take radians",
                       world.what,
                       traced ? fmt::format("your trace (residual_inf {}) is numlab's Newton on that closure from the "
                                            "same start", trace_text(*e.trace, 3))
                              : fmt::format("||f||_inf = {} there at your angles, {} with the task's", sci(r),
                                            sci(residual_at(e, e.x))));
  }
  return std::nullopt;
}

std::optional<std::string> step_sign(const NewtonEvidence& e) {
  NewtonLoop loop;
  loop.minus_step = true;
  const auto simulated = simulate(e, loop, e.start);
  if (!follows(e, simulated, 3, 1e-6)) return std::nullopt;
  return fmt::format("your trace is Newton's with x <- x - dx (residual_inf {} in the first rows, as numlab's Newton with "
                     "that sign gives): dx already solves J dx = -f, so the step is x <- x + dx",
                     trace_text(*e.trace, 3));
}

std::optional<std::string> trace_before_step(const NewtonEvidence& e) {
  NewtonLoop loop;
  loop.record_before = true;
  if (!follows(e, simulate(e, loop, e.start), 3, 1e-6)) return std::nullopt;
  return fmt::format("your trace's residual_inf is ||f|| before each step (row 1 is {} = ||f(start)||_inf): record the "
                     "row after x <- x + dx, with the residual at the new x",
                     digits17(e.trace->front().residual_inf));
}

std::optional<std::string> restart_from_seed(const NewtonEvidence& e) {
  if (e.seed_start.size() != e.start.size() || same_angles(e.seed_start, e.start, 1e-12)) return std::nullopt;
  Eigen::VectorXd seed_end, start_end;
  const auto from_seed = simulate_newton(e.evaluate, e.driver, e.seed_start, e.tolerance, e.max_iterations, {}, &seed_end);
  simulate_newton(e.evaluate, e.driver, e.start, e.tolerance, e.max_iterations, {}, &start_end);
  const bool traced = follows(e, from_seed, 3, 1e-6);
  const bool landed = same_angles(e.x, seed_end, 1e-6) && !same_angles(seed_end, start_end, 1e-6);
  if (!traced && !landed) return std::nullopt;
  return fmt::format("your Newton starts from the seed's own guess, not from the request's: {} (numlab's Newton from the "
                     "seed's guess {}); start from the request's angles, the previous pose",
                     traced ? fmt::format("your trace ({}) is numlab's from the seed's guess", trace_text(*e.trace, 3))
                            : "your angles are where it ends",
                     landed ? "ends at your angles" : "gives your trace");
}

std::optional<std::string> transposed_jacobian(const NewtonEvidence& e) {
  NewtonLoop loop;
  loop.jacobian = [](const Eigen::VectorXd&, const Eigen::MatrixXd& J) { return Eigen::MatrixXd(J.transpose()); };
  if (!follows(e, simulate(e, loop, e.start), 3, 1e-6)) return std::nullopt;
  return fmt::format("your trace (residual_inf {}) is Newton's with J transposed: J[i][k] = d f[i] / d x_k, row i for "
                     "equation i",
                     trace_text(*e.trace, 3));
}

std::optional<std::string> finite_difference_jacobian(const NewtonEvidence& e) {
  struct Scheme {
    bool central;
    double step;
  };
  if (follows(e, simulate(e, {}, e.start), 0, 1e-6)) return std::nullopt;  // Newton's own trace: nothing to explain
  std::vector<Scheme> schemes;
  for (const double h : {1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, std::sqrt(eps)}) schemes.push_back({false, h});
  for (const double h : {1e-3, 1e-4, 1e-5, 1e-6}) schemes.push_back({true, h});
  for (const Scheme& scheme : schemes) {
    NewtonLoop loop;
    loop.jacobian = [&](const Eigen::VectorXd& x, const Eigen::MatrixXd& J) {
      Eigen::MatrixXd D(J.rows(), J.cols());
      const Eigen::VectorXd f = e.evaluate(e.driver, x).f;
      for (int k = 0; k < x.size(); ++k) {
        Eigen::VectorXd up = x, down = x;
        up(k) += scheme.step;
        down(k) -= scheme.step;
        D.col(k) = scheme.central ? Eigen::VectorXd((e.evaluate(e.driver, up).f - e.evaluate(e.driver, down).f) / (2 * scheme.step))
                                  : Eigen::VectorXd((e.evaluate(e.driver, up).f - f) / scheme.step);
      }
      return D;
    };
    if (!follows(e, simulate(e, loop, e.start), 0, 1e-5)) continue;
    return fmt::format("your trace follows Newton with a {} difference J of step h = {} (residual_inf {} ...), not "
                       "numlab's with the analytic J: the task asks for the analytic J",
                       scheme.central ? "central" : "forward", sci(scheme.step), trace_text(*e.trace, 4));
  }
  return std::nullopt;
}

std::optional<std::string> stop_test_own_trace(const NewtonEvidence& e) {
  if (e.status != "converged" || !e.trace || e.trace->empty()) return std::nullopt;
  const double last = e.trace->back().residual_inf;
  if (last <= e.tolerance + e.rounding) return std::nullopt;
  return fmt::format("status \"converged\", but your own trace's last residual_inf is {} above the tolerance {}: the stop "
                     "test is not max |f_i| <= tolerance (a small step, a sum or a signed test stopped the loop)",
                     digits17(last), sci(e.tolerance));
}

std::optional<std::string> rounded_constants(const NewtonEvidence& e) {
  if (e.status != "converged" || !e.trace || e.trace->empty() || !residual_too_large(e)) return std::nullopt;
  const double r = residual_at(e, e.x);
  const double last = e.trace->back().residual_inf;
  if (last > e.tolerance || r > 1e-2 * e.links_sum) return std::nullopt;
  std::string how_far;
  if (e.exact) {
    int worst = 0;
    const double error = worst_angle_error(e.x, *e.exact, worst);
    how_far = fmt::format(", {} rad from the exact pose in {}", sci(error), e.angle_name(worst));
  }
  return fmt::format("your f says converged (your trace's last residual_inf {}), numlab's f at your angles is {}{}: your "
                     "f has its root slightly elsewhere, the mark of a constant that differs a little from the task's (a "
                     "rounded one, such as 4.698 for 5 cos 20 deg = 4.6985); compute each constant from its definition",
                     sci(last), sci(r), how_far);
}

// r_(k+1) / r_k steady in (1e-3, 1): linear convergence. The median ratio, when two or more rows show it.
std::optional<double> linear_rate(const std::vector<TraceRow>& rows) {
  std::vector<double> ratios;
  for (std::size_t k = 1; k < rows.size(); ++k) {
    const double ratio = rows[k].residual_inf / rows[k - 1].residual_inf;
    if (ratio > 1e-3 && ratio < 1.0 && rows[k - 1].residual_inf < 1.0) ratios.push_back(ratio);
  }
  if (ratios.size() < 2) return std::nullopt;
  std::sort(ratios.begin(), ratios.end());
  return ratios[ratios.size() / 2];
}

std::optional<std::string> wrong_jacobian(const NewtonEvidence& e) {
  if (!e.trace || e.trace->empty()) return std::nullopt;
  const auto reference = simulate(e, {}, e.start);
  if (follows(e, reference, 0, 1e-6)) return std::nullopt;
  const bool numlab_converges = !reference.empty() && reference.back().residual_inf <= e.tolerance;
  const auto rate = linear_rate(*e.trace);
  const std::string row1 = fmt::format("iteration 1: your step_inf {}, Newton's {}", digits17(e.trace->front().step_inf),
                                       digits17(reference.empty() ? 0.0 : reference.front().step_inf));
  if (rate && e.status == "converged") {
    const std::vector<TraceRow> tail(e.trace->end() - std::min<std::ptrdiff_t>(5, std::ssize(*e.trace)), e.trace->end());
    return fmt::format("quadratic convergence is lost: your residual falls by a factor of about {:.2g} per iteration (the "
                       "median ratio; your last rows {}), {} iterations where numlab's Newton takes {} ({}): J is not the "
                       "derivative of f -- check J entry by entry (each entry's link, angle and sign)",
                       *rate, trace_text(tail, 5), e.trace->size(), reference.size(), row1);
  }
  if (e.status != "converged" && numlab_converges) {
    return fmt::format("your Newton does not converge in {} iterations where numlab's does in {} from the same start "
                       "(your residual_inf {} ...; {}): the step is not Newton's, so J is not the derivative of f -- check "
                       "J entry by entry",
                       e.trace->size(), reference.size(), trace_text(*e.trace, 4), row1);
  }
  return std::nullopt;
}

}  // namespace

std::vector<Detector> newton_detectors(const NewtonEvidence& evidence) {
  const NewtonEvidence* e = &evidence;
  return {
      {"one_iteration_too_many", Specificity::exact, [e] { return one_iteration_too_many(*e); }},
      {"x_never_updated", Specificity::exact, [e] { return x_never_updated(*e); }},
      {"stop_test", Specificity::exact, [e] { return stop_test_pattern(*e); }},
      {"converged_when_stopped", Specificity::exact, [e] { return converged_when_stopped(*e); }},
      {"angle_from_other_axis", Specificity::exact, [e] { return angle_from_other_axis(*e); }},
      {"degrees_for_radians", Specificity::exact, [e] { return degrees(*e); }},
      {"step_sign", Specificity::exact, [e] { return step_sign(*e); }},
      {"trace_before_step", Specificity::exact, [e] { return trace_before_step(*e); }},
      {"restart_from_seed_guess", Specificity::exact, [e] { return restart_from_seed(*e); }},
      {"transposed_jacobian", Specificity::exact, [e] { return transposed_jacobian(*e); }},
      {"finite_difference_jacobian", Specificity::exact, [e] { return finite_difference_jacobian(*e); }},
      {"stop_test", Specificity::family, [e] { return stop_test_own_trace(*e); }},
      {"rounded_constants", Specificity::family, [e] { return rounded_constants(*e); }},
      {"wrong_jacobian", Specificity::family, [e] { return wrong_jacobian(*e); }},
  };
}

std::optional<Diagnosis> diagnose_newton(const NewtonEvidence& evidence) { return diagnose(newton_detectors(evidence)); }

}  // namespace numlab::exercises
