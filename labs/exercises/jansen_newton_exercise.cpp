// jansen-newton: the student's full Newton on seed 000's 8-equation Jansen closure, against the
// closed form over a whole crank cycle, the residual test, and numlab's Newton trace.

#include <fmt/format.h>
#include <optional>
#include <utility>

#include "exercises/exercise_list.hpp"
#include "exercises/jansen_poses.hpp"
#include "exercises/newton_battery.hpp"
#include "exercises/task_texts.hpp"
#include "numlab/mechanisms/jansen_closure.hpp"

namespace numlab::exercises {

namespace {

struct JansenNewton {
  using Closure = mechanisms::JansenClosure;
  using Lengths = mechanisms::JansenLengths;
  static constexpr const char* input = "crank_angle";
  static constexpr const char* start = "theta0";
  static constexpr const char* answer = "theta";
  static std::string angle_name(int k) { return jansen_angle_name(k); }
  static double links_sum() { return jansen_links_sum(); }
  static std::string where(double angle) { return fmt::format("crank {:.4g} deg", angle / degrees); }
};

using Battery = NewtonBattery<JansenNewton>;
using Request = Battery::Request;

// From the closed-form pose of `leg` `back_deg` earlier in the cycle, with the leg's lengths.
Request from_behind(const JansenVariant& leg, double deg, double back_deg, double tolerance, int max_iterations) {
  return {deg * degrees, jansen_closed_form_angles((deg - back_deg) * degrees, leg.leg()), tolerance, max_iterations,
          leg.links, leg.varied ? leg.named() : LinkLengths{}};
}

// With a variant, every crank angle below is moved by an amount drawn from it (the whole cycle by
// one phase and its starts by another step back); the Jansen leg assembles at every crank angle.
// `shift(spread)`: 0 without a variant, else uniform in [-spread, spread) degrees.
struct Shifts {
  const Variant& variant;
  Variant::Stream stream;
  Shifts(const Variant& v, unsigned base) : variant(v), stream(v.stream(base)) {}
  double operator()(double spread) { return variant.active() ? stream.uniform(-spread, spread) : 0.0; }
};

// Every 10 degrees of the cycle (from a phase in [0, 10) with a variant), each from 10 degrees back
// (6 ... 14 with a variant).
std::pair<std::vector<Request>, std::vector<Battery::Vector>> cycle_requests(const Variant& variant,
                                                                             const JansenVariant& leg) {
  Shifts shift(variant, 1);
  const double phase = variant.active() ? 5.0 + shift(5.0) : 0.0, back = 10.0 + shift(4.0);
  std::vector<Request> requests;
  std::vector<Battery::Vector> exact;
  for (int step = 0; step < 36; ++step) {
    const double deg = variant.active() ? phase + 10.0 * step : static_cast<double>(10 * step);
    requests.push_back(from_behind(leg, deg, back, 1e-10, 20));
    exact.push_back(jansen_closed_form_angles(deg * degrees, leg.leg()));
  }
  return {requests, exact};
}

// A start where every component of f is -0.5 at crank `deg`, if numlab's damped Newton finds one.
std::optional<Request> cancelling_start(const JansenVariant& leg, double deg) {
  const mechanisms::JansenClosure closure(deg * degrees, leg.links);
  const auto start = start_with_residual(closure, jansen_closed_form_angles(deg * degrees, leg.leg()),
                                         mechanisms::JansenClosure::Vector::Constant(-0.5));
  mechanisms::JansenClosure::Vector f;
  closure.residual(start, f);
  if ((f.array() + 0.5).abs().maxCoeff() > 1e-9) return std::nullopt;
  return Request{deg * degrees, start, 1e-9, 20, leg.links, leg.varied ? leg.named() : LinkLengths{}};
}

std::vector<Request> honest_requests(const Variant& variant, const JansenVariant& leg) {
  Shifts shift(variant, 2);
  std::vector<Request> requests;
  // Too few iterations from far away: the honest status is max_iterations.
  for (double deg : {20.0, 110.0, 200.0, 290.0}) requests.push_back(from_behind(leg, deg + shift(10.0), 40.0, 1e-12, 2));
  // A start where every component of f is -0.5: a signed stop test (f_i < tol) passes there.
  std::optional<Request> cancelling = cancelling_start(leg, 60.0 + shift(20.0));
  while (!cancelling) cancelling = cancelling_start(leg, 60.0 + shift(20.0));  // only a variant's angle can miss
  requests.push_back(*cancelling);
  // The seed's tolerances: 1e-5 (seed 000) and 1e-9 (seed 001).
  requests.push_back(from_behind(leg, 150.0 + shift(10.0), 10.0, 1e-5, 10));
  requests.push_back(from_behind(leg, 250.0 + shift(10.0), 10.0, 1e-9, 20));
  return requests;
}

std::vector<Request> trace_requests(const Variant& variant, const JansenVariant& leg) {
  Shifts shift(variant, 3);
  std::vector<Request> requests;
  for (double deg : {30.0, 150.0, 240.0, 330.0}) requests.push_back(from_behind(leg, deg + shift(15.0), 20.0, 1e-10, 20));
  return requests;
}

// The leg's lengths: seed 000's, or a variant's on which numlab's Newton converges from the start
// of every request of the cycle and of the trace (to the closed form, for the cycle's).
JansenVariant leg_for(const Variant& variant) {
  return jansen_variant(variant, false, [&variant](const mechanisms::JansenLeg& candidate) {
    const JansenVariant leg{candidate.lengths(), {}, true, false};
    try {
      const auto [cycle, exact] = cycle_requests(variant, leg);
      return Battery::newton_converges(cycle, exact, trace_requests(variant, leg));
    } catch (const std::logic_error&) {
      return false;  // the closed form fails at an angle of a request
    }
  });
}

}  // namespace

Exercise jansen_newton_exercise() {
  Exercise exercise;
  exercise.name = "jansen-newton";
  exercise.summary = "full Newton-Raphson on seed 000's 8-equation Jansen leg, over a whole crank cycle";
  exercise.task = task_text("jansen-newton");
  exercise.stubs.python = "    raise NotImplementedError(\"not implemented: Newton-Raphson on the Jansen closure\")\n";
  exercise.stubs.cpp = "  throw std::runtime_error(\"not implemented: Newton-Raphson on the Jansen closure\");\n";
  exercise.stubs.octave = "  error('not implemented: Newton-Raphson on the Jansen closure');\n";
  exercise.variant_task = [](const Variant& variant) { return jansen_lengths_task_text(leg_for(variant)); };
  exercise.battery = [](const Variant& variant) {
    const JansenVariant leg = leg_for(variant);
    auto [cycle, exact] = cycle_requests(variant, leg);
    return std::vector<Check>{
        {"Newton reaches the closed-form pose at every 10 degrees of the crank cycle, within 2 ||J^-1|| (tolerance + "
         "rounding)",
         1, [cycle = cycle, exact = exact](Session& s) { return Battery::converges_to(s, cycle, exact); }},
        {"A 'converged' status is backed by ||f(theta)||_inf <= tolerance, and max_iterations is kept", 2,
         [requests = honest_requests(variant, leg)](Session& s) { return Battery::honest(s, requests); }},
        {"The trace follows numlab's Newton from the same start, iteration by iteration", 3,
         [requests = trace_requests(variant, leg)](Session& s) { return Battery::trace_matches(s, requests); }},
    };
  };
  return exercise;
}

}  // namespace numlab::exercises
