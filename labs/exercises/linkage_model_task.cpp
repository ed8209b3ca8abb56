// The linkage exercise's model, as the requests carry it (JSON) and as TASK.md states it (Markdown):
// both made from numlab's derived LinkageModel, so they are specific to the description file.

#include <fmt/format.h>

#include <numbers>

#include "exercises/linkage_exercise.hpp"

namespace numlab::exercises {

namespace {

using mechanisms::Constraint;
using mechanisms::ConstraintKind;
using mechanisms::LinkageModel;

std::string joint_name(const LinkageModel& model, int joint) {
  return model.description().joints[static_cast<std::size_t>(joint)].name;
}

const char* kind_name(ConstraintKind kind) {
  switch (kind) {
    case ConstraintKind::distance: return "distance";
    case ConstraintKind::body_point: return "body_point";
    case ConstraintKind::slider_line: return "slider_line";
    case ConstraintKind::crank: return "crank";
    case ConstraintKind::slider_travel: return "slider_travel";
    case ConstraintKind::slider_on_line: return "slider_on_line";
    case ConstraintKind::actuator: return "actuator";
    case ConstraintKind::motor: return "motor";
  }
  return "";
}

nlohmann::json pair(const Eigen::Vector2d& v) { return nlohmann::json::array({v.x(), v.y()}); }

std::string number(double value) { return fmt::format("{:.17g}", value); }

// p_J's x or y as the task writes it: a symbol for a moving joint, the number for a ground joint.
std::string coordinate(const LinkageModel& model, int joint, int axis) {
  const auto& spec = model.description().joints[static_cast<std::size_t>(joint)];
  if (spec.ground) return fmt::format("({})", number(spec.position(axis)));
  return fmt::format("{}_{}", axis == 0 ? 'x' : 'y', spec.name);
}

// The rows of constraint c, as equations in the unknowns (t: the driver in model units).
std::vector<std::string> row_formulas(const LinkageModel& model, const Constraint& c) {
  const auto x = [&](int k) { return coordinate(model, c.joints[static_cast<std::size_t>(k)], 0); };
  const auto y = [&](int k) { return coordinate(model, c.joints[static_cast<std::size_t>(k)], 1); };
  switch (c.kind) {
    case ConstraintKind::distance: {
      const std::string L = number(c.length);
      return {fmt::format("(({} - {})^2 + ({} - {})^2 - {}^2) / (2 * {})", x(0), x(1), y(0), y(1), L, L)};
    }
    case ConstraintKind::body_point: {
      const std::string a = number(c.coefficients.x()), b = number(c.coefficients.y());
      return {fmt::format("{2} - {0} - {3} * ({1} - {0}) + {4} * ({5} - {6})", x(0), x(1), x(2), a, b, y(1), y(0)),
              fmt::format("{2} - {0} - {3} * ({1} - {0}) - {4} * ({5} - {6})", y(0), y(1), y(2), a, b, x(1), x(0))};
    }
    case ConstraintKind::slider_line:
      return {fmt::format("{} * ({} - {}) - {} * ({} - {})", number(c.direction.x()), y(0), number(c.point.y()),
                          number(c.direction.y()), x(0), number(c.point.x()))};
    case ConstraintKind::crank: {
      const std::string angle = c.offset == 0.0 ? "t" : "t + " + number(c.offset);
      return {fmt::format("{} - {} - {} * cos({})", x(1), x(0), number(c.length), angle),
              fmt::format("{} - {} - {} * sin({})", y(1), y(0), number(c.length), angle)};
    }
    case ConstraintKind::slider_travel:
      return {fmt::format("{} * ({} - {}) + {} * ({} - {}) - t", number(c.direction.x()), x(0), number(c.point.x()),
                          number(c.direction.y()), y(0), number(c.point.y()))};
    case ConstraintKind::slider_on_line:
      return {fmt::format("(({2} - {1}) * ({5} - {4}) - ({6} - {4}) * ({0} - {1})) / sqrt(({2} - {1})^2 + ({6} - {4})^2) - {3}",
                          x(0), x(1), x(2), number(c.offset), y(1), y(0), y(2))};
    case ConstraintKind::actuator:
      return {fmt::format("sqrt(({} - {})^2 + ({} - {})^2) - t", x(0), x(1), y(0), y(1))};
    case ConstraintKind::motor: {
      const std::string ux = fmt::format("({} - {})", x(1), x(0)), uy = fmt::format("({} - {})", y(1), y(0));
      const std::string vx = fmt::format("({} - {})", x(2), x(0)), vy = fmt::format("({} - {})", y(2), y(0));
      return {fmt::format("{0} * (({1} * {4} - {2} * {3}) * cos(t) - ({1} * {3} + {2} * {4}) * sin(t)) / "
                          "sqrt(({1}^2 + {2}^2) * ({3}^2 + {4}^2))",
                          number(c.length), ux, uy, vx, vy)};
    }
  }
  return {};
}

}  // namespace

nlohmann::json linkage_model_json(const LinkageModel& model) {
  const auto& d = model.description();
  nlohmann::json joints = nlohmann::json::array();
  for (const auto& joint : d.joints) {
    joints.push_back({{"name", joint.name}, {"ground", joint.ground}, {"position", pair(joint.position)}});
  }
  nlohmann::json unknowns = nlohmann::json::array();
  for (int k = 0; k < model.unknown_count(); ++k) unknowns.push_back(model.column_name(k));
  nlohmann::json equations = nlohmann::json::array();
  for (const Constraint& c : model.constraints()) {
    nlohmann::json names = nlohmann::json::array();
    for (int joint : c.joints) {
      if (joint >= 0) names.push_back(joint_name(model, joint));
    }
    nlohmann::json equation = {{"kind", kind_name(c.kind)}, {"name", c.name}, {"rows", c.rows()}, {"joints", names}};
    if (c.kind == ConstraintKind::distance || c.kind == ConstraintKind::crank || c.kind == ConstraintKind::motor) {
      equation["length"] = c.length;  // a motor's: its row's length scale l = |AC|
    }
    if (c.kind == ConstraintKind::slider_on_line) equation["offset"] = c.offset;
    if (c.kind == ConstraintKind::crank) equation["offset"] = c.offset;
    if (c.kind == ConstraintKind::body_point) equation["coefficients"] = pair(c.coefficients);
    if (c.kind == ConstraintKind::slider_line || c.kind == ConstraintKind::slider_travel) {
      equation["point"] = pair(c.point);
      equation["direction"] = pair(c.direction);
    }
    equations.push_back(std::move(equation));
  }
  const auto& driver = d.driver;
  constexpr const char* types[] = {"crank", "slider", "actuator", "motor"};
  nlohmann::json driver_json = {{"type", types[static_cast<int>(driver.kind)]},
                                {"joint", joint_name(model, driver.joint)},
                                {"reference", driver.reference},
                                {"units", model.crank_driven() ? "degrees" : "length"}};
  if (driver.pivot >= 0) driver_json["pivot"] = joint_name(model, driver.pivot);
  if (driver.from >= 0) driver_json["from"] = joint_name(model, driver.from);
  return {{"name", d.name}, {"joints", joints}, {"unknowns", unknowns}, {"driver", driver_json}, {"equations", equations}};
}

std::string linkage_model_task(const LinkageModel& model) {
  const auto& d = model.description();
  std::string text = fmt::format("## Your linkage: {}{}\n\n", d.name, d.title.empty() ? "" : " (" + d.title + ")");
  text += "Ground joints (fixed):";
  bool any_ground = false;
  for (const auto& joint : d.joints) {
    if (!joint.ground) continue;
    text += fmt::format(" {} = ({}, {});", joint.name, number(joint.position.x()), number(joint.position.y()));
    any_ground = true;
  }
  if (!any_ground) text += " none;";
  text.back() = '.';
  text += "\n\n";
  const auto& driver = d.driver;
  if (driver.kind == mechanisms::DriverKind::actuator) {
    text += fmt::format("**Driver:** an actuator: joints {} and {} are t apart (length units); a request's `driver` is "
                        "t; the reference pose is at t = {}.\n\n",
                        joint_name(model, driver.from), joint_name(model, driver.joint), number(driver.reference));
  } else if (driver.kind == mechanisms::DriverKind::motor) {
    text += fmt::format("**Driver:** a motor at joint {0}: the angle from {0}->{1} to {0}->{2} in **degrees** (t = driver * "
                        "pi / 180 in the equations below); the reference pose is at {3} degrees.\n\n",
                        joint_name(model, driver.pivot), joint_name(model, driver.from), joint_name(model, driver.joint),
                        number(driver.reference));
  } else if (model.crank_driven()) {
    text += fmt::format("**Driver:** a crank: joint {} turns about ground joint {}; a request's `driver` is the crank "
                        "angle in **degrees** (t = driver * pi / 180 in the equations below); the reference pose is "
                        "at {} degrees.\n\n",
                        joint_name(model, driver.joint), joint_name(model, driver.pivot), number(driver.reference));
  } else {
    text += fmt::format("**Driver:** a slider: joint {} moves along its line; a request's `driver` is its travel t "
                        "(length units) from the line's point; the reference pose is at t = {}.\n\n",
                        joint_name(model, driver.joint), number(driver.reference));
  }
  text += fmt::format("**Unknowns ({}), in this order:** q = (", model.unknown_count());
  for (int k = 0; k < model.unknown_count(); ++k) text += fmt::format("{}{}", k > 0 ? ", " : "", model.column_name(k));
  text += ")\n\n";
  text += fmt::format("**Equations ({}), in this order** (f[i] is row i; every row is in length units):\n\n",
                      model.equation_count());
  int row = 0;
  for (const Constraint& c : model.constraints()) {
    const auto formulas = row_formulas(model, c);
    for (std::size_t r = 0; r < formulas.size(); ++r) {
      text += fmt::format("{}. f[{}] = `{}`  ({}{})\n", row + 1, row, formulas[r], c.name,
                          formulas.size() > 1 ? (r == 0 ? ", x" : ", y") : "");
      ++row;
    }
  }
  text += "\nThe lengths:";
  for (const Constraint& c : model.constraints()) {
    if (c.kind == ConstraintKind::distance || c.kind == ConstraintKind::crank) {
      text += fmt::format(" {} {};", c.name, number(c.length));
    }
  }
  text.back() = '.';
  text += "\n";
  return text;
}

}  // namespace numlab::exercises
