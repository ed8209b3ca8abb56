// The driving torque and the reactions (linkage_statics.hpp) against independent references:
//  - virtual work: driver * 1 + sum F . v_J (+ T omega for a torque) = 0 per radian at every pose,
//    with the velocities the sweep reports;
//  - a central difference of the potential of the constant loads, V = -sum F . r_J - sum T theta,
//    tau = dV/dtheta, from positions solved to rounding at theta +- h;
//  - the whole mechanism's balance of forces and moments with the reactions;
//  - closed forms: the offset slider-crank with a horizontal force P on its slider (tau = -P dx_S/dtheta,
//    dx_S/dtheta differentiated by hand), and the four-bar's free-body method (the coupler a two-force
//    member) with a torque on the rocker;
// on the shipped four-bar and slider-crank and a textbook four-bar in mm and in km; a change point
// (J singular) is `singular`, never a NaN.

#include <catch2/catch.hpp>

#include <Eigen/LU>
#include <cmath>

#include "four_bar_text.hpp"
#include "model_files.hpp"
#include "numlab/linalg/matrix_file.hpp"
#include "newton_polish.hpp"
#include "numlab/mechanisms/linkage/link_motion.hpp"
#include "numlab/mechanisms/linkage/linkage_statics.hpp"
#include "numlab/mechanisms/linkage/linkage_sweep.hpp"

using namespace numlab::mechanisms;
using namespace numlab::mechanisms::testing;

