// Issue 30's shipped models at the edges of scale: inverted-slider-crank, whitworth, hydraulic-boom,
// watt-straight-line and five-bar with every length times k = 1e-8, 1e-6, 1, 1e6, 1e8 (a mechanism
// in tens of nanometres ... thousands of kilometres; scaled_model.hpp rewrites the TOML text), swept
// and held against the same closed forms as test_one_driver_models and test_two_drivers:
//  - positions scale with k (to 1e-8 of the size, and within each pose's own bound), velocities and
//    accelerations as length over the driver's unit, angles and their rates do not change;
//  - every pose converges where it does at k = 1, the limits bisected to the same driver value (a
//    length driver's times k) on the same block, the same change points;
//  - toggles, classification and time ratios do not change (1e-6 deg, 1e-8 relative);
//  - torques scale as force x length, an actuator's force not at all (1e-7 of the load's scale);
//  - the fast path agrees with the teaching path, and --solver analytic with the closed form.

#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "model_files.hpp"
#include "numlab/linalg/matrix_file.hpp"
#include "numlab/mechanisms/closed_forms/from_description.hpp"
#include "numlab/mechanisms/linkage/crank_analysis.hpp"
#include "numlab/mechanisms/linkage/driver_path.hpp"
#include "numlab/mechanisms/linkage/link_motion.hpp"
#include "numlab/mechanisms/linkage/linkage_statics.hpp"
#include "numlab/mechanisms/linkage/linkage_sweep.hpp"
#include "scaled_model.hpp"

using namespace numlab::mechanisms;
using namespace numlab::mechanisms::testing;
namespace cf = numlab::mechanisms::closed_forms;
using numlab::Status;

