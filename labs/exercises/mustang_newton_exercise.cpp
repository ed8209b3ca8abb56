// mustang-newton: the student's full Newton on seed 003's Mustang roof linkage (angles A ... H),
// against the closed form across the assembly range, at and beyond its assembly limits, and
// against numlab's Newton trace.

#include <algorithm>
#include <fmt/format.h>
#include <optional>
#include <utility>

#include "exercises/exercise_list.hpp"
#include "exercises/jansen_poses.hpp"
#include "exercises/mustang_variant.hpp"
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
  using Lengths = mechanisms::MustangLengths;
  static constexpr const char* input = "crank_angle";
  static constexpr const char* start = "guess";
  static constexpr const char* answer = "angles";
  static std::string angle_name(int k) { return std::string(mechanisms::mustang_angle_names[static_cast<std::size_t>(k)]); }
  static double links_sum() { return mustang_links_sum(); }
  static std::string where(double angle) { return fmt::format("theta {:.4g} deg", angle / degrees); }
  static std::vector<SlippedClosure> constant_angle_slips(const Lengths& lengths);
};

// The 20-degree bend typed as 20 and used as radians: everywhere (the chord |2 6| = 5 cos(b) too),
// or in the angles only (theta + b, C - b, C + b) with the chord typed as its value.
std::vector<SlippedClosure> MustangNewton::constant_angle_slips(const Lengths& lengths) {
  mechanisms::MustangLengths typed = lengths;
  typed.bend = 20.0;
  const double chord_error = lengths.chord2_6() - typed.chord2_6();
  auto in_angles = [typed](double chord_shift) {
    return [typed, chord_shift](double theta, const Eigen::VectorXd& x) {
      MustangClosure::Vector f;
      MustangClosure::Matrix J;
      MustangClosure(theta, typed).residual_and_jacobian(MustangClosure::Vector(x), f, J);
      f(2) += chord_shift * std::cos(theta + typed.bend);  // loop 2 reaches P6 along the chord at theta + b
      f(3) += chord_shift * std::sin(theta + typed.bend);
      return ClosureValues{Eigen::VectorXd(f), Eigen::MatrixXd(J)};
    };
  };
  return {{"the bend typed as 20 (degrees) and used as radians, in cos(theta + b) and in the chord 5 cos(b)", in_angles(0.0)},
          {"the bend typed as 20 (degrees) and used as radians in cos(theta + b), cos(C - b), cos(C + b)",
           in_angles(chord_error)}};
}

using Battery = NewtonBattery<MustangNewton>;
using Request = Battery::Request;

// A ... H of the closed form of `linkage` at theta (degrees); the linkage must assemble there
// (std::logic_error otherwise).
MustangClosure::Vector exact_at(const MustangVariant& linkage, double deg) {
  const auto closed = MustangLinkage(linkage.lengths).closed_form(deg * degrees);
  if (closed.status != Status::converged) throw std::logic_error(fmt::format("the Mustang does not assemble at {} deg", deg));
  return MustangLinkage::angles_of(closed.joints, MustangClosure::seed_guess());
}

Request from(const MustangVariant& linkage, double deg, double start_deg, double tolerance, int max_iterations) {
  return {deg * degrees, exact_at(linkage, start_deg), tolerance, max_iterations, linkage.lengths,
          linkage.varied ? linkage.named() : LinkLengths{}};
}

bool assembles(const MustangVariant& linkage, double deg) {
  return MustangLinkage(linkage.lengths).closed_form(deg * degrees).status == Status::converged;
}

// With a variant, an angle of a request is moved by a draw from it: `deg` + uniform [-spread,
// spread), re-drawn until the linkage assembles there and at its start (the moved angle +
// `start_offset`) and the two lie on one side of the kite's crossing (43.15 deg for seed 003's
// lengths; 1 deg clear), where loop 4's Jacobian is singular. Without a variant, `deg`. After 1000
// draws, std::logic_error (the variant's lengths are drawn again).
class Moves {
 public:
  Moves(const Variant& variant, unsigned base, const MustangVariant& linkage)
      : active_(variant.active()), stream_(variant.stream(base)), linkage_(linkage) {}
  double operator()(double deg, double spread, double start_offset) {
    if (!active_) return deg;
    const double crossing = linkage_.crossing_deg;
    for (int draw = 0; draw < 1000; ++draw) {
      const double moved = deg + stream_.uniform(-spread, spread), start = moved + start_offset;
      const bool clear = std::min(moved, start) > crossing + 1.0 || std::max(moved, start) < crossing - 1.0;
      if (clear && assembles(linkage_, moved) && assembles(linkage_, start)) return moved;
    }
    throw std::logic_error(fmt::format("no angle near {} deg for this variant's Mustang", deg));
  }
  // An angle beyond the assembly limits, drawn from [low, high) (`deg` without a variant).
  double beyond(double deg, double low, double high) {
    if (!active_) return deg;
    for (int draw = 0; draw < 1000; ++draw) {
      const double moved = stream_.uniform(low, high);
      if (!assembles(linkage_, moved)) return moved;
    }
    throw std::logic_error(fmt::format("no angle in [{}, {}) deg beyond this variant's limits", low, high));
  }