namespace {

std::string read_text(const std::string& path) { return numlab::linalg::read_text_file(path); }

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

LinkagePose pose_at(const LinkageSolver& solver, double degrees) {
  const LinkageSweep sweep = linkage_sweep(solver, degrees, degrees, 1.0);
  REQUIRE(sweep.poses.size() == 1);
  return sweep.poses[0];
}

// Each load's line: the joints its angle turns with.
std::pair<int, int> line_joints(const LinkageDescription& d, int line) {
  const auto lines = link_lines(d);
  return {lines[static_cast<std::size_t>(line)].from, lines[static_cast<std::size_t>(line)].to};
}

// The loads' power per unit of driver: sum F . v_J + sum T omega, written from the file's loads.
// Also the scale of its terms, sum |F| |v_J| + |T omega|.
std::pair<double, double> load_power(const LinkageModel& model, const LinkagePose& pose) {
  const auto joints = joint_motions(model, pose.q, pose.velocity, pose.acceleration);
  double power = 0.0, scale = 0.0;
  for (const LoadSpec& load : model.description().loads) {
    double term = 0.0;
    if (load.kind == LoadKind::force) term = load.force.dot(joints[static_cast<std::size_t>(load.joint)].v);
    if (load.kind == LoadKind::mass) term = -load.mass * model.description().gravity * joints[static_cast<std::size_t>(load.joint)].v.y();
    if (load.kind == LoadKind::torque) {
      const auto [from, to] = line_joints(model.description(), load.line);
      term = load.torque * angular_motion(joints[static_cast<std::size_t>(from)], joints[static_cast<std::size_t>(to)]).omega;
    }
    power += term;
    scale += std::abs(term);
  }
  return {power, scale};
}

// V(plus) - V(minus), V = -sum F . r_J - sum T theta (the angle's change taken within a half turn).
double potential_change(const LinkageModel& model, const Eigen::VectorXd& plus, const Eigen::VectorXd& minus) {
  const auto p = joint_motions(model, plus, {}, {}), m = joint_motions(model, minus, {}, {});
  const auto angle = [&](const std::vector<JointMotion>& j, int line) {
    const auto [from, to] = line_joints(model.description(), line);
    const Eigen::Vector2d d = j[static_cast<std::size_t>(to)].p - j[static_cast<std::size_t>(from)].p;
    return std::atan2(d.y(), d.x());
  };
  double change = 0.0;
  for (const LoadSpec& load : model.description().loads) {
    const std::size_t j = static_cast<std::size_t>(load.joint < 0 ? 0 : load.joint);
    if (load.kind == LoadKind::force) change -= load.force.dot(p[j].p - m[j].p);
    if (load.kind == LoadKind::mass) change += load.mass * model.description().gravity * (p[j].p.y() - m[j].p.y());
    if (load.kind == LoadKind::torque) change -= load.torque * std::remainder(angle(p, load.line) - angle(m, load.line), 2.0 * pi);
  }
  return change;
}

// dV/dtheta by a central difference, h = 1e-4 rad, positions solved to rounding from the pose.
double potential_slope(const LinkageModel& model, const LinkagePose& pose) {
  const double t = model.driver_from_user(pose.driver), h = 1e-4;
  const Eigen::VectorXd plus = polish(model, t + h, pose.q + h * pose.velocity);
  const Eigen::VectorXd minus = polish(model, t - h, pose.q - h * pose.velocity);
  return potential_change(model, plus, minus) / (2.0 * h);
}

// Every check but the closed forms, at each listed crank angle; returns the driver torques.
std::vector<double> check_statics(const std::string& text, const std::vector<double>& angles, double size) {
  const LinkageModel model(parse_linkage_description(text, "loads.toml"));
  LinkageSolverOptions options;
  options.newton.residual_tolerance = 1e-13 * std::max(size, 1.0);  // polished to rounding below
  const LinkageSolver solver(model, options);
  LinkageStaticsSolver statics(model);
  std::vector<double> torques;
  for (double degrees : angles) {
    INFO("crank " << degrees << " deg");
    LinkagePose pose = pose_at(solver, degrees);
    REQUIRE(pose.outcome.status == numlab::Status::converged);
    pose.q = polish(model, model.driver_from_user(degrees), pose.q);
    pose.velocity = linkage_velocity(model, model.driver_from_user(degrees), pose.q);
    const LinkageStatics& s = statics.solve(pose);
    REQUIRE(s.status == StaticsStatus::equilibrium);
    torques.push_back(s.driver);
    // Virtual work: tau * 1 + power of the loads = 0.
    const auto [power, scale] = load_power(model, pose);
    CHECK(std::abs(s.driver + power) <= 1e-11 * (scale + std::abs(s.driver)));
    // The potential's slope: tau = dV/dtheta (the difference's truncation h^2 ~ 1e-8 of the terms).
    const double slope = potential_slope(model, pose);
    CHECK(std::abs(s.driver - slope) <= 1e-6 * (scale + std::abs(s.driver)));
    // Balance of the whole: loads + reactions = 0, and their moments + tau = 0 (about the origin).
    std::vector<Eigen::Vector2d> applied(model.description().joints.size());
    applied_joint_forces(model, pose.q, applied);
    const auto joints = joint_motions(model, pose.q, {}, {});
    Eigen::Vector2d force = Eigen::Vector2d::Zero();
    double moment = s.driver, force_scale = 0.0;
    for (std::size_t j = 0; j < applied.size(); ++j) {
      force += applied[j];
      moment += cross(joints[j].p, applied[j]);
      force_scale += applied[j].norm();
    }
    const auto supports = statics_supports(model.description());
    for (std::size_t k = 0; k < supports.size(); ++k) {
      force += s.reactions[k];
      moment += cross(joints[static_cast<std::size_t>(supports[k].joint)].p, s.reactions[k]);
      force_scale += s.reactions[k].norm();
    }
    CHECK(force.norm() <= 1e-12 * force_scale);
    CHECK(std::abs(moment) <= 1e-12 * (force_scale * size + std::abs(s.driver)));
  }
  return torques;
}

const std::vector<double> crank_angles{0.0, 35.0, 100.0, 170.0, 230.0, 300.0};

// The four-bar's free body: a torque T on the rocker Q-B, the coupler A-B a two-force member with
// force f along u = (B - A)/|B - A| on B. Rocker: T + (B - Q) x (f u) = 0. Crank: the coupler pushes
// A with -f u, so tau + (A - O) x (-f u) = 0.
double free_body_torque(const Eigen::Vector2d& O, const Eigen::Vector2d& A, const Eigen::Vector2d& B,
                        const Eigen::Vector2d& Q, double T) {
  const Eigen::Vector2d u = (B - A).normalized();
  const double f = -T / cross(B - Q, u);
  return f * cross(A - O, u);
}

}  // namespace