namespace {

const double scales[] = {1e-8, 1e-6, 1.0, 1e6, 1e8};

LinkageDescription scaled_description(const std::string& name, double k, const std::string& extra = "") {
  const std::string text = numlab::linalg::read_text_file(model_path(name)) + extra;
  return parse_linkage_description(scaled_model_text(text, k), name + ".toml");
}

// A closed form's pose: joints and link angles by name, the driver's load (NaN: no loads).
struct Expected {
  std::map<std::string, cf::PointMotion> joints;
  std::map<std::string, cf::AngleMotion> links;
  double driver_load = std::nan("");
};
using ClosedForm = std::function<Expected(const LinkageDescription&, double driver)>;

// A shipped one-driver model, the sweep the one-driver tests use (user units at k = 1; a length
// driver's range is scaled with the model) and its closed form.
struct Case {
  std::string name;
  double start, stop, step;
  ClosedForm closed_form;
};

Eigen::Vector2d load_force(const LinkageDescription& d) {
  for (const LoadSpec& load : d.loads) {
    if (load.kind == LoadKind::force) return load.force;
    if (load.kind == LoadKind::mass) return {0.0, -load.mass * d.gravity};
  }
  return {std::nan(""), std::nan("")};
}

double load_torque(const LinkageDescription& d) {
  for (const LoadSpec& load : d.loads) {
    if (load.kind == LoadKind::torque) return load.torque;
  }
  return std::nan("");
}

const std::vector<Case>& one_driver_cases() {
  static const std::vector<Case> cases = {
      {"inverted-slider-crank", 0.0, 359.0, 1.0,
       [](const LinkageDescription& d, double t) {
         const cf::InvertedSliderCrankPose p = cf::inverted_slider_crank(cf::inverted_slider_crank_of(d), t);
         return Expected{{{"A", p.A}, {"C", p.C}}, {{"crank", p.crank}, {"rocker", p.rocker}}, -load_torque(d) * p.rocker.omega};
       }},
      {"whitworth", 0.0, 359.0, 1.0,
       [](const LinkageDescription& d, double t) {
         const cf::WhitworthPose p = cf::whitworth(cf::whitworth_of(d), t);
         return Expected{{{"A", p.A}, {"B", p.B}, {"C", p.C}}, {{"crank", p.crank}, {"slot", p.slot}, {"rod", p.rod}},
                         -load_force(d).dot(p.C.v)};
       }},
      {"hydraulic-boom", 1.0, 2.2, 0.01,
       [](const LinkageDescription& d, double s) {
         const cf::HydraulicBoom m = cf::hydraulic_boom_of(d);
         const cf::HydraulicBoomPose p = cf::hydraulic_boom(m, s);
         return Expected{{{"B", p.B}, {"T", p.T}}, {{"boom", p.boom}}, cf::cylinder_force(m, p, load_force(d))};
       }},
      {"watt-straight-line", -20.0, 20.0, 0.5,
       [](const LinkageDescription& d, double t) {
         const cf::WattPose p = cf::watt_linkage(cf::watt_linkage_of(d), t);
         return Expected{{{"B", p.B}, {"M", p.M}, {"C", p.C}},
                         {{"rocker-1", p.rocker_1}, {"coupler", p.coupler}, {"rocker-2", p.rocker_2}},
                         std::nan("")};
       }},
  };
  return cases;
}

LinkageSolverOptions options_for(const std::string& solver) {
  LinkageSolverOptions options;
  options.solver = solver;
  options.newton.residual_tolerance = 1e-10;  // numlab mechanism's default, times the size
  return options;
}

LinkageSweep sweep_of(const LinkageSolver& solver, double start, double stop, double step, bool teaching) {
  if (!teaching) return linkage_sweep(solver, start, stop, step);  // no observer: the fast path
  return linkage_sweep(solver, start, stop, step, [](const LinkagePose&) { return numlab::StepControl::proceed; });
}

// The worst differences from the closed form over a sweep, each in the model's own units: lengths
// over the size, a rate per driver unit u (1 for an angle, the size for a length) made dimensionless.
struct Worst {
  double position = 0.0, beyond_bound = 0.0, velocity = 0.0, acceleration = 0.0;
  double angle = 0.0, omega = 0.0, alpha = 0.0, load = 0.0;
};

Worst against_closed_form(const LinkageModel& model, const LinkageSweep& sweep, const ClosedForm& closed_form, double size) {
  const LinkageDescription& d = model.description();
  const double u = d.driver.angle() ? 1.0 : size;
  const auto lines = link_lines(d);
  LinkageStaticsSolver statics(model);
  Worst worst;
  double load_scale = 0.0;
  std::vector<double> load_errors;
  for (const LinkagePose& pose : sweep.poses) {
    INFO("pose at " << pose.driver);
    REQUIRE(pose.outcome.status == Status::converged);
    const Expected e = closed_form(d, model.driver_from_user(pose.driver));
    const auto joints = joint_motions(model, pose.q, pose.velocity, pose.acceleration);
    for (const auto& [name, motion] : e.joints) {
      const auto& got = joints[static_cast<std::size_t>(d.joint_index(name))];
      REQUIRE(std::isfinite(got.a.norm()));
      worst.position = std::max(worst.position, (got.p - motion.p).norm() / size);
      worst.beyond_bound = std::max(worst.beyond_bound, (got.p - motion.p).norm() / pose.closed_form_bound);
      worst.velocity = std::max(worst.velocity, (got.v - motion.v).norm() * u / size);
      worst.acceleration = std::max(worst.acceleration, (got.a - motion.a).norm() * u * u / size);
    }
    int found = 0;
    for (const LinkLine& line : lines) {
      const auto it = e.links.find(line.name);
      if (it == e.links.end()) continue;
      ++found;
      const AngularMotion got = angular_motion(joints[static_cast<std::size_t>(line.from)], joints[static_cast<std::size_t>(line.to)]);
      worst.angle = std::max(worst.angle, std::abs(std::remainder(got.angle - it->second.angle, 2.0 * cf::pi)));
      worst.omega = std::max(worst.omega, std::abs(got.omega - it->second.omega) * u / (1.0 + std::abs(it->second.omega) * u));
      worst.alpha = std::max(worst.alpha, std::abs(got.alpha - it->second.alpha) * u * u / (1.0 + std::abs(it->second.alpha) * u * u));
    }
    CHECK(found == static_cast<int>(e.links.size()));
    if (!std::isnan(e.driver_load)) {
      const LinkageStatics& s = statics.solve(pose);
      REQUIRE(s.status == StaticsStatus::equilibrium);
      load_scale = std::max(load_scale, std::abs(e.driver_load));
      load_errors.push_back(std::abs(s.driver - e.driver_load));
    }
  }
  for (const double error : load_errors) worst.load = std::max(worst.load, error / load_scale);
  return worst;
}

// What must not change with k: per pose the status, the driver (a length driver's over k), the
// angles; the positions over k within `distance` (of the size at k = 1).
void check_like_unit_scale(const LinkageSweep& at_k, const LinkageSweep& at_1, double k, bool length_driver, double size_1) {
  REQUIRE(at_k.poses.size() == at_1.poses.size());
  CHECK(at_k.status == at_1.status);
  CHECK(at_k.branch_kept == at_1.branch_kept);
  CHECK(at_k.change_points.size() == at_1.change_points.size());
  CHECK(at_k.crossings.size() == at_1.crossings.size());
  if (!length_driver) CHECK(at_k.change_points == at_1.change_points);
  const double driver_unit = length_driver ? k : 1.0;
  REQUIRE(at_k.limits.size() == at_1.limits.size());
  for (std::size_t i = 0; i < at_k.limits.size(); ++i) {
    const LinkageLimit &a = at_k.limits[i], &b = at_1.limits[i];
    CHECK(a.block == b.block);
    CHECK(a.upper == b.upper);
    CHECK(a.assembles_beyond == b.assembles_beyond);
    CHECK(a.bracket / driver_unit <= 2.0 * b.bracket + 1e-12);
    CHECK(std::abs(a.driver / driver_unit - b.driver) <= a.bracket / driver_unit + b.bracket);
  }
  for (std::size_t p = 0; p < at_k.poses.size(); ++p) {
    const LinkagePose &a = at_k.poses[p], &b = at_1.poses[p];
    INFO("pose " << p << " at " << b.driver);
    CHECK(a.driver / driver_unit == Approx(b.driver).epsilon(1e-12).margin(1e-12));
    REQUIRE(a.outcome.status == b.outcome.status);
    CHECK(a.failed_block == b.failed_block);
    if (b.outcome.status != Status::converged) continue;
    CHECK(a.signature == b.signature);
    CHECK((a.q / k - b.q).lpNorm<Eigen::Infinity>() <= 2e-8 * size_1);
  }
}

bool print_errors() { return std::getenv("NUMLAB_PRINT_ERRORS") != nullptr; }

}  // namespace

