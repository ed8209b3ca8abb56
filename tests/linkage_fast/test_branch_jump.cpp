// A real branch jump, detected and reported, next to a real change point that is not one.
//
// Mustang's loop 4 is a kite: P11 is placed by |P10 P11| = 4/3 and |P9 P11| = 1 while P8 sits at
// |P10 P8| = 4/3 and |P9 P8| = 1. Where P8, P9 and P10 line up (43.15 deg) the two circles that
// place P11 touch: a change point, and the sweep goes on smoothly on the other side.
//
// Shorten |P10 P11| by delta = 1e-4 and the circles never touch: |P10 P9| >= |P10 P8| - |P8 P9| =
// 1/3 (triangle inequality), so the dyad's margin |P10 P9| - (|P9 P11| - |P10 P11|) stays >= delta
// at every crank angle. Its two solutions come within about 2 sqrt(2 r delta) of each other near
// 43.15 deg but never meet; a sweep 1 degree at a time follows its prediction straight past the
// near-meeting onto the other solution. That is a jump, and it must be reported as one (FLIPPED,
// exit 1), by the generic solvers and by the fast path alike.
#include <catch2/catch.hpp>

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "model_files.hpp"
#include "numlab/mechanisms/linkage/linkage_sweep.hpp"
#include "run_numlab.hpp"

using namespace numlab::mechanisms;
using namespace numlab::mechanisms::testing;
using numlab::Status;

namespace {

constexpr double delta = 1e-4;

// mustang.toml with |P10 P11| shortened by delta.
std::string near_kite_text() {
  std::string text = numlab::test::read_all(model_path("mustang"));
  const std::string link = "joints = [\"P10\", \"P11\"]\nlength = 1.3333333333333333";
  const std::size_t at = text.find(link);
  if (at == std::string::npos) throw std::runtime_error("mustang.toml no longer states the link P10-P11 as expected");
  text.replace(at, link.size(), fmt::format("joints = [\"P10\", \"P11\"]\nlength = {:.17g}", 4.0 / 3.0 - delta));
  return text;
}

LinkageModel near_kite() { return LinkageModel(parse_linkage_description(near_kite_text(), "near-kite.toml")); }

// The index of the dyad block that places P11.
std::size_t p11_block(const LinkageSolver& solver) {
  const int p11 = solver.model().description().joint_index("P11");
  for (std::size_t b = 0; b < solver.blocks().size(); ++b) {
    if (solver.blocks()[b].joints.size() == 1 && solver.blocks()[b].joints[0] == p11) return b;
  }
  throw std::runtime_error("no block places P11");
}

}  // namespace

TEST_CASE("a sweep past a near-meeting of a dyad's two solutions reports the jump to the other branch",
          "[linkage-fast][branch]") {
  const LinkageModel model = near_kite();
  for (const std::string kind : {"full", "sequential", "analytic"}) {
    for (const bool generic : {true, false}) {
      INFO("--solver " << kind << (generic ? ", generic path" : ", fast path"));
      const LinkageSolver solver(model, {kind, "gepp", {}});
      const std::size_t block = p11_block(solver);
      const LinkageSweep sweep = generic ? linkage_sweep(solver, 30.0, 55.0, 1.0, [](const LinkagePose&) {})
                                         : linkage_sweep(solver, 30.0, 55.0, 1.0);
      // Every pose assembles: no limit is passed, the dyad's margin never reaches zero.
      REQUIRE(sweep.status == Status::converged);
      CHECK(sweep.limits.empty());
      CHECK_FALSE(sweep.branch_kept);
      CHECK(sweep.change_points.empty());
      REQUIRE(sweep.flips.size() == 1);
      CHECK(sweep.flips[0].find("block " + std::to_string(block + 1) + " (P11 from") != std::string::npos);
      CHECK(sweep.flips[0].find("jumps to the other branch between 43 and 44") != std::string::npos);
      // The jump itself: P11's side changes between the poses at 43 and 44 degrees...
      const LinkagePose& before = sweep.poses[13];
      const LinkagePose& after = sweep.poses[14];
      REQUIRE(before.driver == 43.0);
      CHECK(before.signature[block] != after.signature[block]);
      CHECK(before.branch_kept);
      CHECK_FALSE(after.branch_kept);
      // ...while the margin between them (read from the closed form, 0.001 degree apart) stays at or
      // above delta, as the triangle inequality says: the two solutions never meet.
      double smallest = std::numeric_limits<double>::infinity();
      Eigen::VectorXd q = before.q;
      for (int i = 0; i <= 1000; ++i) {
        const double t = model.driver_from_user(43.0 + 0.001 * i);
        const LinkageSolution closed = solver.closed_form(t, q);
        REQUIRE(closed.failed_block < 0);
        q = closed.q;
        smallest = std::min(smallest, solver.dyad_margins(q)[block]);
      }
      CHECK(smallest >= delta * (1.0 - 1e-6));
      CHECK(smallest <= 1.01 * delta);  // and it does come that close (near 43.15 degrees)
    }
  }
}

TEST_CASE("the kite's genuine change point (Mustang at 43.15 deg) is still not a jump", "[linkage-fast][branch]") {
  const LinkageModel model = model_file("mustang");
  for (const std::string kind : {"full", "sequential", "analytic"}) {
    for (const bool generic : {true, false}) {
      INFO("--solver " << kind << (generic ? ", generic path" : ", fast path"));
      const LinkageSolver solver(model, {kind, "gepp", {}});
      const LinkageSweep sweep = generic ? linkage_sweep(solver, 30.0, 55.0, 1.0, [](const LinkagePose&) {})
                                         : linkage_sweep(solver, 30.0, 55.0, 1.0);
      REQUIRE(sweep.status == Status::converged);
      CHECK(sweep.branch_kept);
      CHECK(sweep.flips.empty());
      REQUIRE(sweep.change_points.size() == 1);
      CHECK(sweep.change_points[0].find("two branches cross at crank 43.1") != std::string::npos);
    }
  }
}

TEST_CASE("numlab mechanism reports the jump: FLIPPED, exit 1", "[linkage-fast][branch][cli]") {
  const std::string file = numlab::test::temporary_file("near-kite.toml", near_kite_text());
  for (const std::string kind : {"full", "sequential", "analytic"}) {
    INFO("--solver " << kind);
    const auto run = numlab::test::run_numlab("mechanism " + file + " --sweep 30:55:1 --solver " + kind);
    CHECK(run.exit_code == 1);
    CHECK(run.out.find("FLIPPED") != std::string::npos);
    CHECK(run.out.find("jumps to the other branch between 43 and 44") != std::string::npos);
    const auto kite = numlab::test::run_numlab("mechanism " + model_path("mustang") + " --sweep 30:55:1 --solver " + kind);
    CHECK(kite.exit_code == 0);
    CHECK(kite.out.find("two branches cross at crank 43.1") != std::string::npos);
  }
}