TEST_CASE("shipped four-bar and slider-crank: the driver torque by virtual work, the potential and the balance",
          "[linkage-statics]") {
  std::string four_bar = read_text(model_path("four-bar"));
  four_bar += "\n[[load]]\nlink = \"Q-B\"\ntorque = -10.0\n[[load]]\njoint = \"B\"\nmass = 2.0\n"
              "[[load]]\njoint = \"A\"\nforce = [3.0, -4.0]\n";
  check_statics(four_bar, crank_angles, 4.5);
  std::string slider = read_text(model_path("slider-crank"));
  slider += "\n[[load]]\njoint = \"S\"\nforce = [-100.0, 0.0]\n[[load]]\nlink = \"A-S\"\ntorque = 1.5\n"
            "[[load]]\njoint = \"A\"\nmass = 0.5\n";
  check_statics(slider, crank_angles, 3.2);
}

TEST_CASE("slider-crank with a horizontal force P on the slider: tau = -P dx_S/dtheta, in units, mm and km",
          "[linkage-statics]") {
  for (const double scale : {1.0, 1e3, 1e6}) {
    INFO("scale " << scale);
    const double r = 1.0 * scale, l = 3.2 * scale, e = 0.4 * scale, P = -100.0;
    // The shipped slider-crank.toml with every length times `scale`.
    const std::string text = fmt::format("[linkage]\nname = \"sc\"\n[ground]\nO = [0.0, 0.0]\n[joints]\nA = [{0:.17g}, {1:.17g}]\nS = [{2:.17g}, {3:.17g}]\n"
                       "[[link]]\njoints = [\"O\", \"A\"]\nlength = {4:.17g}\n[[link]]\njoints = [\"A\", \"S\"]\nlength = {5:.17g}\n"
                       "[[slider]]\njoint = \"S\"\nthrough = [0.0, {3:.17g}]\n[driver]\ntype = \"crank\"\npivot = \"O\"\n"
                       "joint = \"A\"\nangle = 30.0\n[[load]]\njoint = \"S\"\nforce = [{6:.17g}, 0.0]\n",
                       0.87 * scale, 0.5 * scale, 4.0 * scale, e, r, l, P);
    const auto torques = check_statics(text, crank_angles, l);
    for (std::size_t k = 0; k < crank_angles.size(); ++k) {
      const double t = crank_angles[k] * deg;
      // x_S = r cos t + sqrt(l^2 - (r sin t - e)^2)
      const double root = std::sqrt(l * l - std::pow(r * std::sin(t) - e, 2));
      const double dx = -r * std::sin(t) - (r * std::sin(t) - e) * r * std::cos(t) / root;
      CHECK(std::abs(torques[k] - (-P * dx)) <= 1e-11 * std::abs(P) * r);
    }
  }
}

TEST_CASE("a textbook four-bar in mm and in km: the free-body torque, and tau scales with the length unit",
          "[linkage-statics]") {
  // Crank 40, coupler 120, rocker 80, ground 100 (mm), a torque of -2 N m on the rocker.
  const double a = 40.0, b = 120.0, c = 80.0, d = 100.0;
  std::vector<double> per_unit;
  for (const double scale : {1.0, 1e-6}) {  // lengths in mm, then in km
    INFO("scale " << scale);
    const double T = -2000.0 * scale;  // -2 N m = -2000 N mm = -2e-3 N km
    const std::string text = four_bar_text(a, b, c, d, scale) +
                             fmt::format("[[load]]\nlink = \"rocker\"\ntorque = {:.17g}\n", T);
    const auto torques = check_statics(text, crank_angles, b * scale);
    const LinkageModel model(parse_linkage_description(text, "fb.toml"));
    LinkageSolverOptions options;
    options.newton.residual_tolerance = 1e-13;
    const LinkageSolver solver(model, options);
    for (std::size_t k = 0; k < crank_angles.size(); ++k) {
      const LinkagePose pose = pose_at(solver, crank_angles[k]);
      const auto j = joint_motions(model, polish(model, crank_angles[k] * deg, pose.q), {}, {});
      const double expected = free_body_torque(j[0].p, j[2].p, j[3].p, j[1].p, T);
      CHECK(std::abs(torques[k] - expected) <= 1e-10 * std::abs(T));
      per_unit.push_back(torques[k] / scale);
    }
  }
  // The same mechanism and load: N mm and N km differ by exactly the unit (1e6 mm per km).
  for (std::size_t k = 0; k < crank_angles.size(); ++k) {
    CHECK(std::abs(per_unit[k] - per_unit[k + crank_angles.size()]) <= 1e-9 * std::abs(per_unit[k]));
  }
}

