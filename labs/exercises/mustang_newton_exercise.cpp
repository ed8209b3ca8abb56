// mustang-newton: the student's full Newton on seed 003's Mustang roof linkage (angles A ... H),
// against the closed form across the assembly range, at and beyond its assembly limits, and
// against numlab's Newton trace.

#include <fmt/format.h>

#include "exercises/exercise_list.hpp"
#include "exercises/jansen_poses.hpp"
#include "exercises/newton_battery.hpp"
#include "exercises/task_texts.hpp"
#include "numlab/mechanisms/mustang_linkage.hpp"

namespace numlab::exercises {

namespace {

using mechanisms::MustangClosure;
using mechanisms::MustangLinkage;

double mustang_links_sum() { return 34.8; }  // docs/mechanisms.md: L for the Mustang

struct MustangNewton {
  using Closure = MustangClosure;
  static constexpr const char* input = "crank_angle";
  static constexpr const char* start = "guess";
  static constexpr const char* answer = "angles";
  static std::string angle_name(int k) { return std::string(mechanisms::mustang_angle_names[static_cast<std::size_t>(k)]); }
  static double links_sum() { return mustang_links_sum(); }
  static std::string where(double angle) { return fmt::format("theta {:.4g} deg", angle / degrees); }
};

using Battery = NewtonBattery<MustangNewton>;
using Request = Battery::Request;

// A ... H of the closed form at theta (degrees); the linkage must assemble there.
MustangClosure::Vector exact_at(double deg) {
  const MustangLinkage linkage;
  const auto closed = linkage.closed_form(deg * degrees);
  if (closed.status != Status::converged) throw std::logic_error(fmt::format("the Mustang does not assemble at {} deg", deg));
  return MustangLinkage::angles_of(closed.joints, MustangClosure::seed_guess());
}

Request from(double deg, double start_deg, double tolerance, int max_iterations) {
  return {deg * degrees, exact_at(start_deg), tolerance, max_iterations};
}

// Across the range -41.4257 ... 56.4540 deg, each start 2 degrees nearer the middle; near both
// limits; not across the kite's crossing at 43.15 deg, where loop 4's Jacobian is singular.
Verdict assembly_range(Session& session) {
  std::vector<Request> requests;
  std::vector<MustangClosure::Vector> exact;
  for (double deg : {-41.3, -40.0, -30.0, -20.0, -10.0, 0.0, 10.0, 20.0, 30.0, 40.0, 48.0, 52.0, 55.0, 56.3}) {
    const double start = deg < 10.0 ? deg + 2.0 : deg - 2.0;
    requests.push_back(from(deg, start, 1e-10, 30));
    exact.push_back(exact_at(deg));
  }
  return Battery::converges_to(session, requests, exact);
}

Verdict no_assembly(Session& session) {
  const MustangLinkage linkage;
  for (const auto& [deg, start] : std::vector<std::pair<double, double>>{{-42.0, -41.3}, {-45.0, -41.3}, {57.0, 56.3},
                                                                         {60.0, 56.3}}) {
    const auto closed = linkage.closed_form(deg * degrees);
    if (closed.status == Status::converged) throw std::logic_error("the Mustang assembles beyond its limits");
    const Request request = from(deg, start, 1e-10, 30);
    const auto answer = Battery::ask(session, request);
    if (answer.reply.status == "converged") {
      return Verdict::fail(
          fmt::format("theta {} deg: status \"converged\", but the linkage cannot assemble there ({} cannot close, by the "
                      "closed form; the assembly range is -41.4257 ... 56.4540 deg); your ||f||_inf = {}, tolerance 1e-10",
                      deg, mechanisms::mustang_loop_names[static_cast<std::size_t>(closed.failed_loop - 1)],
                      sci(answer.reply.residual_inf)),
          Battery::diagnosis(request, answer), "past an assembly limit no angles satisfy f = 0: only max |f_i| <= tolerance may say converged (not "
          "|f_i + f_j|, which lets components cancel)");
    }
  }
  return Verdict::pass();
}

Verdict honest_status(Session& session) {
  std::vector<Request> requests;
  // A start where loop k's components are +0.05 and -0.05: seed 003's |f_i + f_j| < 0.001 passes.
  const double deg = 20.0;
  MustangClosure::Vector cancelling;
  cancelling << 0.05, -0.05, 0.05, -0.05, 0.05, -0.05, 0.05, -0.05;
  requests.push_back({deg * degrees, start_with_residual(MustangClosure(deg * degrees), exact_at(deg), cancelling), 1e-3, 30});
  // Too few iterations to converge: the honest status is max_iterations.
  for (double at : {-30.0, 0.0, 30.0}) requests.push_back(from(at, at + 8.0, 1e-12, 2));
  requests.push_back(from(10.0, 12.0, 1e-10, 30));
  return Battery::honest(session, requests);
}

Verdict trace(Session& session) {
  std::vector<Request> requests;
  for (double deg : {-20.0, 0.0, 20.0, 35.0}) requests.push_back(from(deg, deg - 3.0, 1e-10, 30));
  return Battery::trace_matches(session, requests);
}

}  // namespace

Exercise mustang_newton_exercise() {
  Exercise exercise;
  exercise.name = "mustang-newton";
  exercise.summary = "full Newton-Raphson on seed 003's Mustang roof linkage (A ... H), up to its assembly limits";
  exercise.task = task_text("mustang-newton");
  exercise.stubs.python = "    raise NotImplementedError(\"not implemented: Newton-Raphson on the Mustang linkage\")\n";
  exercise.stubs.cpp = "  throw std::runtime_error(\"not implemented: Newton-Raphson on the Mustang linkage\");\n";
  exercise.stubs.octave = "  error('not implemented: Newton-Raphson on the Mustang linkage');\n";
  exercise.battery = [] {
    return std::vector<Check>{
        {"Newton reaches the closed-form pose across the assembly range, near both limits, within 2 ||J^-1|| "
         "(tolerance + rounding)",
         1, assembly_range},
        {"No 'converged' status beyond the assembly limits (-41.43 deg, 56.45 deg), where no root exists", 2, no_assembly},
        {"A 'converged' status is backed by ||f(angles)||_inf <= tolerance, and max_iterations is kept", 3, honest_status},
        {"The trace follows numlab's Newton from the same start, iteration by iteration", 4, trace},
    };
  };
  return exercise;
}

}  // namespace numlab::exercises
