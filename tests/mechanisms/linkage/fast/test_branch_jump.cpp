// A near-meeting of a dyad's two solutions, followed without a jump, next to a real crossing.
//
// Mustang's loop 4 is a kite: P11 is placed by |P10 P11| = 4/3 and |P9 P11| = 1 while P8 sits at
// |P10 P8| = 4/3 and |P9 P8| = 1. Where P8, P9 and P10 line up (43.15 deg) the two circles that
// place P11 touch: a crossing, and the sweep goes on along the smooth branch, on the other side.
//
// Shorten |P10 P11| by delta = 1e-4 and the circles never touch: |P10 P9| >= |P10 P8| - |P8 P9| =
// 1/3 (triangle inequality), so the dyad's margin |P10 P9| - (|P9 P11| - |P10 P11|) stays >= delta
// at every crank angle. Its two solutions come within about 2 sqrt(2 r delta) of each other near
// 43.15 deg but never meet, so each is a branch of its own that keeps its side: the prediction
// alone would step across to the other one (the sweep did, before its fifth step kept each dyad's
// side unless its margin touches zero between two poses). It must keep the reference's side at
// every pose, by the generic solvers and by the fast path alike.
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

TEST_CASE("a sweep past a near-meeting of a dyad's two solutions keeps its branch: no jump, no crossing",
          "[linkage-fast][branch]") {
  const LinkageModel model = near_kite();
  for (const std::string kind : {"full", "sequential", "analytic"}) {
    for (const bool generic : {true, false}) {
      INFO("--solver " << kind << (generic ? ", generic path" : ", fast path"));
      const LinkageSolver solver(model, {kind, "gepp", {}});
      const std::size_t block = p11_block(solver);
      const LinkageSweep sweep = generic ? linkage_sweep(solver, 30.0, 55.0, 1.0, [](const LinkagePose&) { return numlab::StepControl::proceed; })
                                         : linkage_sweep(solver, 30.0, 55.0, 1.0);
      REQUIRE(sweep.status == Status::converged);
      CHECK(sweep.limits.empty());
      CHECK(sweep.branch_kept);
      CHECK(sweep.flips.empty());
      CHECK(sweep.jumps.empty());
      CHECK(sweep.crossings.empty());
      // P11 on the reference's side at every pose, and the margin between the poses at 43 and 44
      // degrees (read from the closed form, 0.001 degree apart) at or above delta: it never meets.
      for (const LinkagePose& pose : sweep.poses) {
        INFO("pose " << pose.driver);
        CHECK(pose.signature[block] == solver.reference_signature()[block]);
      }
      double smallest = std::numeric_limits<double>::infinity();
      Eigen::VectorXd q = sweep.poses[13].q;
      REQUIRE(sweep.poses[13].driver == 43.0);
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
      const LinkageSweep sweep = generic ? linkage_sweep(solver, 30.0, 55.0, 1.0, [](const LinkagePose&) { return numlab::StepControl::proceed; })
                                         : linkage_sweep(solver, 30.0, 55.0, 1.0);
      REQUIRE(sweep.status == Status::converged);
      CHECK(sweep.branch_kept);
      CHECK(sweep.flips.empty());
      REQUIRE(sweep.change_points.size() == 1);
      CHECK(sweep.change_points[0].find("two branches cross at crank 43.1") != std::string::npos);
    }
  }
}

TEST_CASE("numlab mechanism follows the near-meeting (exit 0) and names the kite's crossing", "[linkage-fast][branch][cli]") {
  const std::string file = numlab::test::temporary_file("near-kite.toml", near_kite_text());
  for (const std::string kind : {"full", "sequential", "analytic"}) {
    INFO("--solver " << kind);
    const auto run = numlab::test::run_numlab("mechanism " + file + " --sweep 30:55:1 --solver " + kind);
    CHECK(run.exit_code == 0);
    CHECK(run.out.find("FLIPPED") == std::string::npos);
    CHECK(run.out.find("crossing ") == std::string::npos);
    const auto kite = numlab::test::run_numlab("mechanism " + model_path("mustang") + " --sweep 30:55:1 --solver " + kind);
    CHECK(kite.exit_code == 0);
    CHECK(kite.out.find("two branches cross at crank 43.1") != std::string::npos);
  }
}
