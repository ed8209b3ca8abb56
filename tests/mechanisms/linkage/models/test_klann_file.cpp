// klann.toml: Klann's leg turns fully, its foot path closes, and the foot's stance is long and
// nearly level. The numbers were derived independently of numlab from the file's dimensions
// (circle intersections, sampled every 0.5 degree):
//   the foot G moves backwards (x decreasing) from crank 13.5 to 178 deg (the stance, 164.5 deg of
//   the turn), and forwards over the rest;
//   over 15 ... 165 deg it covers 71.7 in x while its height stays within 5.43 (7.6 % of that) of
//   its lowest point, -64.03 at 145.5 deg;
//   it lifts to -30.60 at 246.5 deg, 33.4 above its lowest point.
#include <catch2/catch.hpp>

#include <algorithm>

#include "model_files.hpp"
#include "numlab/mechanisms/linkage/linkage_blocks.hpp"
#include "numlab/mechanisms/linkage/linkage_sweep.hpp"

using namespace numlab::mechanisms;
using namespace numlab::mechanisms::testing;
using numlab::Status;

TEST_CASE("klann.toml: the leg turns fully by dyads and the foot path closes", "[linkage-models]") {
  const LinkageModel model = model_file("klann");
  for (const auto& block : linkage_blocks(model)) CHECK(block.closed_form());
  LinkageSolverOptions options{"full", "gepp", {}};
  options.newton.residual_tolerance = 1e-12;
  const LinkageSolver linkage(model, options);
  const LinkageSweep sweep = linkage_sweep(linkage, 0.0, 360.0, 1.0);  // by continuation, a whole turn
  REQUIRE(sweep.status == Status::converged);
  CHECK(sweep.branch_kept);
  CHECK(sweep.limits.empty());
  // After a whole turn, every joint is back where it started (kappa(J) <= 40 here, ||Phi|| <= 1e-12).
  const Eigen::VectorXd difference = sweep.poses.back().q - sweep.poses.front().q;
  CHECK(difference.lpNorm<Eigen::Infinity>() < 1e-9);
}

TEST_CASE("klann.toml: the foot's stance covers 164.5 degrees of the crank and is nearly level", "[linkage-models]") {
  const LinkageModel model = model_file("klann");
  const LinkageSolver linkage(model, {"analytic", "gepp", {}});
  const LinkageSweep sweep = linkage_sweep(linkage, 0.0, 359.5, 0.5);
  REQUIRE(sweep.status == Status::converged);
  const int G = model.column_of(model.description().joint_index("G"));
  double lowest = 1e300, highest = -1e300, lowest_at = 0.0, highest_at = 0.0;
  double stance_top = -1e300, stance_left = 1e300, stance_right = -1e300;
  for (std::size_t k = 0; k < sweep.poses.size(); ++k) {
    const LinkagePose& pose = sweep.poses[k];
    const double crank = 0.5 * static_cast<double>(k);  // pose.driver, without its rounding
    const double x = pose.q(G), y = pose.q(G + 1), vx = pose.velocity(G);
    if (y < lowest) lowest = y, lowest_at = crank;
    if (y > highest) highest = y, highest_at = crank;
    // Backwards from 14 to 178 deg (the turning points 13.5 and 178.x lie outside), forwards elsewhere.
    if (crank >= 14.0 && crank <= 177.5) CHECK(vx < 0.0);
    if (crank <= 13.0 || crank >= 179.0) CHECK(vx > 0.0);
    if (crank >= 15.0 && crank <= 165.0) {
      stance_top = std::max(stance_top, y);
      stance_left = std::min(stance_left, x);
      stance_right = std::max(stance_right, x);
    }
  }
  CHECK(lowest == Approx(-64.0284).margin(1e-4));
  CHECK(lowest_at == 145.5);
  CHECK(highest == Approx(-30.5958).margin(1e-4));
  CHECK(highest_at == 246.5);
  CHECK(stance_right - stance_left == Approx(71.7048).margin(1e-4));
  CHECK(stance_top - lowest == Approx(5.4301).margin(1e-4));
}
