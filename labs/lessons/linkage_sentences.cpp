#include "lessons/linkage_sentences.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace numlab::cli {

namespace {

// "1 block" or "3 blocks".
std::string counted(int count, const std::string& word) { return fmt::format("{} {}{}", count, word, count == 1 ? "" : "s"); }

}  // namespace

std::string derived_model_sentence(const DerivedModelSummary& model) {
  int dyads = 0, explicit_blocks = 0, newton = 0;
  for (const std::string& kind : model.block_kinds) {
    if (kind.starts_with("dyad")) ++dyads;
    else if (kind.ends_with("explicit")) ++explicit_blocks;
    else ++newton;
  }
  const int blocks = static_cast<int>(model.block_kinds.size());
  // 1. Unknowns, equations, mobility.
  std::string text = fmt::format("{}'s {} give {} (the x and y of each) and {}; the mobility is {}{}. ", model.file,
                                 counted(model.moving_joints, "moving joint"), counted(model.unknowns, "unknown"),
                                 counted(model.equations, "equation"), model.mobility,
                                 model.mobility == 1 ? ": the driver's value fixes every pose" : "");
  // 2. The blocks, and what they allow.
  text += fmt::format("Of its {}, {} and {} explicit; ", counted(blocks, "block"),
                      dyads == 0   ? std::string("none is a dyad")
                      : dyads == 1 ? std::string("1 is a dyad in closed form")
                                   : fmt::format("{} are dyads in closed form", dyads),
                      explicit_blocks == 1 ? "1 is" : fmt::format("{} are", explicit_blocks));
  text += newton == 0 ? "none needs Newton, so --solver analytic solves the whole linkage in closed form."
                      : fmt::format("{} need{} Newton (joints that can only be found together), so --solver analytic "
                                    "does not apply.",
                                    newton, newton == 1 ? "s" : "");
  return text;
}

std::string sequential_against_full_sentence(const SolverCost& sequential, const SolverCost& full, int unknowns) {
  // 1. Which is faster, and by how much.
  std::string text = fmt::format("Sequential Newton is {} full Newton ({:.3g} s against {:.3g} s per cycle). ",
                                 speed_ratio_phrase(sequential.time_s, full.time_s), sequential.time_s, full.time_s);
  // 2. Why, in the two measured factors: iterations, and the cost of one.
  const double per_sequential = sequential.time_s / sequential.iterations, per_full = full.time_s / full.iterations;
  text += fmt::format("It takes {:.1f}x as many iterations ({} block iterations against {}), ",
                      static_cast<double>(sequential.iterations) / full.iterations, sequential.iterations,
                      full.iterations);
  text += per_sequential < per_full ? fmt::format("and each costs {:.1f}x less.", per_full / per_sequential)
                                    : fmt::format("and each costs {:.1f}x more.", per_sequential / per_full);
  // 3. What one block iteration does.
  text += fmt::format(" A block iteration evaluates only its own rows and their Jacobian entries and solves a system "
                      "of the block's size (a dyad's 2x2 by the closed-form inverse) where full Newton runs GEPP on "
                      "{0}x{0}; a crank or a body point is placed by its formula, with no iteration.",
                      unknowns);
  return text;
}

std::string derivative_check_sentence(const std::vector<DerivativeRow>& rows, const std::string& joint) {
  double velocity = 0.0, acceleration = 0.0, slowest = INFINITY, fastest = 0.0, seed = 0.0;
  for (const DerivativeRow& row : rows) {
    velocity = std::max(velocity, row.velocity_difference);
    acceleration = std::max(acceleration, row.acceleration_difference);
    slowest = std::min(slowest, row.foot_speed);
    fastest = std::max(fastest, row.foot_speed);
    seed = std::max(seed, std::abs(row.foot_speed - row.seed_foot_speed) / row.seed_foot_speed);
  }
  return fmt::format("At these {} poses the velocities from J qdot = -Phi_t differ from central differences of "
                     "solved positions by at most {:.2g}, and the accelerations from J qddot = gamma from the 7-point "
                     "stencil by at most {:.2g} (relative to the largest). {}'s speed ranges from {:.2f} to {:.2f} per "
                     "radian of crank over them, and differs from seed 000's hand-derived rates by at most {:.2g} "
                     "(relative).",
                     rows.size(), velocity, acceleration, joint, slowest, fastest, seed);
}

