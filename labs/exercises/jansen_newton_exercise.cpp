// jansen-newton: the student's full Newton on seed 000's 8-equation Jansen closure, against the
// closed form over a whole crank cycle, the residual test, and numlab's Newton trace.

#include <fmt/format.h>

#include "exercises/exercise_list.hpp"
#include "exercises/jansen_poses.hpp"
#include "exercises/newton_battery.hpp"
#include "exercises/task_texts.hpp"
#include "numlab/mechanisms/jansen_closure.hpp"

namespace numlab::exercises {

namespace {

struct JansenNewton {
  using Closure = mechanisms::JansenClosure;
  static constexpr const char* input = "crank_angle";
  static constexpr const char* start = "theta0";
  static constexpr const char* answer = "theta";
  static std::string angle_name(int k) { return jansen_angle_name(k); }
  static double links_sum() { return jansen_links_sum(); }
  static std::string where(double angle) { return fmt::format("crank {:.4g} deg", angle / degrees); }
};

using Battery = NewtonBattery<JansenNewton>;
using Request = Battery::Request;

// From the closed-form pose `back_deg` earlier in the cycle.
Request from_behind(double deg, double back_deg, double tolerance, int max_iterations) {
  return {deg * degrees, jansen_closed_form_angles((deg - back_deg) * degrees), tolerance, max_iterations};
}

Verdict whole_cycle(Session& session) {
  std::vector<Request> requests;
  std::vector<Battery::Vector> exact;
  for (int deg = 0; deg < 360; deg += 10) {
    requests.push_back(from_behind(deg, 10.0, 1e-10, 20));
    exact.push_back(jansen_closed_form_angles(deg * degrees));
  }
  return Battery::converges_to(session, requests, exact);
}

Verdict honest_status(Session& session) {
  std::vector<Request> requests;
  // Too few iterations from far away: the honest status is max_iterations.
  for (double deg : {20.0, 110.0, 200.0, 290.0}) requests.push_back(from_behind(deg, 40.0, 1e-12, 2));
  // A start where every component of f is -0.5: a signed stop test (f_i < tol) passes there.
  const double deg = 60.0;
  const mechanisms::JansenClosure closure(deg * degrees);
  const auto start = start_with_residual(closure, jansen_closed_form_angles(deg * degrees),
                                         mechanisms::JansenClosure::Vector::Constant(-0.5));
  requests.push_back({deg * degrees, start, 1e-9, 20});
  // The seed's tolerances: 1e-5 (seed 000) and 1e-9 (seed 001).
  requests.push_back(from_behind(150.0, 10.0, 1e-5, 10));
  requests.push_back(from_behind(250.0, 10.0, 1e-9, 20));
  return Battery::honest(session, requests);
}

Verdict trace(Session& session) {
  std::vector<Request> requests;
  for (double deg : {30.0, 150.0, 240.0, 330.0}) requests.push_back(from_behind(deg, 20.0, 1e-10, 20));
  return Battery::trace_matches(session, requests);
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
  exercise.battery = [] {
    return std::vector<Check>{
        {"Newton reaches the closed-form pose at every 10 degrees of the crank cycle, within 2 ||J^-1|| (tolerance + "
         "rounding)",
         1, whole_cycle},
        {"A 'converged' status is backed by ||f(theta)||_inf <= tolerance, and max_iterations is kept", 2, honest_status},
        {"The trace follows numlab's Newton from the same start, iteration by iteration", 3, trace},
    };
  };
  return exercise;
}

}  // namespace numlab::exercises
