#include "output/linkage_report.hpp"

#include "numlab/mechanisms/linkage/linkage_statics.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "numlab/mechanisms/linkage/linkage_structure.hpp"
#include "output/driver_units.hpp"
#include "output/table.hpp"

namespace numlab::cli {

using namespace mechanisms;

namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

const std::string& joint_name(const LinkageModel& model, int joint) {
  return model.description().joints[static_cast<std::size_t>(joint)].name;
}

// The driver's CSV column: crank_deg, travel (a slider driver), length (an actuator), motor_deg.
std::string driver_column(const LinkageModel& model) {
  switch (model.driver_kind()) {
    case DriverKind::crank: return "crank_deg";
    case DriverKind::slider: return "travel";
    case DriverKind::actuator: return "length";
    case DriverKind::motor: return "motor_deg";
  }
  return "travel";
}

// The second driver's CSV column (a file with two drivers): crank2_deg, travel2 or length2.
std::string second_driver_column(const LinkageModel& model) {
  switch (model.description().second_driver->kind) {
    case DriverKind::crank: return "crank2_deg";
    case DriverKind::slider: return "travel2";
    default: return "length2";
  }
}

// The second driver's value at a pose: a driver path's row, or the value a sweep holds it at.
double second_driver_at(const LinkageModel& model, const LinkagePose& pose) {
  return std::isnan(pose.second_driver) ? model.second_driver() : pose.second_driver;
}

// A coordinate (or a speed, `decimals` 4) in the text table: the decimals it has for a model of size
// about 1, and more for a smaller one, so a model in micrometres shows as many digits as one in metres.
// A pose that did not assemble has no speed: "-".
std::string fixed_for_size(double value, int decimals, double size) {
  const int more = size > 0.0 && std::isfinite(size) ? std::max(0, -static_cast<int>(std::floor(std::log10(size)))) : 0;
  return fixed(value, decimals + more);
}

// The driver in words: "crank" or "motor" (per radian of it), "travel" or "length" (per unit of it).
std::string driver_word(const LinkageModel& model) {
  constexpr const char* words[] = {"crank", "travel", "length", "motor"};
  return words[static_cast<int>(model.driver_kind())];
}

bool converged(const LinkagePose& pose) { return pose.outcome.status == Status::converged; }

bool kept(const LinkageSolver&, const LinkagePose& pose) { return pose.branch_kept; }

// Every joint's position, velocity, acceleration at a pose (ground joints: fixed, zero).
struct JointMotion {
  Eigen::Vector2d p, v, a;
};
JointMotion motion(const LinkageModel& model, const LinkagePose& pose, int joint) {
  const int column = model.column_of(joint);
  if (column < 0) return {model.description().joints[static_cast<std::size_t>(joint)].position, {0, 0}, {0, 0}};
  const auto pick = [&](const Eigen::VectorXd& v) {
    return v.size() == 0 ? Eigen::Vector2d(nan, nan) : Eigen::Vector2d(v(column), v(column + 1));
  };
  return {pick(pose.q), pick(pose.velocity), pick(pose.acceleration)};
}

// The dyad blocks (those with a transmission angle), by index.
std::vector<std::size_t> dyads(const LinkageSolver& solver) {
  std::vector<std::size_t> out;
  for (std::size_t b = 0; b < solver.blocks().size(); ++b) {
    if (solver.blocks()[b].dyad()) out.push_back(b);
  }
  return out;
}

std::string block_joint_names(const LinkageModel& model, const LinkageBlock& block) {
  std::vector<std::string> names;
  for (int j : block.joints) names.push_back(joint_name(model, j));
  return fmt::format("{}", fmt::join(names, ", "));
}

// "B: 51.2 .. 128.8 deg, inside 40-140" or "... leaves 40-140 at 12 poses (from 100 to 111)".
std::string transmission_summary(const LinkageReport& r, std::size_t block) {
  double low = std::numeric_limits<double>::infinity(), high = -low;
  int outside = 0;
  double first = nan, last = nan;
  for (const auto& pose : r.sweep.poses) {
    if (!converged(pose)) continue;
    const double mu = pose.transmission_deg[block];
    low = std::min(low, mu), high = std::max(high, mu);
    if (mu < transmission_low_deg || mu > transmission_high_deg) {
      if (outside++ == 0) first = pose.driver;
      last = pose.driver;
    }
  }
  const std::string name = block_joint_names(r.model, r.solver.blocks()[block]);
  if (!std::isfinite(low)) return name + ": no assembled pose";
  std::string text = fmt::format("{}: {:.1f} .. {:.1f} deg", name, low, high);
  if (outside == 0) return text + fmt::format(", inside {:g}-{:g}", transmission_low_deg, transmission_high_deg);
  return text + fmt::format(", outside {:g}-{:g} at {} poses (from {:g} to {:g})", transmission_low_deg,
                            transmission_high_deg, outside, first, last);
}

// "34 poses (57 .. 90): the continuation from the last good pose failed at 56.4531, short of them; each
// repeats that failure", or empty when every pose was tried.
std::string not_tried_text(const LinkageSweep& sweep) {
  int count = 0;
  double first = nan, last = nan, past = nan;
  for (const auto& pose : sweep.poses) {
    if (std::isnan(pose.not_tried_past)) continue;
    if (count++ == 0) first = pose.driver, past = pose.not_tried_past;
    last = pose.driver;
  }
  if (count == 0) return {};
  return fmt::format("{} pose{} ({:g} .. {:g}): the continuation from the last good pose failed at {:.6g}, short of "
                     "{}; {} that failure, solved no further",
                     count, count == 1 ? "" : "s", first, last, past, count == 1 ? "it" : "them",
                     count == 1 ? "it repeats" : "each repeats");
}

std::string limit_text(const LinkageReport& r, const LinkageLimit& limit) {
  const std::string unit = r.model.crank_driven() ? " deg" : "";
  std::string where = "no block named";
  if (limit.block >= 0) {
    where = fmt::format("block {} ({}) cannot close", limit.block + 1,
                        describe_block(r.model, r.solver.blocks()[static_cast<std::size_t>(limit.block)]));
  }
  const std::string angle = std::isfinite(limit.transmission_deg)
                                ? fmt::format("; transmission angle there {:.2f} deg", limit.transmission_deg)
                                : "";
  if (limit.assembles_beyond) {
    return fmt::format("the solver failed {} {:.2f}{} (bisection bracket {:.2g}{}), yet the mechanism assembles just {} "
                       "it: not an assembly limit, a failure of the solver",
                       limit.upper ? "past" : "before", limit.driver, unit, limit.bracket, unit,
                       limit.upper ? "past" : "before");
  }
  return fmt::format("{} limit {:.2f}{} (a fold: the branch ends there; bisection bracket {:.2g}{}): {}{}",
                     limit.upper ? "upper" : "lower", limit.driver, unit, limit.bracket, unit, where, angle);
}

nlohmann::ordered_json number(double value) { return number_or_null(value); }

// The pose farthest from the closed form relative to its bound (NaN when there is no closed form).
struct ClosedFormWorst {
  double distance = std::numeric_limits<double>::quiet_NaN(), bound = std::numeric_limits<double>::quiet_NaN();
};
ClosedFormWorst worst_closed_form(const LinkageSweep& sweep) {
  ClosedFormWorst worst;
  double ratio = -1.0;
  for (const auto& pose : sweep.poses) {
    if (std::isnan(pose.closed_form_distance)) continue;
    const double r = pose.closed_form_distance / pose.closed_form_bound;
    if (r > ratio) ratio = r, worst = {pose.closed_form_distance, pose.closed_form_bound};
  }
  return worst;
}

constexpr double degrees = 180.0 / 3.141592653589793238462643383279502884;

// Every link's angle (radians here; degrees in the output), omega and alpha, and the output's
// velocity ratio, at a pose (NaN where the pose has no kinematics).
struct LinkRates {
  std::vector<AngularMotion> links;
  double ratio = nan;
};
LinkRates link_rates(const LinkageReport& r, const std::vector<LinkLine>& lines, const LinkagePose& pose) {
  const auto joints = joint_motions(r.model, pose.q, pose.velocity, pose.acceleration);
  LinkRates rates;
  for (const LinkLine& line : lines) {
    rates.links.push_back(angular_motion(joints[static_cast<std::size_t>(line.from)], joints[static_cast<std::size_t>(line.to)]));
  }
  if (r.output) rates.ratio = output_rate(*r.output, lines, joints);
  return rates;
}

// The columns after branch_kept: angle_L, omega_L, alpha_L per link and body; the output's
// velocity_ratio_O and mechanical_advantage_O; with --speed omega_L_rad_s and alpha_L_rad_s2.
void print_link_header(std::ostream& out, const LinkageReport& r, const std::vector<LinkLine>& lines) {
  for (const LinkLine& line : lines) out << ",angle_" << line.name << ",omega_" << line.name << ",alpha_" << line.name;
  if (r.output) out << ",velocity_ratio_" << r.output->name << ",mechanical_advantage_" << r.output->name;
  if (r.speed_rad_s) {
    for (const LinkLine& line : lines) out << ",omega_" << line.name << "_rad_s,alpha_" << line.name << "_rad_s2";
  }
}

// "Q-B: velocity ratio -0.52 .. 0.61 per radian of crank; mechanical advantage at least 1.64 in size (infinite at 1 pose)".
std::string output_summary(const LinkageReport& r) {
  const auto lines = link_lines(r.model.description());
  double low = std::numeric_limits<double>::infinity(), high = -low, least = low;
  int infinite = 0;
  for (const auto& pose : r.sweep.poses) {
    if (!converged(pose)) continue;
    const double ratio = link_rates(r, lines, pose).ratio, advantage = mechanical_advantage(ratio);
    if (std::isnan(ratio)) continue;
    low = std::min(low, ratio), high = std::max(high, ratio), least = std::min(least, std::abs(advantage));
    infinite += std::isinf(advantage) ? 1 : 0;
  }
  if (!std::isfinite(low)) return r.output->name + ": no assembled pose";
  return fmt::format("{}: velocity ratio {:.4g} .. {:.4g} per {}; mechanical advantage at least {:.4g} in size{}",
                     r.output->name, low, high, (r.model.crank_driven() ? "radian of " : "unit of ") + driver_word(r.model), least,
                     infinite > 0 ? fmt::format(" (infinite at {} pose{}: a toggle)", infinite, infinite == 1 ? "" : "s") : "");
}

// The statics columns after the link columns, when the file has [[load]]s: driver_torque (crank) or
// driver_force (slider), statics (equilibrium, singular, no_pose), reaction_<S>_x, reaction_<S>_y per
// support (ground joints, then slider joints).
bool has_loads(const LinkageReport& r) { return !r.model.description().loads.empty(); }
const char* driver_load_name(const LinkageModel& model) { return model.crank_driven() ? "driver_torque" : "driver_force"; }

void print_statics_header(std::ostream& out, const LinkageReport& r) {
  if (!has_loads(r)) return;
  out << ',' << driver_load_name(r.model) << ",statics";
  if (r.model.has_second_driver()) out << ',' << (r.model.description().second_driver->angle() ? "driver2_torque" : "driver2_force");
  for (const StaticsSupport& s : statics_supports(r.model.description())) out << ",reaction_" << s.name << "_x,reaction_" << s.name << "_y";
}

void print_statics_row(std::ostream& out, const LinkageModel& model, const LinkageStatics& statics) {
  out << fmt::format(",{:.17g},{}", statics.driver, to_string(statics.status));
  if (model.has_second_driver()) out << fmt::format(",{:.17g}", statics.second_driver);
  for (const Eigen::Vector2d& reaction : statics.reactions) out << fmt::format(",{:.17g},{:.17g}", reaction.x(), reaction.y());
}

nlohmann::ordered_json statics_json(const LinkageReport& r, const std::vector<StaticsSupport>& supports, const LinkageStatics& statics) {
  nlohmann::ordered_json reactions = nlohmann::ordered_json::object();
  for (std::size_t s = 0; s < supports.size(); ++s) {
    reactions[supports[s].name] = {number_or_null(statics.reactions[s].x()), number_or_null(statics.reactions[s].y())};
  }
  nlohmann::ordered_json out = {{"status", std::string(to_string(statics.status))},
                                {driver_load_name(r.model), number_or_null(statics.driver)}};  // null when singular (unbounded) or no pose
  if (r.model.has_second_driver()) {
    out[r.model.description().second_driver->angle() ? "driver2_torque" : "driver2_force"] = number_or_null(statics.second_driver);
  }
  out["reactions"] = reactions;
  return out;
}

// "driver torque -3.2 .. 5.1 (largest in size 5.1 at 120 deg); singular at 2 poses".
std::string statics_summary(const LinkageReport& r) {
  LinkageStaticsSolver solver(r.model);
  double low = std::numeric_limits<double>::infinity(), high = -low, largest = -1.0, at = nan;
  int singular = 0;
  for (const auto& pose : r.sweep.poses) {
    const LinkageStatics& statics = solver.solve(pose);
    if (statics.status == StaticsStatus::singular) ++singular;
    if (statics.status != StaticsStatus::equilibrium) continue;
    low = std::min(low, statics.driver), high = std::max(high, statics.driver);
    if (std::abs(statics.driver) > largest) largest = std::abs(statics.driver), at = pose.driver;
  }
  const std::string what = r.model.crank_driven() ? "driver torque" : "driver force";
  const std::string tail = singular > 0 ? fmt::format("; singular (unbounded) at {} pose{}", singular, singular == 1 ? "" : "s") : "";
  if (largest < 0.0) return what + ": no pose in equilibrium" + tail;
  return fmt::format("{} {:.6g} .. {:.6g} (largest in size {:.6g} at {:.6g}{}){}", what, low, high, largest, at,
                     r.model.crank_driven() ? " deg" : "", tail);
}

}  // namespace