double measured_exponent(double far, double value_far, double near, double value_near) {
  return std::log(value_near / value_far) / std::log(near / far);
}

std::string limit_approach_sentence(const LimitApproach& approach, double far, double near) {
  std::vector<double> mus, kappas;
  const LimitApproachRow *at_far = nullptr, *at_near = nullptr;
  for (const LimitApproachRow& row : approach.rows) {
    mus.push_back(row.mu_deg);
    kappas.push_back(row.kappa);
    if (row.before_deg == far) at_far = &row;
    if (row.before_deg == near) at_near = &row;
  }
  // 1. Where, and which block.
  std::string text = fmt::format("Bisection puts the limit at {:.2f} deg (final bracket {:.2g} deg): {} cannot close "
                                 "beyond it. ",
                                 approach.limit_deg, approach.bracket_deg, approach.block);
  // 2. What the rows show on the way there.
  text += fmt::format("Towards it, {}'s transmission angle {} deg, and kappa(J) {}. ", approach.joint,
                      trend_phrase(mus), trend_phrase(kappas));
  if (at_far == nullptr || at_near == nullptr) return text;
  // 3. How fast: the powers of the distance d between two rows.
  const double kappa = measured_exponent(far, at_far->kappa, near, at_near->kappa);
  const double speed = measured_exponent(far, at_far->speed, near, at_near->speed);
  const double mu = measured_exponent(far, at_far->mu_deg, near, at_near->mu_deg);
  text += fmt::format("From {:g} to {:g} deg before the limit, kappa(J) grows like d^{:.2f}, {}'s speed like d^{:.2f} "
                      "and its transmission angle falls like d^{:.2f} (d the distance from the limit)",
                      far, near, kappa, approach.joint, speed, mu);
  const bool fold = std::abs(kappa + 0.5) <= 0.1 && std::abs(speed + 0.5) <= 0.1 && std::abs(mu - 0.5) <= 0.1;
  text += fold ? ": within 0.1 of the square-root law of a fold, where the dyad's two assemblies meet and J becomes "
                 "singular."
               : ": not the square-root law of a simple fold (exponents -1/2, -1/2, 1/2).";
  return text;
}

std::string over_modelling_sentence(const std::vector<ModelCost>& rows) {
  if (rows.size() != 3) return "";
  const ModelCost &ten = rows[0], &eight = rows[1], &derived = rows[2];
  const auto share = [](const ModelCost& m) { return 100.0 * m.nonzeros / (m.unknowns * m.unknowns); };
  // 1. The same leg, to what accuracy.
  std::string text = fmt::format("All three trace the same leg: the worst joint distance from seed 000's closed form "
                                 "is {:.2g} ({}), {:.2g} ({}) and {:.2g} ({}). ",
                                 ten.error, ten.name, eight.error, eight.name, derived.error, derived.name);
  // 2. Angles: two unknowns more for a triangle that is rigid anyway.
  text += fmt::format("Seed 001's {} unknowns are {} more than seed 000's {} and model nothing new (the triangle "
                      "D-E-F is rigid): its full Newton is {} seed 000's ({:.3g} s against {:.3g} s per cycle). ",
                      ten.unknowns, ten.unknowns - eight.unknowns, eight.unknowns,
                      speed_ratio_phrase(ten.time_s, eight.time_s), ten.time_s, eight.time_s);
  // 3. Joint coordinates: more unknowns, a sparser Jacobian, eliminated densely all the same.
  text += fmt::format("The derived model has {} unknowns, but only {} of its {} Jacobian entries are nonzero "
                      "({:.0f}%, against {:.0f}% for seed 000's {}x{} and {:.0f}% for seed 001's {}x{}). Full Newton "
                      "eliminates it as a dense matrix all the same, about ({}/{})^3 = {:.1f} times the operations "
                      "of the {}x{} LU, and is {} on seed 000's {} equations ({:.3g} s against {:.3g} s, {} iterations "
                      "against {}).",
                      derived.unknowns, derived.nonzeros, derived.unknowns * derived.unknowns, share(derived),
                      share(eight), eight.unknowns, eight.unknowns, share(ten), ten.unknowns, ten.unknowns,
                      derived.unknowns, eight.unknowns, std::pow(static_cast<double>(derived.unknowns) / eight.unknowns, 3),
                      eight.unknowns, eight.unknowns, speed_ratio_phrase(derived.time_s, eight.time_s), eight.unknowns,
                      derived.time_s, eight.time_s, derived.iterations, eight.iterations);
  return text;
}