TEST_CASE("issue 30's one-driver models at 1e-8 ... 1e8 against their closed forms, teaching and fast paths",
          "[linkage-models][scales]") {
  for (const Case& c : one_driver_cases()) {
    const LinkageModel unit_model(scaled_description(c.name, 1.0));
    const LinkageSolver unit_solver(unit_model, options_for("full"));
    const bool length_driver = !unit_model.description().driver.angle();
    const LinkageSweep unit_sweep = sweep_of(unit_solver, c.start, c.stop, c.step, true);
    const double unit_size = unit_solver.size();  // its longest link or body edge
    bool analytic_at_1 = true;
    try {
      (void)LinkageSolver(unit_model, options_for("analytic"));
    } catch (const std::invalid_argument&) {
      analytic_at_1 = false;
    }
    for (const double k : scales) {
      const LinkageModel model(scaled_description(c.name, k));
      const double size = LinkageSolver(model, options_for("full")).size();
      CHECK(size == Approx(k * unit_size).epsilon(1e-15));
      const double driver_unit = length_driver ? k : 1.0;
      std::vector<std::string> solvers = {"full", "sequential"};
      bool analytic = true;
      try {
        (void)LinkageSolver(model, options_for("analytic"));
        solvers.push_back("analytic");
      } catch (const std::invalid_argument&) {
        analytic = false;
      }
      CHECK(analytic == analytic_at_1);  // the blocks do not depend on the size
      for (const std::string& kind : solvers) {
        const LinkageSolver solver(model, options_for(kind));
        for (const bool teaching : {true, false}) {
          INFO(c.name << " x " << k << ", --solver " << kind << (teaching ? ", teaching path" : ", fast path"));
          const LinkageSweep sweep = sweep_of(solver, c.start * driver_unit, c.stop * driver_unit, c.step * driver_unit, teaching);
          REQUIRE(sweep.status == Status::converged);
          CHECK(sweep.branch_kept);
          CHECK(sweep.closed_form_verified);
          const Worst w = against_closed_form(model, sweep, c.closed_form, size);
          if (print_errors() && kind == "full") {
            std::printf("%s x %g %s: position %.2e (bound x %.2f) velocity %.2e acceleration %.2e angle %.2e omega %.2e alpha %.2e load %.2e\n",
                        c.name.c_str(), k, teaching ? "teaching" : "fast", w.position, w.beyond_bound, w.velocity, w.acceleration,
                        w.angle, w.omega, w.alpha, w.load);
          }
          // The bounds of test_one_driver_models at Newton's default tolerance (1e-10 x size).
          CHECK(w.beyond_bound <= 1.0);
          CHECK(w.position <= 1e-8);
          CHECK(w.velocity <= 1e-8);
          CHECK(w.acceleration <= 1e-8);
          CHECK(w.angle <= 1e-8);
          CHECK(w.omega <= 1e-8);
          CHECK(w.alpha <= 1e-8);
          CHECK(w.load <= 1e-7);
          check_like_unit_scale(sweep, unit_sweep, k, length_driver, unit_size);
        }
      }
    }
  }
}

