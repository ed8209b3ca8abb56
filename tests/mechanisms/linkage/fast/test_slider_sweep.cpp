// A sweep of a slider-driven linkage that starts at its reference pose (no walk to the start) ends:
// its continuation sub-steps are never shorter than the sweep's step. It used to take sub-steps of
// 1e-12 and never reach the second pose.
#include <catch2/catch.hpp>

#include <cmath>

#include "numlab/mechanisms/linkage/linkage_sweep.hpp"

using namespace numlab::mechanisms;
using numlab::Status;

namespace {

// docs/linkage-files.md's slider-driven slider-crank: crank 1, coupler 2, the slider's line y = 0.25.
constexpr const char* slider_driven = R"(
[linkage]
name = "offset-slider-crank"
[ground]
O = [0.0, 0.0]
[joints]
A = [0.9, 0.5]
S = [2.9, 0.25]
[[link]]
joints = ["O", "A"]
length = 1.0
[[link]]
joints = ["A", "S"]
length = 2.0
[[slider]]
joint = "S"
through = [0.0, 0.25]
[driver]
type = "slider"
joint = "S"
travel = 2.9
)";

}  // namespace

TEST_CASE("a slider-driven sweep from its reference pose reaches every pose", "[linkage-fast][slider]") {
  const LinkageModel model(parse_linkage_description(slider_driven, "slider.toml"));
  for (const std::string kind : {"full", "sequential", "analytic"}) {
    INFO("--solver " << kind);
    const LinkageSolver solver(model, {kind, "gepp", {}});
    for (const bool generic : {true, false}) {
      const LinkageSweep sweep = generic ? linkage_sweep(solver, 2.9, 2.0, -0.1, [](const LinkagePose&) { return numlab::StepControl::proceed; })
                                         : linkage_sweep(solver, 2.9, 2.0, -0.1);
      REQUIRE(sweep.poses.size() == 10);
      CHECK(sweep.status == Status::converged);
      // Each pose against the closed form: A is where the crank circle meets the circle of radius 2
      // about S = (s, 0.25); |A - S| = 2 and |A| = 1 at the result.
      for (const LinkagePose& pose : sweep.poses) {
        const JointPositions joints = model.positions(pose.q);
        const Eigen::Vector2d a = joints[static_cast<std::size_t>(model.description().joint_index("A"))];
        const Eigen::Vector2d s = joints[static_cast<std::size_t>(model.description().joint_index("S"))];
        CHECK(std::abs(s.x() - pose.driver) <= 1e-9);
        CHECK(std::abs(s.y() - 0.25) <= 1e-9);
        CHECK(std::abs(a.norm() - 1.0) <= 1e-9);
        CHECK(std::abs((a - s).norm() - 2.0) <= 1e-9);
      }
    }
  }
}