TEST_CASE("at a change point J is singular: the statics say so, with +inf, never a NaN", "[linkage-statics]") {
  std::string text = read_text(model_path("parallelogram"));
  text += "\n[[load]]\nlink = \"Q-B\"\ntorque = 1.0\n";
  const LinkageModel model(parse_linkage_description(text, "parallelogram.toml"));
  const LinkageSolver solver(model, LinkageSolverOptions{});
  LinkageStaticsSolver statics(model);
  const LinkageSweep sweep = linkage_sweep(solver, 0.0, 180.0, 45.0);
  REQUIRE(sweep.poses.size() == 5);
  for (const LinkagePose& pose : sweep.poses) {
    INFO("crank " << pose.driver);
    const LinkageStatics& s = statics.solve(pose);
    CHECK_FALSE(std::isnan(s.driver));
    const bool change_point = std::abs(std::remainder(pose.driver, 180.0)) < 1e-9;
    CHECK((s.status == StaticsStatus::singular) == change_point);
    if (change_point) CHECK(std::isinf(s.driver));
    // Away from it the parallelogram's rocker turns with the crank: tau = -T.
    if (!change_point) CHECK(std::abs(s.driver + 1.0) < 1e-9);
  }
}

TEST_CASE("a [[load]] read, with gravity's default and its own value", "[linkage-statics]") {
  const std::string base = four_bar_text(1.5, 4.0, 3.5, 4.5, 1.0);
  auto d = parse_linkage_description(base + "[[load]]\njoint = \"B\"\nmass = 2\n[[load]]\nlink = \"coupler\"\ntorque = 1\n", "f.toml");
  REQUIRE(d.loads.size() == 2);
  CHECK(d.gravity == standard_gravity);
  CHECK(d.loads[0].kind == LoadKind::mass);
  CHECK(d.loads[1].kind == LoadKind::torque);
  CHECK(d.loads[1].line == 1);
  d = parse_linkage_description(four_bar_text(1.5, 4.0, 3.5, 4.5, 1.0, 60.0, 1, "gravity = 1.62") +
                                    "[[load]]\njoint = \"B\"\nforce = [1, 2]\n",
                                "f.toml");
  CHECK(d.gravity == 1.62);
  CHECK(d.loads[0].force == Eigen::Vector2d(1.0, 2.0));
}

TEST_CASE("toward a fold the torque grows, finite, then no pose: never a NaN passed off as a number", "[linkage-statics]") {
  // The non-Grashof four-bar of docs/linkage-files.md 'Assembly limits' (crank 2, coupler 3, rocker
  // 2.5, ground 4): it stops assembling at crank 129.838 deg, coupler and rocker in line (|AQ| = 5.5),
  // where J is singular and a torque on the rocker needs an unbounded driver torque.
  const std::string text = four_bar_text(2.0, 3.0, 2.5, 4.0, 1.0) + "[[load]]\nlink = \"rocker\"\ntorque = 1.0\n";
  const LinkageModel model(parse_linkage_description(text, "non-grashof.toml"));
  const LinkageSolver solver(model, LinkageSolverOptions{});
  LinkageStaticsSolver statics(model);
  const LinkageSweep sweep = linkage_sweep(solver, 100.0, 135.0, 0.25);
  double first = 0.0, last = 0.0;
  int equilibria = 0, no_pose = 0;
  for (const LinkagePose& pose : sweep.poses) {
    INFO("crank " << pose.driver);
    const LinkageStatics& s = statics.solve(pose);
    if (s.status == StaticsStatus::equilibrium) {
      CHECK(std::isfinite(s.driver));
      if (equilibria++ == 0) first = std::abs(s.driver);
      last = std::abs(s.driver);
      CHECK(pose.driver < 129.84);
    } else if (s.status == StaticsStatus::singular) {
      CHECK(std::isinf(s.driver));
    } else {
      CHECK(pose.driver > 129.83);  // past the fold: no pose, and so no statics
      ++no_pose;
    }
  }
  CHECK(equilibria > 100);
  CHECK(no_pose > 0);
  CHECK(last > 5.0 * first);  // measured: 0.917 at 100 deg, 9.198 at 129.75 deg, the last pose before the fold
}