TEST_CASE("issue 30's one-driver models at 1e-8 ... 1e8: the driver's load scales as force x length, or not at all",
          "[linkage-models][scales]") {
  for (const Case& c : one_driver_cases()) {
    if (c.name == "watt-straight-line") continue;  // no loads
    const LinkageModel unit_model(scaled_description(c.name, 1.0));
    const bool length_driver = !unit_model.description().driver.angle();
    const LinkageSolver unit_solver(unit_model, options_for("full"));
    const LinkageSweep unit_sweep = sweep_of(unit_solver, c.start, c.stop, c.step * 10.0, false);
    LinkageStaticsSolver unit_statics(unit_model);
    std::vector<double> unit_loads;
    double load_scale = 0.0;
    for (const LinkagePose& pose : unit_sweep.poses) {
      unit_loads.push_back(unit_statics.solve(pose).driver);
      load_scale = std::max(load_scale, std::abs(unit_loads.back()));
    }
    REQUIRE(load_scale > 0.0);
    for (const double k : scales) {
      INFO(c.name << " x " << k);
      const LinkageModel model(scaled_description(c.name, k));
      const LinkageSolver solver(model, options_for("full"));
      const double driver_unit = length_driver ? k : 1.0;
      const LinkageSweep sweep = sweep_of(solver, c.start * driver_unit, c.stop * driver_unit, c.step * 10.0 * driver_unit, false);
      REQUIRE(sweep.poses.size() == unit_loads.size());
      LinkageStaticsSolver statics(model);
      // A crank's torque is force x length: times k; an actuator's force stays.
      const double load_unit = length_driver ? 1.0 : k;
      for (std::size_t p = 0; p < sweep.poses.size(); ++p) {
        const LinkageStatics& s = statics.solve(sweep.poses[p]);
        REQUIRE(s.status == StaticsStatus::equilibrium);
        CHECK(std::abs(s.driver / load_unit - unit_loads[p]) <= 1e-7 * load_scale);
      }
    }
  }
}