void print_explanation(std::ostream& out, const LinkageModel& model, Format format) {
  const Mobility mobility = gruebler_kutzbach(model.description());
  const auto blocks = linkage_blocks(model);
  const auto pattern = model.pattern();
  std::vector<std::string> unknowns, equations, sparsity;
  for (int c = 0; c < model.unknown_count(); ++c) unknowns.push_back(model.column_name(c));
  for (int r = 0; r < model.equation_count(); ++r) {
    equations.push_back(model.row_name(r));
    std::string row;
    for (int c = 0; c < model.unknown_count(); ++c) row += pattern(r, c) ? 'x' : '.';
    sparsity.push_back(row);
  }
  const auto newton_blocks = std::count_if(blocks.begin(), blocks.end(), [](const LinkageBlock& b) { return !b.closed_form(); });
  if (format == Format::json) {
    nlohmann::ordered_json json = {{"mechanism", model.description().name},
                                   {"title", model.description().title},
                                   {"mobility", {{"members", mobility.members}, {"lower_pairs", mobility.lower_pairs},
                                                 {"mobility", mobility.mobility}}},
                                   {"unknowns", unknowns},
                                   {"equations", equations},
                                   {"sparsity", sparsity},
                                   {"blocks", nlohmann::ordered_json::array()}};
    for (const auto& block : blocks) {
      std::vector<std::string> known;
      for (int j : block.known_joints) known.push_back(joint_name(model, j));
      json["blocks"].push_back({{"joints", block_joint_names(model, block)},
                                {"from", known},
                                {"size", block.rows_and_columns.unknowns.size()},
                                {"kind", std::string(to_string(block.kind))},
                                {"closed_form", block.closed_form()},
                                {"text", describe_block(model, block)}});
    }
    json["analytic"] = newton_blocks == 0;
    out << json.dump(2) << '\n';
    return;
  }
  out << fmt::format("linkage            {}{}\n", model.description().name,
                     model.description().title.empty() ? "" : ": " + model.description().title)
      << fmt::format("mobility           {} (Gruebler-Kutzbach {})\n", mobility.mobility, mobility.formula())
      << fmt::format("formulation        joint coordinates, the x and y of every moving joint; one equation per link,\n"
                     "                   for each body one plus two per further joint, one per slider, two for a crank driver (one for any other)\n")
      << fmt::format("{:<19}{}\n", fmt::format("unknowns ({})", unknowns.size()), fmt::join(unknowns, " "))
      << fmt::format("equations ({})\n", equations.size());
  for (std::size_t r = 0; r < equations.size(); ++r) {
    out << fmt::format("  {:>3}  {}  {}\n", r + 1, sparsity[r], equations[r]);
  }
  out << "blocks, in solving order (from: joints solved before)\n";
  for (std::size_t b = 0; b < blocks.size(); ++b) out << fmt::format("  {:>3}. {}\n", b + 1, describe_block(model, blocks[b]));
  out << fmt::format("closed form        {} of {} blocks; {}\n", static_cast<long>(blocks.size()) - newton_blocks,
                     blocks.size(),
                     newton_blocks == 0 ? "every block has a closed form: --solver analytic applies"
                                        : fmt::format("{} need{} Newton: --solver analytic does not apply", newton_blocks, newton_blocks == 1 ? "s" : ""));
}

