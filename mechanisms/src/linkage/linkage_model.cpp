#include "numlab/mechanisms/linkage/linkage_model.hpp"

#include <cmath>
#include <limits>
#include <numbers>
#include <type_traits>

#include "linkage_rows.hpp"
#include "numlab/mechanisms/linkage/body_base_pairs.hpp"
#include "numlab/mechanisms/linkage/linkage_structure.hpp"
#include "numlab/mechanisms/plane_angles.hpp"

namespace numlab::mechanisms {

namespace {

Eigen::Vector2d perp(const Eigen::Vector2d& v) { return {-v.y(), v.x()}; }

std::string pair_name(const LinkageDescription& d, int i, int j) { return d.joints[static_cast<std::size_t>(i)].name + "-" + d.joints[static_cast<std::size_t>(j)].name; }

// (a, b) with c - b0 = a (b1 - b0) + b perp(b1 - b0), from local coordinates.
Eigen::Vector2d body_coefficients(const Eigen::Vector2d& b0, const Eigen::Vector2d& b1, const Eigen::Vector2d& c) {
  const Eigen::Vector2d base = b1 - b0, offset = c - b0;
  const double squared = base.squaredNorm();
  return {offset.dot(base) / squared, offset.dot(perp(base)) / squared};
}

}  // namespace

LinkageModel::LinkageModel(LinkageDescription description) : LinkageModel(std::move(description), {}) {
  // Each body's base pair from the structure, not from the order of its joints (body_base_pairs.hpp).
  if (!description_.bodies.empty()) *this = LinkageModel(description_, body_base_pairs(*this));
  require_one_degree_of_freedom(*this);
}

LinkageModel::LinkageModel(LinkageDescription description, std::vector<std::array<int, 2>> base_pairs)
    : description_(std::move(description)), base_pairs_(std::move(base_pairs)) {
  derive();
}

void LinkageModel::add(Constraint constraint) {
  first_row_.push_back(equation_count_);
  for (int r = 0; r < constraint.rows(); ++r) row_constraint_.push_back(static_cast<int>(constraints_.size()));
  equation_count_ += constraint.rows();
  constraints_.push_back(std::move(constraint));
}

namespace {

// Whether joints i and j are the driving crank's pivot and joint (either way round).
bool driven_pair(const DriverSpec& driver, int i, int j) {
  return driver.kind == DriverKind::crank &&
         ((i == driver.pivot && j == driver.joint) || (i == driver.joint && j == driver.pivot));
}

// The crank (first or second driver) that drives joints i and j, or nullptr.
const DriverSpec* crank_of_pair(const LinkageDescription& d, int i, int j) {
  for (const DriverSpec* driver : drivers_of(d)) {
    if (driven_pair(*driver, i, j)) return driver;
  }
  return nullptr;
}

// A body's constraints: its base pair's distance (the crank's pair when the crank turns this body:
// then the crank holds that distance), then each further joint placed by the base pair. `pair`:
// the base pair's indices into the body's joints.
std::vector<Constraint> body_constraints(const LinkageDescription& d, int index, std::array<int, 2> pair) {
  const BodySpec& body = d.bodies[static_cast<std::size_t>(index)];
  std::size_t b0 = static_cast<std::size_t>(pair[0]), b1 = static_cast<std::size_t>(pair[1]);
  for (std::size_t i = 0; i < body.joints.size(); ++i) {
    for (std::size_t k = 0; k < body.joints.size(); ++k) {
      const DriverSpec* crank = i == k ? nullptr : crank_of_pair(d, body.joints[i], body.joints[k]);
      if (crank != nullptr && body.joints[i] == crank->pivot) b0 = i, b1 = k;
    }
  }
  std::vector<Constraint> out;
  const int j0 = body.joints[b0], j1 = body.joints[b1];
  if (crank_of_pair(d, j0, j1) == nullptr) {
    Constraint c;
    c.kind = ConstraintKind::distance;
    c.joints = {j0, j1, -1};
    c.length = (body.local[b1] - body.local[b0]).norm();
    c.name = "body " + body.name + ": " + pair_name(d, j0, j1);
    c.body = index;
    c.place = body.place;
    out.push_back(std::move(c));
  }
  for (std::size_t k = 0; k < body.joints.size(); ++k) {
    if (k == b0 || k == b1) continue;
    Constraint c;
    c.kind = ConstraintKind::body_point;
    c.joints = {j0, j1, body.joints[k]};
    c.coefficients = body_coefficients(body.local[b0], body.local[b1], body.local[k]);
    c.name = "body " + body.name + ": " + d.joints[static_cast<std::size_t>(body.joints[k])].name + " from " +
             pair_name(d, j0, j1);
    c.body = index;
    c.place = body.place;
    out.push_back(std::move(c));
  }
  return out;
}

// The driver's constraint: the crank's joint on its circle at angle t, the slider's joint at travel
// t along its line, the actuator's joints t apart, or the motor's two links at angle t.
Constraint driver_constraint(const LinkageDescription& d, const DriverSpec& driver) {
  Constraint c;
  c.kind = driver.kind == DriverKind::crank ? ConstraintKind::crank : ConstraintKind::slider_travel;
  c.place = driver.place;
  if (driver.kind == DriverKind::crank) {
    c.joints = {driver.pivot, driver.joint, -1};
    c.length = crank_radius(d, driver);
    c.name = "crank " + pair_name(d, driver.pivot, driver.joint);
  } else if (driver.kind == DriverKind::actuator) {
    c.kind = ConstraintKind::actuator;
    c.joints = {driver.from, driver.joint, -1};
    c.length = driver.reference;  // the scale below which its direction is rounding (linkage_rows.hpp)
    c.name = "actuator " + pair_name(d, driver.from, driver.joint);
  } else if (driver.kind == DriverKind::motor) {
    c.kind = ConstraintKind::motor;
    c.joints = {driver.pivot, driver.from, driver.joint};
    c.length = held_distance(d, driver.pivot, driver.joint);
    c.name = "motor " + d.joints[static_cast<std::size_t>(driver.from)].name + "-" + pair_name(d, driver.pivot, driver.joint);
  } else {
    const SliderSpec& slider = d.sliders[static_cast<std::size_t>(driver.slider)];
    c.joints = {driver.joint, -1, -1};
    c.point = slider.through;
    c.direction = unit(slider.angle_deg * std::numbers::pi / 180.0);
    c.name = "slider driver " + d.joints[static_cast<std::size_t>(driver.joint)].name;
  }
  return c;
}

}  // namespace

void LinkageModel::derive() {
  const auto& d = description_;
  column_.assign(d.joints.size(), -1);
  for (std::size_t j = 0; j < d.joints.size(); ++j) {
    if (!d.joints[j].ground) {
      column_[j] = 2 * static_cast<int>(moving_.size());
      moving_.push_back(static_cast<int>(j));
    }
  }
  // 1. Links: one distance each, but the crank's own link is the driver's.
  for (const LinkSpec& link : d.links) {
    if (crank_of_pair(d, link.first, link.second) != nullptr) continue;
    Constraint c;
    c.kind = ConstraintKind::distance;
    c.joints = {link.first, link.second, -1};
    c.length = link.length;
    c.name = "link " + pair_name(d, link.first, link.second);
    c.place = link.place;
    add(std::move(c));
  }
  // 2. Bodies: the base pair's distance, then each further joint placed by the base pair.
  for (std::size_t b = 0; b < d.bodies.size(); ++b) {
    const std::array<int, 2> pair = base_pairs_.empty() ? std::array<int, 2>{0, 1} : base_pairs_[b];
    for (Constraint& c : body_constraints(d, static_cast<int>(b), pair)) add(std::move(c));
  }
  // 3. Sliders: the joint on its line (fixed, or through two joints of a moving body).
  for (const SliderSpec& slider : d.sliders) {
    Constraint c;
    if (slider.on_link()) {
      c.kind = ConstraintKind::slider_on_line;
      c.joints = {slider.joint, slider.line_from, slider.line_to};
      c.offset = slider.offset;
      c.name = "slider " + d.joints[static_cast<std::size_t>(slider.joint)].name + " on " +
               pair_name(d, slider.line_from, slider.line_to);
      c.place = slider.place;
      add(std::move(c));
      continue;
    }
    c.kind = ConstraintKind::slider_line;
    c.joints = {slider.joint, -1, -1};
    c.point = slider.through;
    c.direction = unit(slider.angle_deg * std::numbers::pi / 180.0);
    c.name = "slider " + d.joints[static_cast<std::size_t>(slider.joint)].name;
    c.place = slider.place;
    add(std::move(c));
  }
  // 4. The driver, then the second driver's constraint holding its reference value.
  add(driver_constraint(d, d.driver));
  if (d.second_driver) {
    Constraint c = driver_constraint(d, *d.second_driver);
    c.held = true;
    c.name = "held " + c.name;
    add(std::move(c));
    hold_second_driver(d.second_driver->reference);
  }
}

std::string LinkageModel::row_name(int row) const {
  const Constraint& c = constraints_[static_cast<std::size_t>(row_constraint_[static_cast<std::size_t>(row)])];
  if (c.rows() == 1) return c.name;
  const bool second = row != first_row(row_constraint_[static_cast<std::size_t>(row)]);
  return c.name + (second ? " (y)" : " (x)");
}

std::string LinkageModel::column_name(int column) const {
  const auto& joint = description_.joints[static_cast<std::size_t>(moving_[static_cast<std::size_t>(column / 2)])];
  return (column % 2 == 0 ? "x_" : "y_") + joint.name;
}

double LinkageModel::driver_from_user(double value) const {
  return crank_driven() ? value * std::numbers::pi / 180.0 : value;
}

double LinkageModel::second_driver() const {
  for (const Constraint& c : constraints_) {
    if (c.held) return description_.second_driver->angle() ? c.held_value * 180.0 / std::numbers::pi : c.held_value;
  }
  return std::numeric_limits<double>::quiet_NaN();
}

void LinkageModel::hold_second_driver(double user_value) {
  for (Constraint& c : constraints_) {
    if (!c.held) continue;
    c.held_value = description_.second_driver->angle() ? user_value * std::numbers::pi / 180.0 : user_value;
    if (c.kind == ConstraintKind::crank) c.direction = unit(c.held_value + c.offset);
  }
}

void LinkageModel::second_driver_derivative(double user_value, Eigen::VectorXd& phi_s) const {
  phi_s.setZero(equation_count_);
  const double s = std::isnan(user_value) ? second_driver() : user_value;
  for (std::size_t k = 0; k < constraints_.size(); ++k) {
    const Constraint& c = constraints_[k];
    if (!c.held) continue;
    if (c.kind == ConstraintKind::crank) phi_s.segment<2>(first_row_[k]) = -c.length * perp(unit(s * std::numbers::pi / 180.0 + c.offset));
    if (c.kind == ConstraintKind::slider_travel || c.kind == ConstraintKind::actuator) phi_s(first_row_[k]) = -1.0;
  }
}

double LinkageModel::driver_to_user(double value) const {
  return crank_driven() ? value * 180.0 / std::numbers::pi : value;
}

JointPositions LinkageModel::positions(const Eigen::VectorXd& q) const {
  JointPositions p;
  p.reserve(description_.joints.size());
  for (std::size_t j = 0; j < description_.joints.size(); ++j) {
    p.push_back(column_[j] < 0 ? description_.joints[j].position : Eigen::Vector2d(q(column_[j]), q(column_[j] + 1)));
  }
  return p;
}

Eigen::VectorXd LinkageModel::unknowns(const JointPositions& positions) const {
  Eigen::VectorXd q(unknown_count());
  for (std::size_t k = 0; k < moving_.size(); ++k) q.segment<2>(2 * static_cast<Eigen::Index>(k)) = positions[static_cast<std::size_t>(moving_[k])];
  return q;
}

JointPositions LinkageModel::rough_positions() const {
  JointPositions p;
  for (const auto& joint : description_.joints) p.push_back(joint.position);
  return p;
}

namespace {

// Position of joint j: from q, or fixed.
struct PositionReader {
  const LinkageModel& model;
  const Eigen::VectorXd& q;
  Eigen::Vector2d operator()(int joint) const {
    const int column = model.column_of(joint);
    return column < 0 ? model.description().joints[static_cast<std::size_t>(joint)].position
                      : Eigen::Vector2d(q(column), q(column + 1));
  }
};

// Adds `block` (rows x 2) to J at the joint's columns, if it moves.
template <typename Block>
void put(const LinkageModel& model, Eigen::MatrixXd& J, int row, int joint, const Block& block) {
  const int column = model.column_of(joint);
  if (column >= 0) J.block(row, column, block.rows(), 2) += block;
}

}  // namespace

void LinkageModel::residual(const Eigen::VectorXd& q, double t, Eigen::VectorXd& f) const {
  const PositionReader p{*this, q};
  f.resize(equation_count_);
  for (std::size_t k = 0; k < constraints_.size(); ++k) {
    const Constraint& c = constraints_[k];
    const int row = first_row_[k];
    switch (c.kind) {
      case ConstraintKind::distance:
        f(row) = ((p(c.joints[0]) - p(c.joints[1])).squaredNorm() - c.length * c.length) / (2.0 * c.length);
        break;
      case ConstraintKind::body_point: {
        const Eigen::Vector2d base = p(c.joints[1]) - p(c.joints[0]);
        f.segment<2>(row) = p(c.joints[2]) - p(c.joints[0]) - c.coefficients.x() * base - c.coefficients.y() * perp(base);
        break;
      }
      case ConstraintKind::slider_line: {
        const Eigen::Vector2d offset = p(c.joints[0]) - c.point;
        f(row) = c.direction.x() * offset.y() - c.direction.y() * offset.x();
        break;
      }
      case ConstraintKind::crank:
        f.segment<2>(row) = p(c.joints[1]) - p(c.joints[0]) - c.length * (c.held ? c.direction : unit(t + c.offset));
        break;
      case ConstraintKind::slider_travel:
        f(row) = c.direction.dot(p(c.joints[0]) - c.point) - (c.held ? c.held_value : t);
        break;
      case ConstraintKind::slider_on_line:
        f(row) = detail::line_slot_row(p(c.joints[0]), p(c.joints[1]), p(c.joints[2]), c.offset).value;
        break;
      case ConstraintKind::actuator:
        f(row) = (p(c.joints[0]) - p(c.joints[1])).norm() - (c.held ? c.held_value : t);
        break;
      case ConstraintKind::motor:
        f(row) = detail::motor_row(p(c.joints[0]), p(c.joints[1]), p(c.joints[2]), t, c.length).value;
        break;
    }
  }
}

// Each constraint's partial derivatives, block by block: put(row, joint, block) for every joint the
// constraint involves (a block of the constraint's rows by the joint's x and y).
template <typename Put>
void LinkageModel::for_each_partial(const Eigen::VectorXd& q, double t, Put put) const {
  const PositionReader p{*this, q};
  const Eigen::Matrix2d identity = Eigen::Matrix2d::Identity();
  for (std::size_t k = 0; k < constraints_.size(); ++k) {
    const Constraint& c = constraints_[k];
    const int row = first_row_[k];
    switch (c.kind) {
      case ConstraintKind::distance: {
        const Eigen::RowVector2d g = (p(c.joints[0]) - p(c.joints[1])).transpose() / c.length;
        put(row, c.joints[0], g);
        put(row, c.joints[1], Eigen::RowVector2d(-g));
        break;
      }
      case ConstraintKind::body_point: {
        // d/d b1 of a base + b perp(base): a I + b R, R = [[0, -1], [1, 0]] (perp as a matrix).
        Eigen::Matrix2d rotation;
        rotation << 0.0, -1.0, 1.0, 0.0;
        const Eigen::Matrix2d along = c.coefficients.x() * identity + c.coefficients.y() * rotation;
        put(row, c.joints[0], Eigen::Matrix2d(along - identity));
        put(row, c.joints[1], Eigen::Matrix2d(-along));
        put(row, c.joints[2], identity);
        break;
      }
      case ConstraintKind::slider_line:
        put(row, c.joints[0], Eigen::RowVector2d(-c.direction.y(), c.direction.x()));
        break;
      case ConstraintKind::crank:
        put(row, c.joints[0], Eigen::Matrix2d(-identity));
        put(row, c.joints[1], identity);
        break;
      case ConstraintKind::slider_travel:
        put(row, c.joints[0], Eigen::RowVector2d(c.direction.transpose()));
        break;
      case ConstraintKind::slider_on_line: {
        const detail::LineSlotRow slot = detail::line_slot_row(p(c.joints[0]), p(c.joints[1]), p(c.joints[2]), c.offset);
        put(row, c.joints[0], Eigen::RowVector2d(slot.dA.transpose()));
        put(row, c.joints[1], Eigen::RowVector2d(slot.dB.transpose()));
        put(row, c.joints[2], Eigen::RowVector2d(slot.dC.transpose()));
        break;
      }
      case ConstraintKind::actuator: {
        const Eigen::RowVector2d g = detail::actuator_gradient(p(c.joints[0]), p(c.joints[1]), c.length).transpose();
        put(row, c.joints[0], g);
        put(row, c.joints[1], Eigen::RowVector2d(-g));
        break;
      }
      case ConstraintKind::motor: {
        const detail::MotorRow motor = detail::motor_row(p(c.joints[0]), p(c.joints[1]), p(c.joints[2]), t, c.length);
        put(row, c.joints[0], Eigen::RowVector2d(motor.dA.transpose()));
        put(row, c.joints[1], Eigen::RowVector2d(motor.dB.transpose()));
        put(row, c.joints[2], Eigen::RowVector2d(motor.dC.transpose()));
        break;
      }
    }
  }
}

void LinkageModel::jacobian(const Eigen::VectorXd& q, double t, Eigen::MatrixXd& J) const {
  J.setZero(equation_count_, unknown_count());
  for_each_partial(q, t, [&](int row, int joint, const auto& block) { put(*this, J, row, joint, block); });
}

void LinkageModel::jacobian_entries(const Eigen::VectorXd& q, double t, std::vector<JacobianEntry>& entries) const {
  entries.clear();
  for_each_partial(q, t, [&](int row, int joint, const auto& block) {
    const int column = column_of(joint);
    if (column < 0) return;  // a ground joint: no unknowns
    for (Eigen::Index r = 0; r < block.rows(); ++r) {
      for (int xy = 0; xy < 2; ++xy) entries.push_back({row + static_cast<int>(r), column + xy, block(r, xy)});
    }
  });
}

void LinkageModel::multiplier_forces(const Eigen::VectorXd& q, double t, const Eigen::VectorXd& lambda,
                                     std::vector<Eigen::Vector2d>& forces) const {
  for (Eigen::Vector2d& f : forces) f.setZero();
  for_each_partial(q, t, [&](int row, int joint, const auto& block) {
    constexpr int rows = std::decay_t<decltype(block)>::RowsAtCompileTime;
    forces[static_cast<std::size_t>(joint)] += block.transpose() * lambda.template segment<rows>(row);
  });
}

void LinkageModel::driver_derivative(const Eigen::VectorXd& q, double t, Eigen::VectorXd& phi_t) const {
  const PositionReader p{*this, q};
  phi_t.setZero(equation_count_);
  for (std::size_t k = 0; k < constraints_.size(); ++k) {
    const Constraint& c = constraints_[k];
    if (c.held) continue;  // the second driver's value does not move with t
    if (c.kind == ConstraintKind::crank) phi_t.segment<2>(first_row_[k]) = -c.length * perp(unit(t + c.offset));
    if (c.kind == ConstraintKind::slider_travel || c.kind == ConstraintKind::actuator) phi_t(first_row_[k]) = -1.0;
    if (c.kind == ConstraintKind::motor) {
      phi_t(first_row_[k]) = detail::motor_row(p(c.joints[0]), p(c.joints[1]), p(c.joints[2]), t, c.length).dt;
    }
  }
}

void LinkageModel::acceleration_rhs(const Eigen::VectorXd& q, const Eigen::VectorXd& qdot, double t,
                                    Eigen::VectorXd& gamma) const {
  const PositionReader p{*this, q};
  const PositionReader v{*this, qdot};  // velocities; ground joints read as their positions, so mask them
  const auto velocity = [&](int joint) -> Eigen::Vector2d {
    return column_of(joint) < 0 ? Eigen::Vector2d::Zero() : v(joint);
  };
  gamma.setZero(equation_count_);
  for (std::size_t k = 0; k < constraints_.size(); ++k) {
    const Constraint& c = constraints_[k];
    const int row = first_row_[k];
    // The rows linear in q and t (body points, fixed sliders, the slider driver) have none.
    const auto [a, b, e] = c.joints;
    if (c.kind == ConstraintKind::distance) {
      gamma(row) = -(velocity(a) - velocity(b)).squaredNorm() / c.length;
    } else if (c.kind == ConstraintKind::crank && !c.held) {
      gamma.segment<2>(row) = -c.length * unit(t + c.offset);
    } else if (c.kind == ConstraintKind::slider_on_line) {
      gamma(row) = -detail::line_slot_second(p(a), p(b), p(e), velocity(a), velocity(b), velocity(e));
    } else if (c.kind == ConstraintKind::actuator) {
      gamma(row) = -detail::actuator_second(p(a), p(b), velocity(a), velocity(b), c.length);
    } else if (c.kind == ConstraintKind::motor) {
      gamma(row) = -detail::motor_second(p(a), p(b), p(e), velocity(a), velocity(b), velocity(e), t, c.length);
    }
  }
}

Eigen::Matrix<bool, Eigen::Dynamic, Eigen::Dynamic> LinkageModel::pattern() const {
  Eigen::Matrix<bool, Eigen::Dynamic, Eigen::Dynamic> result =
      Eigen::Matrix<bool, Eigen::Dynamic, Eigen::Dynamic>::Constant(equation_count_, unknown_count(), false);
  for (std::size_t k = 0; k < constraints_.size(); ++k) {
    const Constraint& c = constraints_[k];
    for (int joint : c.joints) {
      if (joint < 0 || column_of(joint) < 0) continue;
      result.block(first_row_[k], column_of(joint), c.rows(), 2).setConstant(true);
    }
  }
  return result;
}

}  // namespace numlab::mechanisms
