// Every shipped file: it reads, its model has one degree of freedom, its reference pose solves, its
// Jacobian agrees with finite differences, and its velocities and accelerations agree with finite
// differences of solved positions at a few poses.
#include <catch2/catch.hpp>

#include <algorithm>
#include <limits>

#include "model_files.hpp"
#include "numlab/mechanisms/linkage/linkage_structure.hpp"
#include "numlab/mechanisms/linkage/linkage_sweep.hpp"
#include "numlab/nonlinear/jacobian_check.hpp"

using namespace numlab::mechanisms;
using namespace numlab::mechanisms::testing;
using numlab::Status;

namespace {

// Poses to check at, in degrees: the Mustang only assembles on (-41.42, 56.45), and the 7-point
// stencil reaches 3 x 0.05 rad = 8.6 deg to either side.
std::vector<double> poses_for(const std::string& name) {
  if (name == "mustang") return {-20.0, 0.0, 30.0};
  if (name == "hydraulic-boom") return {1.2, 1.6, 2.0};  // the cylinder's length, m
  if (name == "watt-straight-line") return {-15.0, 0.0, 15.0};  // a rocker: it swings, it does not turn
  if (name == "five-bar") return {45.0, 100.0, 150.0};  // the first crank, the second held at 90: P exists for 0 ... 180
  return {0.0, 100.0, 230.0};
}

}  // namespace

TEST_CASE("Every shipped file: mobility 1 (2 with two drivers), Jacobian and derivatives against finite differences", "[linkage-models]") {
  for (const std::string& name : shipped_model_names()) {
    INFO(name);
    const LinkageModel model = model_file(name);
    CHECK(model.description().name == name);
    CHECK(gruebler_kutzbach(model.description()).mobility == (model.has_second_driver() ? 2 : 1));
    LinkageSolverOptions options{"full", "gepp", {}};
    options.newton.residual_tolerance = 1e-12;
    options.newton.max_iterations = 50;
    const LinkageSolver linkage(model, options);
    for (double at : poses_for(name)) {
      INFO("at " << at);
      const LinkageSweep sweep = linkage_sweep(linkage, at, at, 1.0);
      REQUIRE(sweep.status == Status::converged);
      const LinkagePose& pose = sweep.poses.front();
      const double t = model.driver_from_user(at);
      // The Jacobian at the pose and at the rough (unsolved) positions.
      for (const Eigen::VectorXd& q : {pose.q, Eigen::VectorXd(model.unknowns(model.rough_positions()))}) {
        const LinkageSystem system(model, t);
        const auto check = numlab::nonlinear::check_jacobian(system, q);
        INFO(numlab::nonlinear::describe_worst_entry(check));
        CHECK(check.agrees);
      }
      // Velocity: check_derivatives' central difference of positions (h = 1e-5): truncation
      // h^2 |q'''| / 6 and rounding kappa 64 eps |q| / h, ~1e-9 here; the bound leaves a decade.
      const DerivativeCheck derivatives = check_derivatives(linkage, t, pose.q);
      REQUIRE(derivatives.solved);
      const double scale_q = std::max(1.0, pose.q.lpNorm<Eigen::Infinity>());
      INFO("kappa " << pose.condition << ", |q| " << scale_q << ", velocity difference " << derivatives.velocity_difference
                    << " of " << derivatives.velocity_scale);
      CHECK(derivatives.velocity_difference < 1e-8 * std::max(scale_q, derivatives.velocity_scale));
      // Acceleration: a central difference of the Jacobian's velocities at t +- h (h = 1e-4), the
      // positions there solved to ||Phi||_inf <= 1e-13. Rounding: kappa 64 eps max(|q|, |qdot|) / h;
      // truncation h^2 |q''''| / 6, below 1e-6 max(1, |qddot|) while |q''''| <= 600 max(1, |qddot|).
      // (check_derivatives' 7-point stencil of positions uses h = 0.05 rad, where its truncation
      // error reaches 1e-5 ... 3e-4 on chebyshev, hoeken and mustang: shown, not checked.)
      const double h = 1e-4;
      const auto velocity_at = [&](double s) {
        LinkageSolverOptions fine = options;
        fine.newton.residual_tolerance = 1e-13;
        const LinkageSolution solution = LinkageSolver(model, fine).solve(s, pose.q);
        REQUIRE(solution.outcome.status == Status::converged);
        Eigen::VectorXd velocity, acceleration;
        linkage_kinematics(model, s, solution.q, velocity, acceleration);
        return velocity;
      };
      const Eigen::VectorXd difference = (velocity_at(t + h) - velocity_at(t - h)) / (2.0 * h) - pose.acceleration;
      const double scale_v = std::max(scale_q, pose.velocity.lpNorm<Eigen::Infinity>());
      const double scale_a = std::max(1.0, pose.acceleration.lpNorm<Eigen::Infinity>());
      const double rounding = pose.condition * 64.0 * std::numeric_limits<double>::epsilon() * scale_v / h;
      INFO("acceleration difference " << difference.lpNorm<Eigen::Infinity>() << " of " << scale_a << " (rounding bound "
                                      << rounding << "); 7-point stencil: " << derivatives.acceleration_difference);
      CHECK(difference.lpNorm<Eigen::Infinity>() < 10.0 * rounding + 1e-6 * scale_a);
    }
  }
}
