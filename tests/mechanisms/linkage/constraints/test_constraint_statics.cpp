// The driver's load through the new drivers and constraints (linkage_statics.hpp): an actuator's
// force (N), a motor's torque (N x length unit), a crank's torque through a slot, checked at several
// poses against
//  - virtual work: driver * 1 + sum F . v_J + sum T omega = 0 per unit of driver;
//  - the central difference of the loads' potential V = -sum F . r_J - sum T theta along the closed
//    form's positions (constraint_mechanisms.hpp), which knows nothing of the model: driver = dV/dt;
//  - the balance of the whole mechanism: the ground's reactions and the loads in force and in moment
//    (the crank's torque from the ground counts; the actuator and the motor act between members);
//  - the boom's push by moments about its pivot: F = m g x_T / (P x u), u the cylinder's direction.
// The same figures in mm and in km: forces unchanged, torques scaled by the unit.

#include <catch2/catch.hpp>

#include <Eigen/LU>
#include <cmath>

#include "constraint_mechanisms.hpp"
#include "newton_polish.hpp"
#include "numlab/mechanisms/linkage/link_motion.hpp"
#include "numlab/mechanisms/linkage/linkage_statics.hpp"
#include "numlab/mechanisms/linkage/linkage_sweep.hpp"

using namespace numlab::mechanisms;
using namespace numlab::mechanisms::testing;

namespace {

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

// A pose at driver t (model units) solved to rounding, with its velocity.
LinkagePose pose_at(const LinkageSolver& solver, double t, const Eigen::VectorXd& near) {
  const LinkageModel& model = solver.model();
  LinkagePose pose;
  pose.driver = model.driver_to_user(t);
  pose.q = polish(model, t, solver.solve(t, near).q);
  pose.velocity = linkage_velocity(model, t, pose.q);
  pose.outcome.status = numlab::Status::converged;
  pose.condition = linkage_condition(model, t, pose.q);
  return pose;
}

// V = -sum F . r_J - sum T theta_line over the closed form's joints.
double potential(const LinkageDescription& d, const Joints& joints) {
  const auto lines = link_lines(d);
  const auto p = [&](int joint) { return joints.at(d.joints[static_cast<std::size_t>(joint)].name); };
  double v = 0.0;
  for (const LoadSpec& load : d.loads) {
    if (load.kind == LoadKind::force) v -= load.force.dot(p(load.joint));
    if (load.kind == LoadKind::mass) v += load.mass * d.gravity * p(load.joint).y();
    if (load.kind == LoadKind::torque) {
      const LinkLine& line = lines[static_cast<std::size_t>(load.line)];
      const Eigen::Vector2d r = p(line.to) - p(line.from);
      v -= load.torque * std::atan2(r.y(), r.x());  // the difference below stays within a half turn
    }
  }
  return v;
}

// Every check at each driver value; returns the driver loads.
template <typename Closed>
std::vector<double> check_statics(const std::string& text, const Closed& closed, const std::vector<double>& drivers, double size) {
  const LinkageModel model(parse_linkage_description(text, "loads.toml"));
  const LinkageSolver solver(model, LinkageSolverOptions{});
  LinkageStaticsSolver statics(model);
  const LinkageDescription& d = model.description();
  const auto lines = link_lines(d);
  const auto supports = statics_supports(d);
  std::vector<double> loads_found;
  Eigen::VectorXd q = solver.reference();
  for (const double t : drivers) {
    INFO("driver " << model.driver_to_user(t));
    const LinkagePose pose = pose_at(solver, t, q);
    q = pose.q;
    const LinkageStatics& s = statics.solve(pose);
    REQUIRE(s.status == StaticsStatus::equilibrium);
    REQUIRE(std::isfinite(s.driver));
    loads_found.push_back(s.driver);
    const auto joints = joint_motions(model, pose.q, pose.velocity, {});
    // 1. Virtual work.
    double power = 0.0, scale = std::abs(s.driver);
    for (const LoadSpec& load : d.loads) {
      double term = 0.0;
      if (load.kind == LoadKind::force) term = load.force.dot(joints[static_cast<std::size_t>(load.joint)].v);
      if (load.kind == LoadKind::mass) term = -load.mass * d.gravity * joints[static_cast<std::size_t>(load.joint)].v.y();
      if (load.kind == LoadKind::torque) {
        const LinkLine& line = lines[static_cast<std::size_t>(load.line)];
        term = load.torque * angular_motion(joints[static_cast<std::size_t>(line.from)], joints[static_cast<std::size_t>(line.to)]).omega;
      }
      power += term;
      scale += std::abs(term);
    }
    CHECK(std::abs(s.driver + power) <= 1e-11 * scale);
    // 2. The potential's slope along the closed form (h: 1e-5 of the driver's unit, 4th order).
    const double h = 1e-4 * (model.crank_driven() ? 1.0 : size);
    const auto V = [&](double k) { return potential(d, closed(t + k * h)); };
    const double slope = (V(-2) - 8.0 * V(-1) + 8.0 * V(1) - V(2)) / (12.0 * h);
    CHECK(std::abs(s.driver - slope) <= 1e-7 * scale);
    // 3. The balance of the whole mechanism: reactions + loads, in force and in moment about O.
    std::vector<Eigen::Vector2d> applied(d.joints.size(), Eigen::Vector2d::Zero());
    applied_joint_forces(model, pose.q, applied);
    Eigen::Vector2d force = Eigen::Vector2d::Zero();
    double moment = 0.0, force_scale = 0.0;
    for (std::size_t j = 0; j < applied.size(); ++j) {
      force += applied[j];
      moment += cross(joints[j].p, applied[j]);
      force_scale += applied[j].norm();
    }
    for (std::size_t k = 0; k < supports.size(); ++k) {
      force += s.reactions[k];
      moment += cross(joints[static_cast<std::size_t>(supports[k].joint)].p, s.reactions[k]);
      force_scale += s.reactions[k].norm();
    }
    // A crank's torque acts between the ground and the crank: an outside moment. An actuator's force
    // and a motor's torque act between members, the actuator's ground end through its joint's reaction.
    if (d.driver.kind == DriverKind::crank) moment += s.driver;
    CHECK(force.norm() <= 1e-12 * force_scale);
    CHECK(std::abs(moment) <= 1e-12 * (force_scale * size + std::abs(s.driver)));
  }
  return loads_found;
}

const std::string rocker_loads = R"(
[[load]]
link = "rocker"
torque = -10.0

[[load]]
joint = "C"
force = [1.0, -5.0]
)";

}  // namespace