nlohmann::ordered_json pose_trace_json(const LinkagePose& pose) {
  return {{"driver", pose.driver},
          {"iterations", pose.outcome.iterations},
          {"residual_inf", number(pose.outcome.residual_norm)},
          {"condition", number(pose.condition)},
          {"status", std::string(to_string(pose.outcome.status))}};
}

void print_linkage_csv(std::ostream& out, const LinkageReport& r) {
  const auto& joints = r.model.description().joints;
  const auto dyad_blocks = dyads(r.solver);
  out << driver_column(r.model);
  if (r.model.has_second_driver()) out << ',' << second_driver_column(r.model);
  for (const auto& j : joints) out << ",x_" << j.name << ",y_" << j.name;
  for (const auto& j : joints) out << ",vx_" << j.name << ",vy_" << j.name << ",ax_" << j.name << ",ay_" << j.name;
  for (std::size_t b : dyad_blocks) out << ",mu_" << block_joint_names(r.model, r.solver.blocks()[b]);
  out << ",condition,iterations,residual_inf,status,branch_kept";
  const auto lines = link_lines(r.model.description());
  print_link_header(out, r, lines);
  print_statics_header(out, r);
  out << '\n';
  LinkageStaticsSolver statics(r.model);
  for (const auto& pose : r.sweep.poses) {
    out << fmt::format("{:.10g}", pose.driver);
    if (r.model.has_second_driver()) out << fmt::format(",{:.10g}", second_driver_at(r.model, pose));
    std::vector<JointMotion> m;
    for (std::size_t j = 0; j < joints.size(); ++j) m.push_back(motion(r.model, pose, static_cast<int>(j)));
    for (const auto& jm : m) out << fmt::format(",{:.17g},{:.17g}", jm.p.x(), jm.p.y());
    for (const auto& jm : m) out << fmt::format(",{:.17g},{:.17g},{:.17g},{:.17g}", jm.v.x(), jm.v.y(), jm.a.x(), jm.a.y());
    for (std::size_t b : dyad_blocks) out << fmt::format(",{:.10g}", converged(pose) ? pose.transmission_deg[b] : nan);
    out << fmt::format(",{:.6g},{},{:.6g},{},{}", pose.condition, pose.outcome.iterations, pose.outcome.residual_norm,
                       to_string(pose.outcome.status), kept(r.solver, pose) ? "yes" : "no");
    const LinkRates rates = link_rates(r, lines, pose);
    for (const AngularMotion& m : rates.links) out << fmt::format(",{:.12g},{:.17g},{:.17g}", m.angle * degrees, m.omega, m.alpha);
    if (r.output) out << fmt::format(",{:.17g},{:.17g}", rates.ratio, mechanical_advantage(rates.ratio));
    if (r.speed_rad_s) {
      const double w = *r.speed_rad_s;
      for (const AngularMotion& m : rates.links) out << fmt::format(",{:.17g},{:.17g}", m.omega * w, m.alpha * w * w);
    }
    if (has_loads(r)) print_statics_row(out, r.model, statics.solve(pose));
    out << '\n';
  }
}