TEST_CASE("the quick-returns' toggles and time ratios, and every crank model's classification, at 1e-8 ... 1e8",
          "[linkage-models][scales]") {
  for (const std::string name : {"inverted-slider-crank", "whitworth", "watt-straight-line"}) {
    const LinkageModel unit_model(scaled_description(name, 1.0));
    const CrankAnalysis unit = analyse_crank_mechanism(LinkageSolver(unit_model, options_for("full")));
    for (const double k : scales) {
      INFO(name << " x " << k);
      const LinkageModel model(scaled_description(name, k));
      const CrankAnalysis a = analyse_crank_mechanism(LinkageSolver(model, options_for("full")));
      CHECK(a.kind == unit.kind);
      CHECK(a.not_analysed == unit.not_analysed);
      CHECK(a.classification == unit.classification);
      CHECK(a.grashof == unit.grashof);
      CHECK(a.crank_turns_fully == unit.crank_turns_fully);
      CHECK(a.crank == Approx(k * unit.crank).epsilon(1e-14));
      REQUIRE(a.driver_toggles.size() == unit.driver_toggles.size());
      REQUIRE(a.output_toggles.size() == unit.output_toggles.size());
      for (std::size_t i = 0; i < a.output_toggles.size(); ++i) {
        CHECK(std::abs(std::remainder(a.output_toggles[i].crank_deg - unit.output_toggles[i].crank_deg, 360.0)) <= 1e-6);
        CHECK(a.output_toggles[i].what == unit.output_toggles[i].what);
      }
      for (std::size_t i = 0; i < a.driver_toggles.size(); ++i) {
        CHECK(std::abs(std::remainder(a.driver_toggles[i].crank_deg - unit.driver_toggles[i].crank_deg, 360.0)) <= 1e-6);
      }
      if (std::isnan(unit.time_ratio)) {
        CHECK(std::isnan(a.time_ratio));
      } else {
        CHECK(std::abs(a.time_ratio - unit.time_ratio) <= 1e-8 * unit.time_ratio);
      }
      // The quick-returns against their closed forms, as at k = 1.
      if (name == "watt-straight-line") continue;
      const cf::QuickReturn exact = name == "whitworth" ? cf::whitworth_quick_return(cf::whitworth_of(model.description()))
                                                        : cf::inverted_slider_crank_quick_return(cf::inverted_slider_crank_of(model.description()));
      REQUIRE(a.output_toggles.size() == 2);
      for (const Toggle& toggle : a.output_toggles) {
        const double t = toggle.crank_deg * cf::pi / 180.0;
        const double off = std::min(std::abs(std::remainder(t - exact.toggle_1, 2.0 * cf::pi)),
                                    std::abs(std::remainder(t - exact.toggle_2, 2.0 * cf::pi)));
        CHECK(off * 180.0 / cf::pi <= 1e-6);
      }
      CHECK(std::abs(a.time_ratio - exact.time_ratio) <= 1e-8 * exact.time_ratio);
    }
  }
}