std::string crossing_sentence(const CrossingPassage& c) {
  const auto vector_text = [](const Eigen::Vector2d& v) { return fmt::format("({:.4f}, {:.4f})", v.x(), v.y()); };
  // 1. Where: J singular, as the condition number says.
  std::string text = fmt::format("At crank {:.3f} deg the two assembly branches cross: kappa(J) is {:.3g} there, against "
                                 "{:.3g} at the first pose. ",
                                 c.crossing_deg, c.kappa_at, c.kappa_away);
  // 2. The tangents either side: the smooth branch's continues the incoming one.
  const double turn = std::acos(std::clamp(c.before.normalized().dot(c.after.normalized()), -1.0, 1.0)) * 180.0 / std::acos(-1.0);
  const double other_turn =
      std::acos(std::clamp(c.before.normalized().dot(c.other_after.normalized()), -1.0, 1.0)) * 180.0 / std::acos(-1.0);
  text += fmt::format("{:g} deg before it {} moves at {} per radian of crank, {:g} deg after it at {} on the branch the sweep "
                      "followed ({:.1f} deg of turn: the incoming tangent goes on) and at {} on the other ({:.1f} deg of "
                      "turn). ",
                      c.step_deg, c.joint, vector_text(c.before), c.step_deg, vector_text(c.after), turn,
                      vector_text(c.other_after), other_turn);
  // 3. The side, which a sign test would have misread as a jump.
  text += fmt::format("On the smooth branch {} changes side, from {} to {}: a branch test by sides alone would call this "
                      "a jump; --at-crossing switch takes the other branch",
                      c.joint, c.side_before, c.side_after);
  return text + ".";
}

std::string driving_torque_sentence(const std::vector<DrivingTorqueRow>& rows) {
  double work = 0.0, potential = 0.0, low = INFINITY, high = -INFINITY, largest = 0.0, at = 0.0;
  for (const DrivingTorqueRow& r : rows) {
    work = std::max(work, std::abs(r.multipliers - r.virtual_work) / r.scale);
    potential = std::max(potential, std::abs(r.multipliers - r.potential) / r.scale);
    low = std::min(low, r.multipliers), high = std::max(high, r.multipliers);
    if (std::abs(r.multipliers) > largest) largest = std::abs(r.multipliers), at = r.crank_deg;
  }
  return fmt::format("At these {} poses the driver torque from one more linear solve with J (J^T lambda = Q, tau = lambda . "
                     "Phi_t) is the virtual work's -sum F . v_J to {:.2g} and the central difference of the loads' "
                     "potential to {:.2g}, both relative to the loads' terms: the multipliers are the constraint forces, and "
                     "the driver's own multiplier is the torque. Over these poses it runs from {:.4g} to {:.4g} N x length "
                     "unit, largest in size at crank {:g} deg.",
                     rows.size(), work, potential, low, high, at);
}

std::string quick_return_sentence(const QuickReturnSummary& q) {
  // 1. The two strokes in crank degrees, and their ratio.
  std::string text = fmt::format("With the crank turning steadily the way its angle grows, {0}'s forward (slow) stroke, from "
                                 "{1:.6g} to {2:.6g}, takes {3:.4f} deg of crank and the return {4:.4f} deg: "
                                 "ratio {3:.4f} / {4:.4f} = {5:.4f}, so {0} comes back {5:.4f} times faster than it goes. ",
                                 q.output, q.slow_from, q.slow_to, q.slow_deg, q.quick_deg, q.time_ratio);
  // 2. The root finding against the closed form.
  text += fmt::format("Brent's toggles on the velocity ratio are the closed form's ({}) to {:.2g} deg, and the time "
                      "ratio is its {:.4f} to {:.2g}.",
                      q.closed_form, q.toggle_difference, q.closed_form_ratio, std::abs(q.time_ratio - q.closed_form_ratio));
  return text;
}

}  // namespace numlab::cli