// The crossings, jumps and limits of a sweep, into its JSON.
void add_branch_events(nlohmann::ordered_json& out, const LinkageReport& r) {
  out["crossings"] = nlohmann::ordered_json::array();
  for (const auto& c : r.sweep.crossings) {
    const std::size_t b = static_cast<std::size_t>(c.block);
    out["crossings"].push_back({{"kind", c.tangency ? "tangency" : "crossing"},
                                {"driver", c.driver},
                                {"block", describe_block(r.model, r.solver.blocks()[b])},
                                {"side_before", c.side_before},
                                {"side_after", c.side_after},
                                {"followed", c.switched ? "other" : "smooth"}});
  }
  out["jumps"] = r.sweep.jumps;
  out["limits"] = nlohmann::ordered_json::array();
  for (const auto& limit : r.sweep.limits) {
    out["limits"].push_back({{"kind", limit.assembles_beyond ? "solver_failure" : "fold"},
                             {"driver", limit.driver},
                             {"bracket", limit.bracket},
                             {"upper", limit.upper},
                             {"block", limit.block >= 0 ? nlohmann::ordered_json(describe_block(r.model, r.solver.blocks()[static_cast<std::size_t>(limit.block)])) : nlohmann::ordered_json()},
                             {"transmission_deg", number(limit.transmission_deg)},
                             {"text", limit_text(r, limit)}});
  }
}

