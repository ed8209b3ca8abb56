// chebyshev.toml (Chebyshev's lambda) and hoeken.toml (Hoeken's linkage): where the coupler point P
// runs nearly straight, how straight, and (Hoeken) how evenly.
//
// Both files have the proportions crank 1 : ground 2 : rocker 2.5 : coupler 2.5 + 2.5 (P = 2 B - A),
// Hoeken's upright, the lambda hung below the ground line. The numbers below were derived
// independently of numlab, from that geometry alone (circle intersection for B, sampled every
// 0.09 degrees, a least-squares line by SVD):
//   crank 90 ... 270 deg (half the turn): P travels 4 (twice the ground) along a line parallel to
//     O-Q and stays within 0.00502 of it: 0.1255 % of the stretch. P is on the line y = +-4
//     exactly at 90, 180 and 270 deg.
//   crank 60 ... 300 deg: the deviation is 0.0539, 1.15 % of the length: the straight stretch ends
//     near 90 and 270 deg.
//   speed |dP/dt| (per radian of crank): 1.279 ... 1.336 over 120 ... 240 deg (4.3 % of its mean),
//     1.000 ... 1.336 over 90 ... 270 deg (26 %).
// The tests first check the file's P against that geometry in closed form (Freudenstein), then
// measure the same quantities on the poses the file's model solves.
#include <catch2/catch.hpp>

#include <Eigen/SVD>
#include <algorithm>

#include "closed_forms.hpp"
#include "model_files.hpp"
#include "numlab/mechanisms/linkage/linkage_sweep.hpp"

using namespace numlab::mechanisms;
using namespace numlab::mechanisms::testing;
using numlab::Status;

namespace {

struct Stretch {
  double deviation = 0.0;  // max distance from the least-squares line
  double length = 0.0;     // extent along it
  double min_speed = 0.0, max_speed = 0.0, mean_speed = 0.0;
  double reference_distance = 0.0;  // max |P - P_closed_form|
};

// P over crank angles [from, to] degrees (step 0.5), solved by the file's model, and measured.
Stretch measure(const std::string& file, double from, double to) {
  const LinkageModel model = model_file(file);
  LinkageSolverOptions options{"analytic", "gepp", {}};
  const LinkageSolver linkage(model, options);
  const LinkageSweep sweep = linkage_sweep(linkage, from, to, 0.5);
  REQUIRE(sweep.status == Status::converged);
  REQUIRE(sweep.branch_kept);
  // Freudenstein's closed form for the same four-bar: rocker angle -> B -> P = 2 B - A.
  const double a = 1.0, b = 2.5, c = 2.5, d = 2.0;
  const auto closed_P = [&](double t, int sign) {
    const double p = freudenstein_rocker(a, b, c, d, t, sign);
    const Eigen::Vector2d A(a * std::cos(t), a * std::sin(t)), B(d + c * std::cos(p), c * std::sin(p));
    return Eigen::Vector2d(2.0 * B - A);
  };
  const double t0 = linkage.reference_driver();
  const Eigen::Vector2d P0 = joint_at(model, linkage.reference(), "P");
  const int sign = (closed_P(t0, 1) - P0).norm() < (closed_P(t0, -1) - P0).norm() ? 1 : -1;

  Stretch s;
  const int n = static_cast<int>(sweep.poses.size());
  Eigen::MatrixXd points(n, 2);
  std::vector<double> speeds;
  const int P_column = model.column_of(model.description().joint_index("P"));
  for (int k = 0; k < n; ++k) {
    const LinkagePose& pose = sweep.poses[static_cast<std::size_t>(k)];
    const Eigen::Vector2d P = joint_at(model, pose.q, "P");
    points.row(k) = P.transpose();
    s.reference_distance = std::max(s.reference_distance, (P - closed_P(pose.driver * deg, sign)).norm());
    speeds.push_back(pose.velocity.segment<2>(P_column).norm());
  }
  const Eigen::RowVector2d centre = points.colwise().mean();
  const Eigen::MatrixXd centred = points.rowwise() - centre;
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(centred, Eigen::ComputeThinV);
  const Eigen::VectorXd along = centred * svd.matrixV().col(0), across = centred * svd.matrixV().col(1);
  s.deviation = across.cwiseAbs().maxCoeff();
  s.length = along.maxCoeff() - along.minCoeff();
  s.min_speed = *std::min_element(speeds.begin(), speeds.end());
  s.max_speed = *std::max_element(speeds.begin(), speeds.end());
  for (double v : speeds) s.mean_speed += v / static_cast<double>(speeds.size());
  return s;
}

}  // namespace

TEST_CASE("Chebyshev's lambda: the foot runs straight over half the crank turn, within 0.13 % of its stride",
          "[linkage-models]") {
  const Stretch half = measure("chebyshev", 90.0, 270.0);
  INFO("deviation " << half.deviation << " over " << half.length << " (closed form within " << half.reference_distance
                    << ")");
  CHECK(half.reference_distance < 1e-10);
  CHECK(half.length == Approx(4.0).epsilon(1e-9));
  CHECK(half.deviation / half.length == Approx(0.001255).epsilon(0.03));
  // Beyond it the path bends away: ten times the deviation, relative to the length.
  const Stretch wider = measure("chebyshev", 60.0, 300.0);
  CHECK(wider.deviation / wider.length == Approx(0.01149).epsilon(0.03));
  // The foot is on the line at 90, 180 and 270 degrees.
  const LinkageModel model = model_file("chebyshev");
  const LinkageSolver linkage(model, {"analytic", "gepp", {}});
  for (double t : {90.0, 180.0, 270.0}) {
    const auto solution = linkage.solve(model.driver_from_user(t), linkage.reference());
    REQUIRE(solution.outcome.status == Status::converged);
    CHECK(joint_at(model, solution.q, "P").y() == Approx(-4.0).margin(1e-12));
  }
}

TEST_CASE("Hoeken's linkage: the coupler point's speed is even along the middle of the straight stretch",
          "[linkage-models]") {
  const Stretch middle = measure("hoeken", 120.0, 240.0);
  INFO("speed " << middle.min_speed << " ... " << middle.max_speed << ", mean " << middle.mean_speed);
  CHECK(middle.reference_distance < 1e-10);
  CHECK(middle.min_speed == Approx(1.2791).epsilon(1e-3));
  CHECK(middle.max_speed == Approx(1.3360).epsilon(1e-3));
  CHECK((middle.max_speed - middle.min_speed) / middle.mean_speed < 0.045);
  const Stretch half = measure("hoeken", 90.0, 270.0);
  CHECK(half.deviation / half.length == Approx(0.001255).epsilon(0.03));
  CHECK(half.min_speed == Approx(1.0).epsilon(1e-3));
  CHECK((half.max_speed - half.min_speed) / half.mean_speed == Approx(0.2639).epsilon(0.03));
}