 private:
  bool active_;
  Variant::Stream stream_;
  const MustangVariant& linkage_;
};

// Across the range (-41.4257 ... 56.4540 deg for seed 003's lengths), each start 2 degrees nearer the
// middle; near both limits; not across the kite's crossing, where loop 4's Jacobian is singular.
// With a variant, the angles near a limit move with it (-41.3 is 0.1257 deg inside the lower limit),
// and each but the two nearest the limits is moved by up to 4 deg (1.5 deg near the limits).
std::pair<std::vector<Request>, std::vector<MustangClosure::Vector>> range_requests(const Variant& variant,
                                                                                    const MustangVariant& linkage) {
  Moves move(variant, 1, linkage);
  std::vector<Request> requests;
  std::vector<MustangClosure::Vector> exact;
  for (double deg : {-41.3, -40.0, -30.0, -20.0, -10.0, 0.0, 10.0, 20.0, 30.0, 40.0, 48.0, 52.0, 55.0, 56.3}) {
    const double offset = deg < 10.0 ? 2.0 : -2.0;
    const bool edge = deg <= -40.0 || deg >= 48.0;
    const bool limit = deg == -41.3 || deg == 56.3;
    if (edge) deg += deg < 0.0 ? linkage.lower_shift() : linkage.upper_shift();
    if (!limit) deg = move(deg, edge ? 1.5 : 4.0, offset);
    requests.push_back(from(linkage, deg, deg + offset, 1e-10, 30));
    exact.push_back(exact_at(linkage, deg));
  }
  return {requests, exact};
}

std::string range_text(const MustangVariant& linkage) {
  return fmt::format("{:.4f} ... {:.4f} deg", linkage.lower_deg, linkage.upper_deg);
}

Verdict no_assembly(Session& session, const std::vector<std::pair<double, double>>& angles, const MustangVariant& linkage) {
  const MustangLinkage mechanism(linkage.lengths);
  for (const auto& [deg, start] : angles) {
    const auto closed = mechanism.closed_form(deg * degrees);
    if (closed.status == Status::converged) throw std::logic_error("the Mustang assembles beyond its limits");
    const Request request = from(linkage, deg, start, 1e-10, 30);
    const auto answer = Battery::ask(session, request);
    if (answer.reply.status == "converged") {
      return Verdict::fail(
          fmt::format("theta {} deg: status \"converged\", but the linkage cannot assemble there ({} cannot close, by the "
                      "closed form; the assembly range is {}); your ||f||_inf = {}, tolerance 1e-10",
                      deg, mechanisms::mustang_loop_names[static_cast<std::size_t>(closed.failed_loop - 1)],
                      range_text(linkage), sci(answer.reply.residual_inf)),
          Battery::diagnosis(request, answer), "past an assembly limit no angles satisfy f = 0: only max |f_i| <= tolerance may say converged (not "
          "|f_i + f_j|, which lets components cancel)");
    }
  }
  return Verdict::pass();
}

// Beyond the limits, each from the pose at the nearer limit; with a variant, drawn past each limit
// (the windows moved with the variant's limits).
std::vector<std::pair<double, double>> beyond_limits(const Variant& variant, const MustangVariant& linkage) {
  Moves move(variant, 2, linkage);
  const double low = linkage.lower_shift(), high = linkage.upper_shift();
  return {{move.beyond(-42.0, -43.0 + low, -41.5 + low), -41.3 + low},
          {move.beyond(-45.0, -50.0 + low, -43.0 + low), -41.3 + low},
          {move.beyond(57.0, 56.5 + high, 58.0 + high), 56.3 + high},
          {move.beyond(60.0, 58.0 + high, 65.0 + high), 56.3 + high}};
}

