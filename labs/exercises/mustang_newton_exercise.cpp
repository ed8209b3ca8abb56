// mustang-newton: the student's full Newton on seed 003's Mustang roof linkage (angles A ... H),
// against the closed form across the assembly range, at and beyond its assembly limits, and
// against numlab's Newton trace.

#include <fmt/format.h>

#include "exercises/exercise_list.hpp"
#include "exercises/jansen_poses.hpp"
#include "exercises/newton_battery.hpp"
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
    const auto answer = Battery::ask(session, from(deg, start, 1e-10, 30));
    if (answer.reply.status == "converged") {
      return Verdict::fail(
          fmt::format("theta {} deg: status \"converged\", but the linkage cannot assemble there ({} cannot close, by the "
                      "closed form; the assembly range is -41.4257 ... 56.4540 deg); your ||f||_inf = {}, tolerance 1e-10",
                      deg, mechanisms::mustang_loop_names[static_cast<std::size_t>(closed.failed_loop - 1)],
                      sci(answer.reply.residual_inf)),
          "past an assembly limit no angles satisfy f = 0: only max |f_i| <= tolerance may say converged (not "
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
  exercise.task = R"(# mustang-newton: Newton-Raphson on the Ford Mustang roof linkage

Write `solve(request)`: full Newton-Raphson on the 8 loop-closure equations below, from the guess.

- **Request:** `crank_angle` (theta, radians: the direction of link 2->4 from +x), `guess`
  (A ... H, radians), `tolerance`, `max_iterations`.
- **Reply:** `angles` (A ... H), `status` (`"converged"` only when max_i |f_i| <= tolerance;
  otherwise `"max_iterations"`, `"singular"`, ...), `iterations` (at most `max_iterations`),
  and `trace`: one entry per iteration `{"residual_inf", "step_inf"}` as in jansen-newton.

### The model (as `numlab mechanism mustang`; docs/mechanisms.md)

Fixed points P0 = (sqrt 0.5, 0), P1 = (0, sqrt 0.5), P2 = (0, 1 + sqrt 0.5). A, B, D, F are
directions from +x; C, E, G, H are measured from -x turning towards +y (a link "at C" points along
(-cos C, sin C)). Lengths (seed 003): |1 3| = |3 4| = 2, |0 5| = 5, |2 4| = 2.5, |5 6| = 4/3,
|6 7| = 4/3, |6 8| = 4, |8 9| = 1, |7 10| = 4.5, |10 8| = 4/3, |10 11| = 4/3, |9 11| = 1. The bend
b = pi/9 (20 degrees) exactly; the chord |2 6| = 2 (2.5) cos(b) (the seed's 4.698, exact here).

    f[0] = -2.5 cos(theta) + 2 cos A + 2 cos B                                         loop 1 (A, B), x
    f[1] = -1 - 2.5 sin(theta) + 2 sin A + 2 sin B                                     loop 1, y
    f[2] = -sqrt0.5 + |2 6| cos(theta + b) + (4/3) cos C - 5 cos D                     loop 2 (C, D), x
    f[3] = 1 + sqrt0.5 + |2 6| sin(theta + b) - (4/3) sin C - 5 sin D                  loop 2, y
    f[4] = (4/3) cos(theta + b) + 4 cos(C - b) - 4.5 cos E - (4/3) cos F              loop 3 (E, F), x
    f[5] = (4/3) sin(theta + b) - 4 sin(C - b) + 4.5 sin E - (4/3) sin F              loop 3, y
    f[6] = cos(C + b) + (4/3) cos F - (4/3) cos G + cos H                              loop 4 (G, H), x
    f[7] = -sin(C + b) + (4/3) sin F + (4/3) sin G - sin H                             loop 4, y

The linkage assembles on the seed's branch only for theta from -41.4257 to 56.4540 degrees.

## Task 1
Newton converges to the closed-form pose at 14 angles across the assembly range, near both
limits included, each from the pose 2 degrees nearer the middle (tolerance 1e-10). The allowed
distance is 2 ||J^-1||_inf (tolerance + 1e3 eps L): kappa(J) grows towards the limits.

## Task 2
Beyond the assembly limits (-42, -45, 57, 60 degrees) there is no root: never say
`"converged"` there.

## Task 3
A status `"converged"` is backed by max_i |f_i(angles)| <= tolerance (numlab re-evaluates f), and
`iterations` never exceeds `max_iterations`. One start has residual components +0.05 and -0.05
in every loop.

## Task 4
The trace follows numlab's Newton (GEPP inner solve) from the same start, iteration by iteration.

## Hints
- Seed 003's stop test |f_i + f_j| < 0.001 lets the two components of a loop cancel.
- Seed 003's loop-3 Jacobian had its second row's signs flipped, and d f[7]/dH (loop 4, y) read D for H.
- Use the guess you are given: seed 003 restarted every loop from [pi/18, pi/2].
)";
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
