// four-bar.toml against Freudenstein's equation, slider-crank.toml against the offset
// slider-crank's formulas. The lengths are read from the files, not restated here.
#include <catch2/catch.hpp>

#include <algorithm>

#include "closed_forms.hpp"
#include "model_files.hpp"
#include "numlab/mechanisms/linkage/linkage_sweep.hpp"

using namespace numlab::mechanisms;
using namespace numlab::mechanisms::testing;
using numlab::Status;

namespace {

// The length of the link between two named joints, as the file gives it.
double link_length(const LinkageDescription& d, std::string_view first, std::string_view second) {
  const int i = d.joint_index(first), j = d.joint_index(second);
  for (const LinkSpec& link : d.links) {
    if ((link.first == i && link.second == j) || (link.first == j && link.second == i)) return link.length;
  }
  throw std::invalid_argument("no link " + std::string(first) + "-" + std::string(second));
}

double angle_distance(double x, double y) { return std::abs(std::remainder(x - y, 2.0 * pi)); }

}  // namespace

TEST_CASE("four-bar.toml is a Grashof crank-rocker and follows Freudenstein's equation", "[linkage-models]") {
  const LinkageModel model = model_file("four-bar");
  const LinkageDescription& d = model.description();
  const Eigen::Vector2d O = d.joints[static_cast<std::size_t>(d.joint_index("O"))].position;
  const Eigen::Vector2d Q = d.joints[static_cast<std::size_t>(d.joint_index("Q"))].position;
  REQUIRE(O.isZero());
  REQUIRE(Q.y() == 0.0);  // the formula's frame: O at the origin, Q on +x
  const double a = link_length(d, "O", "A"), b = link_length(d, "A", "B"), c = link_length(d, "Q", "B"), g = Q.x();
  // Grashof: s + l <= p + q, and the crank is the shortest link (a crank-rocker).
  const double s = std::min({a, b, c, g}), l = std::max({a, b, c, g});
  CHECK(s + l <= a + b + c + g - s - l);
  CHECK(a == s);

  for (const std::string solver : {"full", "sequential", "analytic", "gsl-hybridsj"}) {
    LinkageSolverOptions options{solver, "gepp", {}};
    options.newton.residual_tolerance = 1e-12;
    const LinkageSolver linkage(model, options);
    const LinkageSweep sweep = linkage_sweep(linkage, 0.0, 359.0, 1.0);
    INFO(solver);
    REQUIRE(sweep.status == Status::converged);
    CHECK(sweep.branch_kept);
    CHECK(sweep.limits.empty());  // Grashof: the crank turns fully
    const auto rocker = [&](const Eigen::VectorXd& q) {
      const Eigen::Vector2d B = joint_at(model, q, "B");
      return std::atan2(B.y(), B.x() - g);
    };
    // The reference pose picks one of the two roots; the whole sweep must stay on it.
    const double t0 = linkage.reference_driver();
    const int sign = angle_distance(rocker(linkage.reference()), freudenstein_rocker(a, b, c, g, t0, 1)) <
                             angle_distance(rocker(linkage.reference()), freudenstein_rocker(a, b, c, g, t0, -1))
                         ? 1
                         : -1;
    double worst = 0.0, worst_condition = 0.0;
    for (const auto& pose : sweep.poses) {
      worst = std::max(worst, angle_distance(rocker(pose.q), freudenstein_rocker(a, b, c, g, pose.driver * deg, sign)));
      worst_condition = std::max(worst_condition, pose.condition);
    }
    // ||Phi||_inf <= 1e-12 and kappa(J) below 10 (measured per pose): angles to ~1e-11 rad.
    INFO("max kappa " << worst_condition);
    CHECK(worst_condition < 10.0);
    CHECK(worst < 1e-10);
  }
}

TEST_CASE("slider-crank.toml's slider position, velocity and acceleration match the closed form", "[linkage-models]") {
  const LinkageModel model = model_file("slider-crank");
  const LinkageDescription& d = model.description();
  REQUIRE(d.sliders.size() == 1);
  REQUIRE(d.sliders[0].angle_deg == 0.0);  // the formula's slider line: y = e along +x
  REQUIRE(d.joints[static_cast<std::size_t>(d.joint_index("O"))].position.isZero());
  const double r = link_length(d, "O", "A"), l = link_length(d, "A", "S"), e = d.sliders[0].through.y();
  REQUIRE(e != 0.0);  // an offset slider-crank
  const int column = model.column_of(d.joint_index("S"));
  for (const std::string solver : {"full", "sequential", "analytic"}) {
    LinkageSolverOptions options{solver, "gepp", {}};
    options.newton.residual_tolerance = 1e-13;
    const LinkageSweep sweep = linkage_sweep(LinkageSolver(model, options), 0.0, 359.0, 1.0);
    INFO(solver);
    REQUIRE(sweep.status == Status::converged);
    double worst_x = 0.0, worst_v = 0.0, worst_a = 0.0;
    for (const auto& pose : sweep.poses) {
      const SliderMotion exact = offset_slider_crank(r, l, e, pose.driver * deg);
      worst_x = std::max(worst_x, std::abs(pose.q(column) - exact.x) + std::abs(pose.q(column + 1) - e));
      worst_v = std::max(worst_v, std::abs(pose.velocity(column) - exact.velocity) + std::abs(pose.velocity(column + 1)));
      worst_a = std::max(worst_a, std::abs(pose.acceleration(column) - exact.acceleration) +
                                      std::abs(pose.acceleration(column + 1)));
    }
    // kappa(J) <= 3 here and |x| ~ 4: positions to a few ulps of the residual tolerance; velocity
    // and acceleration inherit that error times |dJ^-1| ~ 1 and the rounding of one more solve.
    INFO("worst |dx| " << worst_x << ", |dv| " << worst_v << ", |da| " << worst_a);
    CHECK(worst_x < 1e-12);
    CHECK(worst_v < 1e-11);
    CHECK(worst_a < 1e-10);
  }
}