// A start where loop k's components are +0.05 and -0.05 at `deg`, if numlab's damped Newton finds one.
std::optional<Request> cancelling_start(const MustangVariant& linkage, double deg) {
  MustangClosure::Vector cancelling;
  cancelling << 0.05, -0.05, 0.05, -0.05, 0.05, -0.05, 0.05, -0.05;
  const MustangClosure closure(deg * degrees, linkage.lengths);
  const MustangClosure::Vector start = start_with_residual(closure, exact_at(linkage, deg), cancelling);
  MustangClosure::Vector f;
  closure.residual(start, f);
  if ((f - cancelling).cwiseAbs().maxCoeff() > 1e-9) return std::nullopt;
  return Request{deg * degrees, start, 1e-3, 30, linkage.lengths, linkage.varied ? linkage.named() : LinkLengths{}};
}

std::vector<Request> honest_requests(const Variant& variant, const MustangVariant& linkage) {
  Moves move(variant, 3, linkage);
  std::vector<Request> requests;
  // A start where loop k's components are +0.05 and -0.05: seed 003's |f_i + f_j| < 0.001 passes.
  std::optional<Request> cancelling = cancelling_start(linkage, move(20.0, 8.0, 0.0));
  for (int draw = 0; !cancelling; ++draw) {  // only a variant's angle can miss
    if (draw == 100) throw std::logic_error("no cancelling start for this variant's Mustang");
    cancelling = cancelling_start(linkage, move(20.0, 8.0, 0.0));
  }
  requests.push_back(*cancelling);
  // Too few iterations to converge: the honest status is max_iterations.
  for (double at : {-30.0, 0.0, 30.0}) {
    at = move(at, 5.0, 8.0);
    requests.push_back(from(linkage, at, at + 8.0, 1e-12, 2));
  }
  const double at = move(10.0, 5.0, 2.0);
  requests.push_back(from(linkage, at, at + 2.0, 1e-10, 30));
  return requests;
}

std::vector<Request> trace_requests(const Variant& variant, const MustangVariant& linkage) {
  Moves move(variant, 4, linkage);
  std::vector<Request> requests;
  for (double deg : {-20.0, 0.0, 20.0, 35.0}) {
    deg = move(deg, 4.0, -3.0);
    requests.push_back(from(linkage, deg, deg - 3.0, 1e-10, 30));
  }
  return requests;
}

// The linkage: seed 003's, or a variant's for which every request of the battery can be built and
// numlab's Newton converges from the start of every range request (to the closed form) and of every
// trace request.
MustangVariant linkage_for(const Variant& variant) {
  return mustang_variant(variant, [&variant](const MustangVariant& candidate) {
    try {
      const auto [range, exact] = range_requests(variant, candidate);
      beyond_limits(variant, candidate);  // each throws when it finds no angle for its requests
      honest_requests(variant, candidate);
      return Battery::newton_converges(range, exact, trace_requests(variant, candidate));
    } catch (const std::logic_error&) {
      return false;
    }
  });
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
  exercise.variant_task = [](const Variant& variant) { return mustang_variant_task_text(linkage_for(variant)); };
  exercise.battery = [](const Variant& variant) {
    const MustangVariant linkage = linkage_for(variant);
    auto [range, exact] = range_requests(variant, linkage);
    return std::vector<Check>{
        {"Newton reaches the closed-form pose across the assembly range, near both limits, within 2 ||J^-1|| "
         "(tolerance + rounding)",
         1, [range = range, exact = exact](Session& s) { return Battery::converges_to(s, range, exact); }},
        {fmt::format("No 'converged' status beyond the assembly limits ({:.2f} deg, {:.2f} deg), where no root exists",
                     linkage.lower_deg, linkage.upper_deg),
         2, [angles = beyond_limits(variant, linkage), linkage](Session& s) { return no_assembly(s, angles, linkage); }},
        {"A 'converged' status is backed by ||f(angles)||_inf <= tolerance, and max_iterations is kept", 3,
         [requests = honest_requests(variant, linkage)](Session& s) { return Battery::honest(s, requests); }},
        {"The trace follows numlab's Newton from the same start, iteration by iteration", 4,
         [requests = trace_requests(variant, linkage)](Session& s) { return Battery::trace_matches(s, requests); }},
    };
  };
  return exercise;
}

}  // namespace numlab::exercises
