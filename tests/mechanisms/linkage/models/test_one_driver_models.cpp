// The one-driver models issue 30 §5 ships (inverted-slider-crank, whitworth, hydraulic-boom,
// watt-straight-line) solved over a whole sweep the way `numlab mechanism` solves them
// (linkage_sweep: the fast path, continuation, velocities and accelerations from the Jacobian),
// against their closed forms (numlab/mechanisms/closed_forms/, written from each mechanism's
// geometry): every joint's position, velocity and acceleration, every link's angle_, omega_ and
// alpha_, the driver torque or force under the file's loads (the closed form's virtual work, and the
// boom's balance of moments), and each quick-return's toggles and time ratio from --analyse.
// Tolerances are relative to each model's size (its longest link: mm, m).

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <map>
#include <string>

#include "model_files.hpp"
#include "numlab/mechanisms/closed_forms/from_description.hpp"
#include "numlab/mechanisms/linkage/crank_analysis.hpp"
#include "numlab/mechanisms/linkage/link_motion.hpp"
#include "numlab/mechanisms/linkage/linkage_statics.hpp"
#include "numlab/mechanisms/linkage/linkage_structure.hpp"
#include "numlab/mechanisms/linkage/linkage_sweep.hpp"

using namespace numlab::mechanisms;
using namespace numlab::mechanisms::testing;
namespace cf = numlab::mechanisms::closed_forms;