TEST_CASE("past the ends at 1e-8 ... 1e8: watt-straight-line's folds and hydraulic-boom's stroke reported as at 1",
          "[linkage-models][scales]") {
  struct Range {
    std::string name;
    double start, stop, step;
  };
  // Watt's rocker folds at -64.59 and +64.59 deg (block 2, C, cannot close); the boom's stroke
  // ends where P, O and B are collinear, |PB| = |OB| -/+ |OP| = 1.5 -/+ sqrt(0.9^2 + 0.6^2) m =
  // 0.418 and 2.582 m: a fold each, a limit, never a branch left (before 23dcc77 a
  // sub-step next to 2.582 met the twin branch and the sweep reported "it left its branch").
  const Range ranges[] = {{"watt-straight-line", 0.0, 120.0, 5.0}, {"watt-straight-line", 0.0, -120.0, -5.0},
                          {"hydraulic-boom", 1.0, 2.7, 0.05}, {"hydraulic-boom", 2.2, 0.3, -0.05}};
  for (const Range& r : ranges) {
    const LinkageModel unit_model(scaled_description(r.name, 1.0));
    const bool length_driver = !unit_model.description().driver.angle();
    const LinkageSolver unit_solver(unit_model, options_for("full"));
    const LinkageSweep unit_sweep = sweep_of(unit_solver, r.start, r.stop, r.step, true);
    CHECK(unit_sweep.status != Status::converged);
    CHECK(unit_sweep.limits.size() + unit_sweep.jumps.size() > 0);
    for (const double k : scales) {
      const double driver_unit = length_driver ? k : 1.0;
      for (const bool teaching : {true, false}) {
        INFO(r.name << " x " << k << " from " << r.start << " to " << r.stop << (teaching ? ", teaching path" : ", fast path"));
        const LinkageModel model(scaled_description(r.name, k));
        const LinkageSolver solver(model, options_for("full"));
        const LinkageSweep sweep = sweep_of(solver, r.start * driver_unit, r.stop * driver_unit, r.step * driver_unit, teaching);
        if (print_errors()) {
          for (const LinkageLimit& limit : sweep.limits) {
            std::printf("%s x %g: limit at %.9g (/unit %.9g), bracket %.2g, block %d\n", r.name.c_str(), k, limit.driver,
                        limit.driver / driver_unit, limit.bracket, limit.block);
          }
        }
        check_like_unit_scale(sweep, unit_sweep, k, length_driver, unit_solver.size());
        CHECK(sweep.jumps.empty());
        REQUIRE(sweep.limits.size() == 1);
        CHECK_FALSE(sweep.limits[0].assembles_beyond);
        if (r.name == "hydraulic-boom") {
          const double end = (r.step > 0.0 ? 1.5 + std::sqrt(1.17) : 1.5 - std::sqrt(1.17)) * k;
          CHECK(std::abs(sweep.limits[0].driver - end) <= sweep.limits[0].bracket);
        }
        // A pose that failed shows its residual at its own driver value, never a sub-step's.
        for (const LinkagePose& pose : sweep.poses) {
          if (pose.outcome.status != Status::converged) CHECK(pose.outcome.residual_norm > 1e-6 * k);
        }
      }
    }
  }
}

namespace {

// P of the shipped five-bar scaled by s, cranks at t1, t2 (radians): the upper intersection of the
// circles of radius 4 s about A and D (as in test_two_drivers).
Eigen::Vector2d five_bar_pen(double t1, double t2, double s) {
  const Eigen::Vector2d A = 2.0 * s * Eigen::Vector2d(std::cos(t1), std::sin(t1));
  const Eigen::Vector2d D = Eigen::Vector2d(4.0 * s, 0.0) + 2.0 * s * Eigen::Vector2d(std::cos(t2), std::sin(t2));
  const Eigen::Vector2d half = (D - A) / 2.0;
  const double height = std::sqrt(16.0 * s * s - half.squaredNorm());
  return A + half + height * Eigen::Vector2d(-half.y(), half.x()) / half.norm();
}

}  // namespace

