// The new constraints on the fast path (linkage_fast_solver.hpp) against the teaching solvers, and
// their singular poses named, never a NaN:
//  - per pose, the fast full and sequential Newton give the generic solvers' status, iterations and
//    joints (to rounding), and the same velocities;
//  - a sweep on the fast path reports the generic sweep's poses;
//  - an actuator swept to zero length (its direction undefined) and a slot whose block passes
//    through the slot's pivot: J singular there, said so, every number finite.

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "constraint_mechanisms.hpp"
#include "numlab/mechanisms/linkage/linkage_fast_solver.hpp"
#include "numlab/mechanisms/linkage/linkage_statics.hpp"
#include "numlab/mechanisms/linkage/linkage_sweep.hpp"

using namespace numlab::mechanisms;
using namespace numlab::mechanisms::testing;
using numlab::Status;

namespace {

struct Case {
  std::string text;
  double from, to, step;  // user units
};

std::vector<Case> cases() {
  return {{InvertedSliderCrank{1.0, 0.3}.text(60.0), 60.0, 420.0, 7.0},
          {Boom{}.text(1.8), 1.2, 2.9, 0.05},
          {MotorFourBar{}.text(100.0), 100.0, 460.0, 6.0}};
}

LinkageSolverOptions options_for(const std::string& solver) {
  LinkageSolverOptions options{solver, "gepp", {}};
  options.newton.residual_tolerance = 1e-11;
  options.newton.max_iterations = 50;
  return options;
}

}  // namespace

TEST_CASE("The new constraints on the fast path: the teaching solvers' poses, counts and velocities", "[linkage][constraints][fast]") {
  for (const Case& c : cases()) {
    const LinkageModel model(parse_linkage_description(c.text, "f.toml"));
    for (const std::string kind : {"full", "sequential"}) {
      INFO(model.description().name << ", --solver " << kind);
      const LinkageSolver solver(model, options_for(kind));
      LinkageFastSolver fast(solver);
      const LinkageSweep poses = linkage_sweep(solver, c.from, c.to, c.step, [](const LinkagePose&) { return numlab::StepControl::proceed; });
      REQUIRE(poses.status == Status::converged);
      int compared = 0;
      for (std::size_t k = 0; k + 1 < poses.poses.size(); ++k) {
        const double t = model.driver_from_user(poses.poses[k + 1].driver);
        const LinkageSolution generic = solver.solve(t, poses.poses[k].q);
        Eigen::VectorXd q = poses.poses[k].q;
        const LinkageFastOutcome quick = fast.solve(t, q);
        INFO("to " << poses.poses[k + 1].driver);
        REQUIRE(generic.outcome.status == Status::converged);
        REQUIRE(quick.outcome.status == Status::converged);
        CHECK(quick.outcome.iterations == generic.outcome.iterations);
        const double size = solver.size();
        CHECK((q - generic.q).lpNorm<Eigen::Infinity>() <= 1e-9 * size);
        Eigen::VectorXd fast_velocity;
        REQUIRE(fast.velocity(t, q, fast_velocity));
        const Eigen::VectorXd velocity = linkage_velocity(model, t, q);
        CHECK((fast_velocity - velocity).lpNorm<Eigen::Infinity>() <= 1e-12 * (1.0 + velocity.lpNorm<Eigen::Infinity>()));
        ++compared;
      }
      CHECK(compared >= 30);
      // The whole sweep on the fast path (no observer) against the generic one.
      const LinkageSweep quick = linkage_sweep(solver, c.from, c.to, c.step);
      REQUIRE(quick.poses.size() == poses.poses.size());
      CHECK(quick.status == poses.status);
      for (std::size_t k = 0; k < quick.poses.size(); ++k) {
        CHECK((quick.poses[k].q - poses.poses[k].q).lpNorm<Eigen::Infinity>() <= 1e-9 * solver.size());
      }
    }
  }
}

TEST_CASE("An actuator swept to zero length: singular there, named, no NaN", "[linkage][constraints][singular]") {
  // |OG| = |OP| = 2: at length 0 the cylinder's two ends meet (P = G) and its direction is undefined.
  const Boom boom{1.0, 2.0, 2.0};
  const LinkageModel model(parse_linkage_description(boom.text(0.9, "\n[[load]]\njoint = \"T\"\nmass = 10.0\n"), "boom0.toml"));
  const LinkageSolver solver(model, LinkageSolverOptions{});
  const LinkageSweep sweep = linkage_sweep(solver, 0.9, 0.0, -0.15);
  REQUIRE(!sweep.poses.empty());
  LinkageStaticsSolver statics(model);
  for (const LinkagePose& pose : sweep.poses) {
    INFO("length " << pose.driver << ": " << numlab::to_string(pose.outcome.status));
    if (pose.outcome.status != Status::converged) continue;
    CHECK(pose.q.allFinite());
    const LinkageStatics& s = statics.solve(pose);
    CHECK(!std::isnan(s.driver));
    // Away from zero length, the push by moments (boom.at's closed form).
    if (pose.driver > 0.1) {
      CHECK(s.status == StaticsStatus::equilibrium);
      const Joints j = boom.at(pose.driver);
      const Eigen::Vector2d u = (j.at("P") - j.at("G")).normalized();
      CHECK(s.driver == Approx(10.0 * standard_gravity * j.at("T").x() / (j.at("P").x() * u.y() - j.at("P").y() * u.x())).epsilon(1e-8));
    }
  }
  // The last pose, at zero length: singular (J's actuator row vanishes), and said so.
  const LinkagePose& last = sweep.poses.back();
  CHECK(std::abs(last.driver) <= 1e-12);
  if (last.outcome.status == Status::converged) {
    CHECK(!(last.condition <= 1e5));  // kappa(J) above the sweep's threshold, or infinite
    CHECK(statics.solve(last).status == StaticsStatus::singular);
    CHECK(std::isinf(statics.solve(last).driver));
  }
  // At exactly zero length from P = G: the row has no direction; the solve stops, named.
  Eigen::MatrixXd J;
  Eigen::VectorXd at_zero = model.unknowns({{0, 0}, {2, 0}, {2, 0}, {3, 0}});
  model.jacobian(at_zero, 0.0, J);
  CHECK(J.allFinite());
  CHECK(J.row(3).norm() == 0.0);
}