nlohmann::ordered_json linkage_json(const LinkageReport& r, const nlohmann::ordered_json* trace) {
  const auto& joints = r.model.description().joints;
  const auto dyad_blocks = dyads(r.solver);
  const auto lines = link_lines(r.model.description());
  nlohmann::ordered_json out = {{"mechanism", r.model.description().name},
                                {"title", r.model.description().title},
                                {"solver", r.solver.options().solver},
                                {"driver", driver_column(r.model)},
                                {"poses", nlohmann::ordered_json::array()}};
  if (r.model.has_second_driver()) out["second_driver"] = second_driver_column(r.model);
  LinkageStaticsSolver statics(r.model);
  const auto supports = statics_supports(r.model.description());
  for (const auto& pose : r.sweep.poses) {
    nlohmann::ordered_json positions, velocities, accelerations, transmission;
    for (std::size_t j = 0; j < joints.size(); ++j) {
      const JointMotion m = motion(r.model, pose, static_cast<int>(j));
      positions[joints[j].name] = {number(m.p.x()), number(m.p.y())};
      velocities[joints[j].name] = {number(m.v.x()), number(m.v.y())};
      accelerations[joints[j].name] = {number(m.a.x()), number(m.a.y())};
    }
    for (std::size_t b : dyad_blocks) {
      transmission[block_joint_names(r.model, r.solver.blocks()[b])] = number(converged(pose) ? pose.transmission_deg[b] : nan);
    }
    out["poses"].push_back({{"driver", pose.driver},
                            {"second_driver", r.model.has_second_driver() ? number(second_driver_at(r.model, pose)) : nullptr},
                            {"joints", positions},
                            {"velocity", velocities},
                            {"acceleration", accelerations},
                            {"transmission_deg", transmission},
                            {"condition", number(pose.condition)},
                            {"closed_form_distance", number(pose.closed_form_distance)},
                            {"closed_form_bound", number(pose.closed_form_bound)},
                            {"signature", pose.signature},
                            {"branch_kept", kept(r.solver, pose)},
                            {"iterations", pose.outcome.iterations},
                            {"residual_inf", number(pose.outcome.residual_norm)},
                            {"status", std::string(to_string(pose.outcome.status))}});
    if (!std::isnan(pose.not_tried_past)) out["poses"].back()["not_tried_past"] = pose.not_tried_past;
    const LinkRates rates = link_rates(r, lines, pose);
    nlohmann::ordered_json links = nlohmann::ordered_json::object();
    for (std::size_t k = 0; k < lines.size(); ++k) {
      const AngularMotion& m = rates.links[k];
      links[lines[k].name] = {{"angle_deg", number(m.angle * degrees)}, {"omega", number(m.omega)}, {"alpha", number(m.alpha)}};
      if (r.speed_rad_s) {
        links[lines[k].name]["omega_rad_s"] = number(m.omega * *r.speed_rad_s);
        links[lines[k].name]["alpha_rad_s2"] = number(m.alpha * *r.speed_rad_s * *r.speed_rad_s);
      }
    }
    out["poses"].back()["links"] = links;
    if (r.output) {
      const double advantage = mechanical_advantage(rates.ratio);
      out["poses"].back()["velocity_ratio"] = number(rates.ratio);
      out["poses"].back()["mechanical_advantage"] = number(advantage);  // null at a toggle (infinite) or no pose
      out["poses"].back()["mechanical_advantage_infinite"] = std::isinf(advantage);
    }
    if (has_loads(r)) out["poses"].back()["statics"] = statics_json(r, supports, statics.solve(pose));
  }
  out["status"] = std::string(to_string(r.status));
  out["links_per"] = velocity_per(r.model.driver_kind());
  out["output"] = r.output ? nlohmann::ordered_json(r.output->name) : nlohmann::ordered_json();
  out["speed_rad_s"] = r.speed_rad_s ? nlohmann::ordered_json(*r.speed_rad_s) : nlohmann::ordered_json();
  out["branch_kept"] = r.sweep.branch_kept;
  out["closed_form_verified"] = r.sweep.closed_form_verified;
  out["worst_closed_form_distance"] = number(worst_closed_form(r.sweep).distance);
  out["worst_closed_form_bound"] = number(worst_closed_form(r.sweep).bound);
  out["flips"] = r.sweep.flips;
  out["change_points"] = r.sweep.change_points;
  add_branch_events(out, r);
  out["derivative_check"] = {{"poses", r.derivatives.poses},
                             {"singular_poses", r.derivatives.singular},
                             {"ill_conditioned_poses", r.derivatives.ill_conditioned},
                             {"velocity_relative", r.derivatives.velocity},
                             {"acceleration_relative", r.derivatives.acceleration},
                             {"agrees", r.derivatives.poses == 0 ? nlohmann::ordered_json()  // nothing checked: no verdict
                                                                 : nlohmann::ordered_json(r.derivatives.failure.empty())},
                             {"failure", r.derivatives.failure}};
  if (r.jacobian) {
    out["jacobian_check"] = {{"poses", r.jacobian->poses},
                             {"worst_relative_error", number(r.jacobian->worst.worst_error)},
                             {"at_driver", r.jacobian->driver},
                             {"agrees", r.jacobian->worst.agrees}};
  }
  out["warnings"] = r.warnings;
  out["time_s"] = r.time_s;
  if (trace != nullptr) out["trace"] = *trace;
  return out;
}