namespace {

// What a closed form gives at one driver value: joints by name, link angles by link name, the
// driver's load (NaN: the file has no loads).
struct Expected {
  std::map<std::string, cf::PointMotion> joints;
  std::map<std::string, cf::AngleMotion> links;
  double driver_load = std::nan("");
};

// The worst differences over a sweep, relative to the model's size (angles: absolute, radians);
// `beyond_bound`: the worst position error over the pose's own bound (closed_form_bound: 10 ||J^-1||
// (||Phi||_2 + n eps |q|), what the residual test allows).
struct Worst {
  double position = 0.0, velocity = 0.0, acceleration = 0.0, beyond_bound = 0.0;
  double angle = 0.0, omega = 0.0, alpha = 0.0, load = 0.0;
  int poses = 0;
};

// The model's size: its longest link or body edge.
double size_of(const LinkageDescription& d) {
  double size = 0.0;
  for (const LinkSpec& link : d.links) size = std::max(size, link.length);
  for (const BodySpec& body : d.bodies) {
    for (const auto& a : body.local) {
      for (const auto& b : body.local) size = std::max(size, (a - b).norm());
    }
  }
  return size;
}

// Sweeps `name` over start:stop:step (user units) with Newton's residual tolerance `tolerance` x size
// (1e-10: numlab mechanism's default) and compares every pose with `expected`.
Worst compare_sweep(const std::string& name, double start, double stop, double step, double tolerance,
                    const std::function<Expected(double driver)>& expected) {
  const LinkageModel model = model_file(name);
  LinkageSolverOptions options;
  options.newton.residual_tolerance = tolerance;
  const LinkageSolver solver(model, options);
  const LinkageSweep sweep = linkage_sweep(solver, start, stop, step);
  REQUIRE(sweep.status == numlab::Status::converged);
  REQUIRE(sweep.branch_kept);
  const double size = size_of(model.description());
  const auto lines = link_lines(model.description());
  LinkageStaticsSolver statics(model);
  Worst worst;
  for (const LinkagePose& pose : sweep.poses) {
    INFO(name << " at " << pose.driver);
    REQUIRE(pose.outcome.status == numlab::Status::converged);
    const Expected e = expected(model.driver_from_user(pose.driver));
    const auto joints = joint_motions(model, pose.q, pose.velocity, pose.acceleration);
    for (const auto& [joint, motion] : e.joints) {
      const auto& got = joints[static_cast<std::size_t>(model.description().joint_index(joint))];
      worst.position = std::max(worst.position, (got.p - motion.p).norm() / size);
      worst.beyond_bound = std::max(worst.beyond_bound, (got.p - motion.p).norm() / pose.closed_form_bound);
      worst.velocity = std::max(worst.velocity, (got.v - motion.v).norm() / size);
      worst.acceleration = std::max(worst.acceleration, (got.a - motion.a).norm() / size);
      REQUIRE(std::isfinite(got.a.norm()));
    }
    int links_found = 0;
    for (const LinkLine& line : lines) {
      const auto it = e.links.find(line.name);
      if (it == e.links.end()) continue;
      ++links_found;
      const AngularMotion got = angular_motion(joints[static_cast<std::size_t>(line.from)], joints[static_cast<std::size_t>(line.to)]);
      worst.angle = std::max(worst.angle, std::abs(std::remainder(got.angle - it->second.angle, 2.0 * cf::pi)));
      worst.omega = std::max(worst.omega, std::abs(got.omega - it->second.omega) / (1.0 + std::abs(it->second.omega)));
      worst.alpha = std::max(worst.alpha, std::abs(got.alpha - it->second.alpha) / (1.0 + std::abs(it->second.alpha)));
    }
    CHECK(links_found == static_cast<int>(e.links.size()));
    if (!std::isnan(e.driver_load)) {
      const LinkageStatics& s = statics.solve(pose);
      REQUIRE(s.status == StaticsStatus::equilibrium);
      worst.load = std::max(worst.load, std::abs(s.driver - e.driver_load) / (1.0 + std::abs(e.driver_load)));
    }
    ++worst.poses;
  }
  return worst;
}

// Each model swept twice: at numlab mechanism's default tolerance (1e-10 x size) every position
// within its pose's bound from the conditioning, and the derivatives, from the same J at that pose,
// within 1e-8 relative (measured 5e-11 ... 2.3e-9), the driver's load within 1e-7 (measured up to
// 4.8e-9); to 1e-13 x size everything within 1e-11, the load 1e-10 (measured: 1e-16 ... 3e-13,
// rounding). The figures: docs/linkage-files.md "The shipped models"; NUMLAB_PRINT_ERRORS=1 in the
// environment prints them.
void check_sweeps(const std::string& name, double start, double stop, double step, int poses,
                  const std::function<Expected(double driver)>& expected) {
  for (const double tolerance : {1e-10, 1e-13}) {
    INFO(name << ", Newton's tolerance " << tolerance << " x size");
    const Worst w = compare_sweep(name, start, stop, step, tolerance, expected);
    if (std::getenv("NUMLAB_PRINT_ERRORS") != nullptr) {
      std::printf("%s tol %g: position %.2e (bound x %.2f) velocity %.2e acceleration %.2e angle %.2e omega %.2e alpha %.2e load %.2e\n",
                  name.c_str(), tolerance, w.position, w.beyond_bound, w.velocity, w.acceleration, w.angle, w.omega, w.alpha, w.load);
    }
    const double bound = tolerance == 1e-10 ? 1e-8 : 1e-11;
    CHECK(w.poses == poses);
    CHECK(w.beyond_bound <= 1.0);
    CHECK(w.position <= bound);
    CHECK(w.velocity <= bound);
    CHECK(w.acceleration <= bound);
    CHECK(w.angle <= bound);
    CHECK(w.omega <= bound);
    CHECK(w.alpha <= bound);
    CHECK(w.load <= 10.0 * bound);  // the driver's load: a further solve with J^T (4.8e-9 measured at 1e-10)
  }
}

double load_torque(const LinkageDescription& d) {
  for (const LoadSpec& load : d.loads) {
    if (load.kind == LoadKind::torque) return load.torque;
  }
  return std::nan("");
}

Eigen::Vector2d load_force(const LinkageDescription& d) {
  for (const LoadSpec& load : d.loads) {
    if (load.kind == LoadKind::force) return load.force;
    if (load.kind == LoadKind::mass) return {0.0, -load.mass * d.gravity};
  }
  return {std::nan(""), std::nan("")};
}

}  // namespace

TEST_CASE("inverted-slider-crank.toml over a turn against its closed form: joints, rocker angle, driver torque",
          "[linkage-models][one-driver]") {
  const LinkageModel model = model_file("inverted-slider-crank");
  CHECK(gruebler_kutzbach(model.description()).mobility == 1);
  const cf::InvertedSliderCrank m = cf::inverted_slider_crank_of(model.description());
  const double torque = load_torque(model.description());  // on the rocker
  REQUIRE(torque == -20000.0);
  check_sweeps("inverted-slider-crank", 0.0, 359.0, 1.0, 360, [&](double t) {
    const cf::InvertedSliderCrankPose p = cf::inverted_slider_crank(m, t);
    // Virtual work: tau * 1 + T omega_rocker = 0.
    return Expected{{{"A", p.A}, {"C", p.C}}, {{"crank", p.crank}, {"rocker", p.rocker}}, -torque * p.rocker.omega};
  });
}