TEST_CASE("A slot's block through the slot's pivot: the rocker's turn is undefined there, named", "[linkage][constraints][singular]") {
  // Crank 3 = |OB|: at crank 0 the block A reaches the rocker's pivot B, where the slot's line through
  // A and B has no direction of its own.
  const std::string text = R"([linkage]
name = "isc-through-pivot"
[ground]
O = [0.0, 0.0]
B = [3.0, 0.0]
[joints]
A = [1.5, 2.598]
C = [0.0, 5.0]
[[link]]
joints = ["O", "A"]
length = 3.0
[[link]]
joints = ["B", "C"]
length = 5.0
[[slider]]
joint = "A"
line = ["B", "C"]
[driver]
type = "crank"
pivot = "O"
joint = "A"
angle = 60.0
)";
  const LinkageModel model(parse_linkage_description(text, "isc3.toml"));
  const LinkageSolver solver(model, LinkageSolverOptions{});
  const LinkageSweep sweep = linkage_sweep(solver, 60.0, 0.0, -10.0);
  REQUIRE(sweep.poses.size() == 7);
  const LinkagePose& at_pivot = sweep.poses.back();
  INFO(numlab::to_string(at_pivot.outcome.status) << ", kappa " << at_pivot.condition);
  CHECK(at_pivot.q.allFinite());
  CHECK(!(at_pivot.condition <= 1e5));
  for (const LinkagePose& pose : sweep.poses) {
    if (pose.outcome.status == Status::converged) {
      CHECK(pose.q.allFinite());
      CHECK(!std::isnan(pose.condition));
    }
  }
}

TEST_CASE("The slotted link through a known joint is a closed-form block: analytic poses against the closed form",
          "[linkage][constraints][closed-form]") {
  // The inverted slider-crank's rocker C turns about B with the slot through A: one closed-form block
  // (BlockKind::slot_pivot), written with the slot's line either way round (B -> C or C -> B, the
  // offset's sign flipped with it), at three offsets and three scales.
  for (const double e : {0.0, 0.3, -0.4}) {
    for (const double k : {1e-3, 1.0, 1e3}) {
      for (const bool reversed : {false, true}) {
        INFO("offset " << e << ", scale " << k << (reversed ? ", line C -> B" : ""));
        const InvertedSliderCrank mechanism{k, e};
        std::string text = mechanism.text(60.0);
        if (reversed) {
          text.replace(text.find("line = [\"B\", \"C\"]"), 17, "line = [\"C\", \"B\"]");
          text.replace(text.find("offset = "), 9, "offset = -");
          const auto doubled = text.find("offset = --");
          if (doubled != std::string::npos) text.replace(doubled, 11, "offset = ");
        }
        const LinkageModel model(parse_linkage_description(text, "isc.toml"));
        LinkageSolverOptions options;
        options.solver = "analytic";
        const LinkageSolver solver(model, options);
        REQUIRE(solver.blocks().size() == 2);
        CHECK(solver.blocks()[1].kind == BlockKind::slot_pivot);
        const LinkageSweep sweep = linkage_sweep(solver, 60.0, 420.0, 7.5);
        REQUIRE(sweep.status == Status::converged);
        CHECK(sweep.branch_kept);
        for (const LinkagePose& pose : sweep.poses) {
          const Joints exact = mechanism.at(pose.driver * deg);
          const auto joints = model.positions(pose.q);
          const Eigen::Vector2d C = joints[static_cast<std::size_t>(model.description().joint_index("C"))];
          CHECK((C - exact.at("C")).norm() <= 1e-12 * 5 * k);  // closed form against closed form: rounding
        }
      }
    }
  }
}

TEST_CASE("The slotted link's closed form where no line through the pivot passes the block at the offset", "[linkage][constraints][closed-form]") {
  // Offset 2.5 and the block A on a crank of 1 about O, 3 from B: |BA| runs 2 ... 4, so where |BA| < 2.5
  // no slot line through B is 2.5 from A: the closed form refuses (cannot_assemble), never a NaN.
  const InvertedSliderCrank mechanism{1.0, 2.5};
  const LinkageModel model(parse_linkage_description(mechanism.text(90.0), "isc-far.toml"));
  LinkageSolverOptions options;
  options.solver = "analytic";
  const LinkageSolver solver(model, options);
  REQUIRE(solver.blocks()[1].kind == BlockKind::slot_pivot);
  const LinkageSolution inside = solver.closed_form(10.0 * deg, solver.reference());  // |BA| = 2.02 < 2.5
  CHECK(inside.outcome.status == Status::cannot_assemble);
  CHECK(inside.failed_block == 1);
  const LinkageSolution outside = solver.closed_form(100.0 * deg, solver.reference());  // |BA| = 3.3
  REQUIRE(outside.outcome.status == Status::converged);
  CHECK(outside.q.allFinite());
}