TEST_CASE("five-bar at 1e-8 ... 1e8: a sweep, a --drivers path through a singular pose, both driver torques",
          "[two-drivers][scales]") {
  const std::string force = "\n[[load]]\njoint = \"P\"\nforce = [3.0, -10.0]\n";
  const Eigen::Vector2d F(3.0, -10.0);
  const LinkageModel unit_model(scaled_description("five-bar", 1.0, force));
  const LinkageSolver unit_solver(unit_model, options_for("full"));
  const LinkageSweep unit_sweep = sweep_of(unit_solver, 40.0, 140.0, 5.0, true);
  const double t2 = 90.0 * deg;
  // A path through a singular pose: from 70, 110 to -10, 190 the cranks pass t1 = 0, t2 = 180, where
  // A and D coincide and P's two circles are one (at -10, 190 they are 0.06 apart). Full and
  // sequential Newton call that row singular; analytic solves it and reports the branch changed at
  // the next row. Each solver's rows at k = 1:
  const auto path = parse_driver_path("a,b\n90,90\n70,110\n-10,190\n120,60\n", "p.csv");
  std::map<std::string, LinkageSweep> unit_walks;
  for (const std::string kind : {"full", "sequential", "analytic"}) {
    LinkageModel model(scaled_description("five-bar", 1.0, force));
    const LinkageSolver solver(model, options_for(kind));
    unit_walks[kind] = solve_driver_path(model, solver, path);
  }
  for (const double k : scales) {
    for (const std::string kind : {"full", "sequential", "analytic"}) {
      for (const bool teaching : {true, false}) {
        INFO("five-bar x " << k << ", --solver " << kind << (teaching ? ", teaching path" : ", fast path"));
        LinkageModel model(scaled_description("five-bar", k, force));
        const LinkageSolver solver(model, options_for(kind));
        const LinkageSweep sweep = sweep_of(solver, 40.0, 140.0, 5.0, teaching);
        REQUIRE(sweep.status == Status::converged);
        REQUIRE(sweep.poses.size() == 21);
        check_like_unit_scale(sweep, unit_sweep, k, false, 4.0);
        const int column = model.column_of(model.description().joint_index("P"));
        const double h = 1e-4;
        for (const LinkagePose& pose : sweep.poses) {
          const double t1 = pose.driver * deg;
          const Eigen::Vector2d P = joint_at(model, pose.q, "P");
          CHECK((P - five_bar_pen(t1, t2, k)).norm() <= 1e-9 * 4.0 * k);
          const Eigen::Vector2d v = pose.velocity.segment<2>(column);
          const Eigen::Vector2d v_fd = (five_bar_pen(t1 + h, t2, k) - five_bar_pen(t1 - h, t2, k)) / (2 * h);
          CHECK((v - v_fd).norm() <= 1e-7 * (4.0 * k + v.norm()));
        }
        // The path at every scale as at 1, row by row, whatever each solver makes of its singular row.
        const LinkageSweep walked = solve_driver_path(model, solver, path);
        const LinkageSweep& unit_walk = unit_walks.at(kind);
        REQUIRE(walked.poses.size() == path.size());
        if (kind != "analytic") CHECK(walked.status != Status::converged);  // the singular row
        CHECK(walked.status == unit_walk.status);
        CHECK(walked.branch_kept == unit_walk.branch_kept);
        for (std::size_t row = 0; row < path.size(); ++row) {
          INFO("path row " << row);
          REQUIRE(walked.poses[row].outcome.status == unit_walk.poses[row].outcome.status);
          if (unit_walk.poses[row].outcome.status != Status::converged) continue;
          CHECK((walked.poses[row].q / k - unit_walk.poses[row].q).lpNorm<Eigen::Infinity>() <= 1e-9 * 4.0);
        }
        // The rows before the singular one against the closed form, and their driver torques.
        LinkageStaticsSolver statics(model);
        for (const std::size_t row : {0u, 1u}) {
          const LinkagePose& pose = walked.poses[row];
          REQUIRE(pose.outcome.status == Status::converged);
          const double a = pose.driver * deg, b = pose.second_driver * deg;
          CHECK((joint_at(model, pose.q, "P") - five_bar_pen(a, b, k)).norm() <= 1e-9 * 4.0 * k);
          // Both torques by virtual work, tau_i = -F . dP/dt_i: force x length, times k.
          const LinkageStatics& result = statics.solve(pose);
          REQUIRE(result.status == StaticsStatus::equilibrium);
          const double e = 1e-5;
          const Eigen::Vector2d dP1 = (five_bar_pen(a + e, b, k) - five_bar_pen(a - e, b, k)) / (2 * e);
          const Eigen::Vector2d dP2 = (five_bar_pen(a, b + e, k) - five_bar_pen(a, b - e, k)) / (2 * e);
          const double scale = F.norm() * 4.0 * k;
          CHECK(std::abs(result.driver - (-F.dot(dP1))) <= 1e-7 * scale);
          CHECK(std::abs(result.second_driver - (-F.dot(dP2))) <= 1e-7 * scale);
        }
      }
    }
  }
}
