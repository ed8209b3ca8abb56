#include "numlab/mechanisms/linkage/linkage_authoring_checks.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>

#include "numlab/mechanisms/linkage/linkage_model.hpp"
#include "numlab/mechanisms/linkage/linkage_solver.hpp"
#include "numlab/nonlinear/newton.hpp"

namespace numlab::mechanisms {

// Named, not anonymous: the unity build puts this file beside others with their own helpers.
namespace authoring {

constexpr double infinity = std::numeric_limits<double>::infinity();
// The reference pose is solved again to this many times the mechanism's size.
constexpr double relative_residual = 1e-11;
// A body's rough triangle must have at least this fraction of its local area to tell its turn.
constexpr double mirror_area_fraction = 0.1;

double degrees_of(const Eigen::Vector2d& v) { return std::atan2(v.y(), v.x()) * 180.0 / std::numbers::pi; }
double to_degrees(double radians) { return radians * 180.0 / std::numbers::pi; }
double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

const JointSpec& joint(const LinkageDescription& d, int j) { return d.joints[static_cast<std::size_t>(j)]; }

// The shortest link at joint j: its links' lengths and its distances to the other joints of its
// bodies (infinity when it has neither).
double shortest_link_at(const LinkageDescription& d, int j) {
  double shortest = infinity;
  for (const LinkSpec& link : d.links) {
    if (link.first == j || link.second == j) shortest = std::min(shortest, link.length);
  }
  for (const BodySpec& body : d.bodies) {
    const auto at = std::find(body.joints.begin(), body.joints.end(), j);
    if (at == body.joints.end()) continue;
    const Eigen::Vector2d& own = body.local[static_cast<std::size_t>(at - body.joints.begin())];
    for (const Eigen::Vector2d& other : body.local) {
      if (&other != &own) shortest = std::min(shortest, (other - own).norm());
    }
  }
  return shortest;
}

// The length a joint's shift and a slider's offset are measured against.
double joint_scale(const LinkageDescription& d, int j) {
  const double shortest = shortest_link_at(d, j);
  return std::isfinite(shortest) ? shortest : mechanism_size(d);
}

// ", which looks like radians: 45.0°" when `value` read as radians matches `rough_deg` (modulo
// `period` degrees), else "".
std::string radians_hint(double value, double rough_deg, double period) {
  if (value == 0.0 || std::abs(value) > 2.0 * std::numbers::pi + 1e-9) return {};
  if (std::abs(std::remainder(to_degrees(value) - rough_deg, period)) > driver_angle_tolerance_deg) return {};
  return fmt::format("; angle = {:g} looks like radians: {:.1f}°, write angle = {:.1f}", value, to_degrees(value),
                     to_degrees(value));
}

void check_crank_angle(const LinkageDescription& d) {
  const DriverSpec& driver = d.driver;
  const Eigen::Vector2d arm = joint(d, driver.joint).position - joint(d, driver.pivot).position;
  if (arm.norm() <= joint_shift_fraction * joint_scale(d, driver.joint)) return;  // no direction to compare with
  const double rough = degrees_of(arm);
  const double off = std::remainder(driver.reference - rough, 360.0);
  if (std::abs(off) <= driver_angle_tolerance_deg) return;
  const std::string hint = radians_hint(driver.reference, rough, 360.0);
  throw LinkageFileError(
      d.file, driver.reference_place,
      fmt::format("the crank's angle = {:g} disagrees with the rough positions, which put {} -> {} at {:.1f}°{}", driver.reference,
                  joint(d, driver.pivot).name, joint(d, driver.joint).name, rough,
                  hint.empty() ? fmt::format(" ({:.1f}° apart, more than {:g}°): fix the angle or {}'s rough position",
                                             std::abs(off), driver_angle_tolerance_deg, joint(d, driver.joint).name)
                               : hint));
}

// A motor's angle against its joints' rough positions: the angle from pivot -> from to pivot -> joint.
// Its row also vanishes half a turn away, so a wrong angle would pick the other root: an error.
void check_motor_angle(const LinkageDescription& d) {
  const DriverSpec& driver = d.driver;
  const Eigen::Vector2d u = joint(d, driver.from).position - joint(d, driver.pivot).position;
  const Eigen::Vector2d v = joint(d, driver.joint).position - joint(d, driver.pivot).position;
  const double shift = joint_shift_fraction * std::min(joint_scale(d, driver.from), joint_scale(d, driver.joint));
  if (u.norm() <= shift || v.norm() <= shift) return;  // no direction to compare with
  const double rough = to_degrees(std::atan2(cross(u, v), u.dot(v)));
  const double off = std::remainder(driver.reference - rough, 360.0);
  if (std::abs(off) <= driver_angle_tolerance_deg) return;
  const std::string hint = radians_hint(driver.reference, rough, 360.0);
  throw LinkageFileError(
      d.file, driver.reference_place,
      fmt::format("the motor's angle = {:g} disagrees with the rough positions, which put {} -> {} at {:.1f}° from {} -> {}{}",
                  driver.reference, joint(d, driver.pivot).name, joint(d, driver.joint).name, rough, joint(d, driver.pivot).name,
                  joint(d, driver.from).name,
                  hint.empty() ? fmt::format(" ({:.1f}° apart, more than {:g}°): fix the angle or the rough positions", std::abs(off),
                                             driver_angle_tolerance_deg)
                               : hint));
}

// A slider's line against its joint's rough position: the direction from `through` to the joint,
// when the joint is off the line by more than a tenth of its shortest link.
void check_slider_angle(const LinkageDescription& d, const SliderSpec& slider) {
  const Eigen::Vector2d v = joint(d, slider.joint).position - slider.through;
  const double angle = slider.angle_deg * std::numbers::pi / 180.0;
  const double off_line = std::abs(cross(Eigen::Vector2d(std::cos(angle), std::sin(angle)), v));
  if (off_line <= joint_shift_fraction * joint_scale(d, slider.joint)) return;
  const double rough = degrees_of(v);
  const double off = std::remainder(slider.angle_deg - rough, 180.0);
  if (std::abs(off) <= driver_angle_tolerance_deg) return;
  const std::string& name = joint(d, slider.joint).name;
  const std::string hint = radians_hint(slider.angle_deg, rough, 180.0);
  throw LinkageFileError(
      d.file, slider.angle_place,
      fmt::format("slider {}'s angle = {:g} disagrees with the rough position of {}, which puts its line at {:.1f}°{}", name,
                  slider.angle_deg, name, std::remainder(rough, 180.0),
                  hint.empty() ? fmt::format(" ({} is {:.3g} off the line): fix the angle, 'through' or {}'s rough position",
                                             name, off_line, name)
                               : hint));
}

void warn_link_lengths(const LinkageDescription& d, std::vector<AuthoringWarning>& out) {
  for (const LinkSpec& link : d.links) {
    const double rough = (joint(d, link.first).position - joint(d, link.second).position).norm();
    const double relative = (rough - link.length) / link.length;
    if (std::abs(relative) <= link_length_tolerance) continue;
    out.push_back({link.place, fmt::format("link {}-{}: length {:g}, but its joints' rough positions are {:.4g} apart "
                                           "({:.0f}% {})",
                                           joint(d, link.first).name, joint(d, link.second).name, link.length, rough,
                                           std::abs(relative) * 100.0, relative > 0 ? "longer" : "shorter")});
  }
}

void warn_mirrored_bodies(const LinkageDescription& d, std::vector<AuthoringWarning>& out) {
  std::vector<Eigen::Vector2d> rough;
  for (const JointSpec& j : d.joints) rough.push_back(j.position);
  for (const BodySpec& body : d.bodies) {
    const BodyTurn turn = body_turn(body, rough);
    if (!turn.mirrored(mirror_area_fraction)) continue;
    out.push_back({body.place, fmt::format("body '{}': its local coordinates are the mirror image of its joints' rough "
                                           "positions ({}); the body keeps its local shape",
                                           body.name, turn.text(d, "[joints]"))});
  }
}

void warn_shifted_joints(const LinkageModel& model, const Eigen::VectorXd& reference, std::vector<AuthoringWarning>& out) {
  const LinkageDescription& d = model.description();
  const JointPositions solved = model.positions(reference);
  for (int j : model.moving()) {
    const JointSpec& spec = joint(d, j);
    const Eigen::Vector2d& at = solved[static_cast<std::size_t>(j)];
    const double shift = (at - spec.position).norm(), limit = joint_shift_fraction * joint_scale(d, j);
    if (shift <= limit) continue;
    out.push_back({spec.place, fmt::format("joint {} is solved {:.3g} from its rough position, at [{:.4g}, {:.4g}] "
                                           "instead of [{:.4g}, {:.4g}] (more than a tenth of its shortest link, {:.3g})",
                                           spec.name, shift, at.x(), at.y(), spec.position.x(), spec.position.y(),
                                           limit / joint_shift_fraction)});
  }
}

}  // namespace authoring

bool BodyTurn::mirrored(double fraction) const {
  return local * placed < 0.0 && std::abs(placed) >= fraction * std::abs(local);
}

std::string BodyTurn::text(const LinkageDescription& description, const std::string& where) const {
  const auto turn = [](double area) { return area > 0 ? "counter-clockwise" : "clockwise"; };
  return fmt::format("{}, {}, {} turn {} in 'local', {} in {}", authoring::joint(description, joints[0]).name,
                     authoring::joint(description, joints[1]).name, authoring::joint(description, joints[2]).name,
                     turn(local), turn(placed), where);
}

// The spanning triangle: the two local points farthest apart and the one farthest from their line.
BodyTurn body_turn(const BodySpec& body, const std::vector<Eigen::Vector2d>& positions) {
  using authoring::cross;
  std::array<std::size_t, 3> t{0, 1, 2};
  double far = -1.0;
  for (std::size_t i = 0; i < body.local.size(); ++i) {
    for (std::size_t j = i + 1; j < body.local.size(); ++j) {
      if (const double d = (body.local[i] - body.local[j]).norm(); d > far) far = d, t[0] = i, t[1] = j;
    }
  }
  const Eigen::Vector2d base = body.local[t[1]] - body.local[t[0]];
  double height = -1.0;
  for (std::size_t k = 0; k < body.local.size(); ++k) {
    if (const double h = std::abs(cross(base, body.local[k] - body.local[t[0]])); h > height) height = h, t[2] = k;
  }
  const auto area = [](const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
    return 0.5 * cross(b - a, c - a);
  };
  const auto at = [&](std::size_t k) { return positions[static_cast<std::size_t>(body.joints[k])]; };
  BodyTurn turn;
  for (std::size_t k = 0; k < 3; ++k) turn.joints[k] = body.joints[t[k]];
  turn.local = area(body.local[t[0]], body.local[t[1]], body.local[t[2]]);
  turn.placed = area(at(t[0]), at(t[1]), at(t[2]));
  return turn;
}

std::string warning_line(const std::string& file, const AuthoringWarning& warning) {
  return warning.place.line > 0 ? fmt::format("{}:{}: {}", file, warning.place.line, warning.text)
                                : fmt::format("{}: {}", file, warning.text);
}

double mechanism_size(const LinkageDescription& d) {
  double size = 0.0;
  for (const LinkSpec& link : d.links) size = std::max(size, link.length);
  for (const BodySpec& body : d.bodies) {
    for (const Eigen::Vector2d& a : body.local) {
      for (const Eigen::Vector2d& b : body.local) size = std::max(size, (a - b).norm());
    }
  }
  if (d.joints.empty()) return size;
  Eigen::Vector2d low = d.joints.front().position, high = low;
  for (const JointSpec& j : d.joints) low = low.cwiseMin(j.position), high = high.cwiseMax(j.position);
  return std::max(size, (high - low).norm());
}

void check_driver_angles(const LinkageDescription& description) {
  if (description.driver.kind == DriverKind::crank) authoring::check_crank_angle(description);
  if (description.driver.kind == DriverKind::motor) authoring::check_motor_angle(description);
  for (const SliderSpec& slider : description.sliders) {
    if (!slider.on_link()) authoring::check_slider_angle(description, slider);  // a slot's line moves: no angle to check
  }
}

Eigen::VectorXd polished_reference(const LinkageModel& model, const Eigen::VectorXd& start) {
  const Eigen::VectorXd q0 = start.size() == 0 ? model.unknowns(model.rough_positions()) : start;
  nonlinear::NewtonOptions newton;
  newton.damped = true;
  newton.max_iterations = 100;
  newton.residual_tolerance = authoring::relative_residual * mechanism_size(model.description());
  const LinkageSystem system(model, model.driver_from_user(model.description().driver.reference));
  const auto result = nonlinear::newton_solve(system, q0, newton);
  return result.status == Status::converged ? result.x : q0;
}

std::vector<AuthoringWarning> authoring_warnings(const LinkageModel& model, const Eigen::VectorXd& reference) {
  std::vector<AuthoringWarning> out;
  authoring::warn_link_lengths(model.description(), out);
  authoring::warn_mirrored_bodies(model.description(), out);
  authoring::warn_shifted_joints(model, reference, out);
  std::stable_sort(out.begin(), out.end(), [](const AuthoringWarning& a, const AuthoringWarning& b) {
    return a.place.line < b.place.line;
  });
  return out;
}

}  // namespace numlab::mechanisms