TEST_CASE("whitworth.toml over a turn against its closed form: joints, slot and rod angles, the cutting force's torque",
          "[linkage-models][one-driver]") {
  const LinkageModel model = model_file("whitworth");
  CHECK(gruebler_kutzbach(model.description()).mobility == 1);
  const cf::Whitworth m = cf::whitworth_of(model.description());
  const Eigen::Vector2d force = load_force(model.description());  // at the ram C
  REQUIRE(force.x() == 1500.0);
  // The cut resists the slow stroke: at crank 90 deg (inside -26.74 ... 206.74) the ram moves to -x.
  CHECK(force.dot(cf::whitworth(m, cf::pi / 2.0).C.v) < 0.0);
  check_sweeps("whitworth", 0.0, 359.0, 1.0, 360, [&](double t) {
    const cf::WhitworthPose p = cf::whitworth(m, t);
    // Virtual work: tau * 1 + F . C' = 0.
    return Expected{{{"A", p.A}, {"B", p.B}, {"C", p.C}}, {{"crank", p.crank}, {"slot", p.slot}, {"rod", p.rod}},
                    -force.dot(p.C.v)};
  });
}

TEST_CASE("hydraulic-boom.toml over the cylinder's stroke against its closed form: joints, boom angle, the cylinder's push",
          "[linkage-models][one-driver]") {
  const LinkageModel model = model_file("hydraulic-boom");
  CHECK(gruebler_kutzbach(model.description()).mobility == 1);
  CHECK(model.description().driver.kind == DriverKind::actuator);
  const cf::HydraulicBoom m = cf::hydraulic_boom_of(model.description());
  const Eigen::Vector2d weight = load_force(model.description());  // 500 kg at the tip T
  REQUIRE(weight.y() == Approx(-500.0 * 9.80665).epsilon(1e-15));
  check_sweeps("hydraulic-boom", 1.0, 2.2, 0.01, 121, [&](double s) {
    const cf::HydraulicBoomPose p = cf::hydraulic_boom(m, s);
    // The push from the boom's balance of moments about O (not virtual work).
    return Expected{{{"B", p.B}, {"T", p.T}}, {{"boom", p.boom}}, cf::cylinder_force(m, p, weight)};
  });
  // The push at the ends of the stroke, for the docs: 8.1 deg (s = 1.0) and 82.3 deg (s = 2.2).
  CHECK(cf::cylinder_force(m, cf::hydraulic_boom(m, 1.0), weight) > cf::cylinder_force(m, cf::hydraulic_boom(m, 2.2), weight));
}

TEST_CASE("watt-straight-line.toml over +-20 deg against its closed form: B, M, C, the coupler bar's and rockers' angles",
          "[linkage-models][one-driver]") {
  const LinkageModel model = model_file("watt-straight-line");
  CHECK(gruebler_kutzbach(model.description()).mobility == 1);
  const cf::WattLinkage m = cf::watt_linkage_of(model.description());
  CHECK(m.fraction == 0.5);
  REQUIRE(model.description().bodies.size() == 1);
  CHECK(model.description().bodies[0].collinear);
  check_sweeps("watt-straight-line", -20.0, 20.0, 0.5, 81, [&](double t) {
    const cf::WattPose p = cf::watt_linkage(m, t);
    return Expected{{{"B", p.B}, {"M", p.M}, {"C", p.C}},
                    {{"rocker-1", p.rocker_1}, {"coupler", p.coupler}, {"rocker-2", p.rocker_2}},
                    std::nan("")};
  });
}

TEST_CASE("The quick-returns' toggles and time ratios from --analyse against their closed forms",
          "[linkage-models][one-driver]") {
  struct Case {
    std::string name;
    cf::QuickReturn exact;
  };
  const Case cases[] = {
      {"inverted-slider-crank", cf::inverted_slider_crank_quick_return(cf::inverted_slider_crank_of(model_file("inverted-slider-crank").description()))},
      {"whitworth", cf::whitworth_quick_return(cf::whitworth_of(model_file("whitworth").description()))}};
  for (const Case& c : cases) {
    INFO(c.name);
    const LinkageModel model = model_file(c.name);
    const LinkageSolver solver(model, {});
    const CrankAnalysis analysis = analyse_crank_mechanism(solver);
    CHECK(analysis.crank_turns_fully);
    REQUIRE(analysis.output_toggles.size() == 2);
    for (const Toggle& toggle : analysis.output_toggles) {
      const double t = toggle.crank_deg * cf::pi / 180.0;
      const double off = std::min(std::abs(std::remainder(t - c.exact.toggle_1, 2.0 * cf::pi)),
                                  std::abs(std::remainder(t - c.exact.toggle_2, 2.0 * cf::pi)));
      CHECK(off * 180.0 / cf::pi <= 1e-6);  // issue 30: toggles to 1e-6 deg
    }
    CHECK(std::abs(analysis.time_ratio - c.exact.time_ratio) <= 1e-8 * c.exact.time_ratio);
  }
}