TEST_CASE("A crank's torque through a slot (the inverted slider-crank) by virtual work and the potential", "[linkage][constraints][statics]") {
  std::vector<double> drivers;
  for (double a = 60.0; a < 420.0; a += 30.0) drivers.push_back(a * deg);
  std::vector<std::vector<double>> torques;
  for (const double k : {1e-3, 1.0, 1e3}) {
    INFO("scale " << k);
    const InvertedSliderCrank mechanism{k, 0.3};
    torques.push_back(check_statics(mechanism.text(60.0, rocker_loads), [&](double t) { return mechanism.at(t); }, drivers, 5 * k));
  }
  // The torque T on the rocker scales with nothing; the force's moment with the unit. With only the
  // torque the crank's torque would be the same at every scale: here tau(k) = tau_T + k tau_F.
  for (std::size_t i = 0; i < drivers.size(); ++i) {
    const double tau_F = (torques[2][i] - torques[1][i]) / (1e3 - 1.0), tau_T = torques[1][i] - tau_F;
    CHECK(torques[0][i] == Approx(tau_T + 1e-3 * tau_F).epsilon(1e-9).margin(1e-12 * std::abs(tau_T)));
  }
}

TEST_CASE("An actuator's force: the boom against the moments about its pivot, in mm and in km", "[linkage][constraints][statics]") {
  const std::string mass = "\n[[load]]\njoint = \"T\"\nmass = 10.0\n";
  for (const double k : {1e-3, 1.0, 1e3}) {
    INFO("scale " << k);
    const Boom boom{k};
    std::vector<double> drivers;
    for (double s = 1.2; s <= 2.85; s += 0.15) drivers.push_back(s * k);
    const std::vector<double> forces = check_statics(boom.text(1.8 * k, mass), [&](double s) { return boom.at(s); }, drivers, 3 * k);
    for (std::size_t i = 0; i < drivers.size(); ++i) {
      const Joints j = boom.at(drivers[i]);
      const Eigen::Vector2d u = (j.at("P") - j.at("G")).normalized();
      const double by_moments = 10.0 * standard_gravity * j.at("T").x() / cross(j.at("P"), u);
      CHECK(forces[i] == Approx(by_moments).epsilon(1e-11));
    }
  }
}

TEST_CASE("A motor's torque between two moving links by virtual work, the potential and the balance", "[linkage][constraints][statics]") {
  const std::string loads = "\n[[load]]\nlink = \"rocker\"\ntorque = 7.0\n\n[[load]]\njoint = \"B\"\nforce = [2.0, -3.0]\n";
  std::vector<double> drivers;
  for (double a = 100.0; a <= 170.0; a += 10.0) drivers.push_back(a * deg);
  for (const double k : {1e-3, 1.0, 1e3}) {
    INFO("scale " << k);
    const MotorFourBar four_bar{k};
    check_statics(four_bar.text(100.0, loads), [&](double t) { return four_bar.at(t); }, drivers, 4.5 * k);
  }
}