// The derivative check's lines: the poses checked and the verdict, then the poses skipped and why.
void print_derivative_check(std::ostream& out, const DerivativeReport& d) {
  out << fmt::format("derivatives        at {} pose{}, against finite differences of positions: velocity {:.1e}, "
                     "acceleration {:.1e} (relative): {}\n",
                     d.poses, d.poses == 1 ? "" : "s", d.velocity, d.acceleration,
                     d.poses == 0 ? "nothing checked" : d.failure.empty() ? "agree" : "DISAGREE " + d.failure);
  if (d.singular > 0) {
    out << fmt::format("                   {} pose{} on a crossing not checked: J is singular there, and their velocity "
                       "and acceleration are differences of positions solved along the branch\n",
                       d.singular, d.singular == 1 ? "" : "s");
  }
  if (d.ill_conditioned > 0) {
    out << fmt::format("                   {} pose{} not checked: kappa(J) above 1e5 with every dyad away from its meeting "
                       "point (J is ill-conditioned, not singular): J's kinematics are good only to about eps kappa^2, "
                       "so their velocity and acceleration are differences of positions solved along the branch\n",
                       d.ill_conditioned, d.ill_conditioned == 1 ? "" : "s");
  }
}

void print_linkage_text(std::ostream& out, const LinkageReport& r, const std::string& file) {
  const auto& d = r.model.description();
  const auto& blocks = r.solver.blocks();
  const int tracked = r.model.moving().back();  // the last moving joint listed: usually the output point
  const std::string t = joint_name(r.model, tracked);
  const auto newton_blocks = std::count_if(blocks.begin(), blocks.end(), [](const LinkageBlock& b) { return !b.closed_form(); });
  out << fmt::format("mechanism          {}{} ({})\n", d.name, d.title.empty() ? "" : ": " + d.title, file)
      << fmt::format("model              {} unknowns, {} equations; {} blocks, {} in closed form (--explain shows them)\n",
                     r.model.unknown_count(), r.model.equation_count(), blocks.size(),
                     static_cast<long>(blocks.size()) - newton_blocks)
      << fmt::format("solver             {}\n", r.solver.options().solver == "full"
                                                     ? "full (" + r.solver.options().linear + ")"
                                                     : r.solver.options().solver)
      << fmt::format("status             {}\n", to_string(r.status))
      << fmt::format("poses              {}\n", r.sweep.poses.size());
  constexpr std::size_t shown = 8;
  std::vector<std::string> header{driver_word(r.model) + (r.model.crank_driven() ? " (deg)" : ""), "x_" + t, "y_" + t,
                                  "|v_" + t + "|", "kappa(J)", "iterations", "||Phi||_inf", "status"};
  const bool two_drivers = r.model.has_second_driver();
  if (two_drivers) header.insert(header.begin() + 1, second_driver_column(r.model));
  Table table(header);
  for (std::size_t i = 0; i < r.sweep.poses.size(); ++i) {
    if (r.sweep.poses.size() > shown && i == shown / 2) {
      table.add_row({fmt::format("... ({} more)", r.sweep.poses.size() - shown)});
      i = r.sweep.poses.size() - shown / 2;
    }
    const auto& pose = r.sweep.poses[i];
    const JointMotion m = motion(r.model, pose, tracked);
    const double size = r.solver.size();
    std::vector<std::string> row{fmt::format("{:g}", pose.driver), fixed_for_size(m.p.x(), 6, size), fixed_for_size(m.p.y(), 6, size),
                                 fixed_for_size(m.v.norm(), 4, size), scientific(pose.condition), std::to_string(pose.outcome.iterations),
                                 scientific(pose.outcome.residual_norm),
                                 std::isnan(pose.not_tried_past) ? std::string(to_string(pose.outcome.status)) : "not tried"};
    if (two_drivers) row.insert(row.begin() + 1, fmt::format("{:g}", second_driver_at(r.model, pose)));
    table.add_row(row);
  }
  table.print(out);
  out << fmt::format("branch             {}\n", r.sweep.branch_kept ? "kept (no block's side changed but at a crossing)"
                                                                      : "FLIPPED");
  for (const auto& flip : r.sweep.flips) out << "                   " << flip << '\n';
  for (const auto& jump : r.sweep.jumps) out << "                   " << jump << '\n';
  for (std::size_t i = 0; i < r.sweep.change_points.size(); ++i) {
    const bool touch = i < r.sweep.crossings.size() && r.sweep.crossings[i].tangency;
    out << (touch ? "tangency           " : "crossing           ") << r.sweep.change_points[i] << '\n';
  }
  const ClosedFormWorst worst = worst_closed_form(r.sweep);
  if (!std::isnan(worst.distance)) {
    out << fmt::format("closed form        worst joint distance {:.2g} (the residual allows {:.2g}): {}\n", worst.distance,
                       worst.bound, r.sweep.closed_form_verified ? "verified" : "NOT VERIFIED");
  }
  for (const auto& limit : r.sweep.limits) out << "limit              " << limit_text(r, limit) << '\n';
  if (const std::string skipped = not_tried_text(r.sweep); !skipped.empty()) out << "not tried          " << skipped << '\n';
  double low = std::numeric_limits<double>::infinity(), high = 0.0, at = nan;
  for (const auto& pose : r.sweep.poses) {
    if (!converged(pose)) continue;
    low = std::min(low, pose.condition);
    if (pose.condition > high) high = pose.condition, at = pose.driver;
  }
  if (std::isfinite(low)) out << fmt::format("kappa(J)           {:.3g} .. {:.3g} (largest at {:g})\n", low, high, at);
  for (std::size_t b : dyads(r.solver)) out << "transmission       " << transmission_summary(r, b) << '\n';
  if (r.output) out << "output             " << output_summary(r) << '\n';
  if (has_loads(r)) out << "statics            " << statics_summary(r) << '\n';
  print_derivative_check(out, r.derivatives);
  if (r.jacobian) {
    out << fmt::format("jacobian           exact J against finite differences at {} solved poses: worst relative error "
                       "{:.1e} at {:g}: {}\n",
                       r.jacobian->poses, r.jacobian->worst.worst_error, r.jacobian->driver,
                       r.jacobian->worst.agrees ? "agrees" : "DISAGREES " + nonlinear::describe_worst_entry(r.jacobian->worst));
  }
  out << fmt::format("time               {:.3g} s\n", r.time_s)
      << "velocities per " << velocity_per(r.model.driver_kind())
      << (r.model.crank_driven() ? ", accelerations per radian squared\n" : "\n");
  if (r.model.has_second_driver()) {
    out << fmt::format("second driver      {} held {}; velocities are the first driver's partial derivatives\n",
                       second_driver_column(r.model),
                       r.sweep.poses.empty() || std::isnan(r.sweep.poses.front().second_driver)
                           ? fmt::format("at {:g} (the file's value)", r.model.second_driver())
                           : "at each row of the --drivers path");
  }
}

}  // namespace numlab::cli
