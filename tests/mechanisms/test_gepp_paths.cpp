// The textbook GEPP stepper and the fast path give bit-identical steps on the Jacobians the Jansen
// solvers actually meet (../linalg/gepp_paths.hpp).

#include <catch2/catch.hpp>

#include "../linalg/gepp_paths.hpp"
#include "numlab/mechanisms/jansen10_closure.hpp"
#include "numlab/mechanisms/jansen_closure.hpp"
#include "numlab/mechanisms/jansen_leg.hpp"
#include "numlab/mechanisms/jansen_solvers.hpp"

using namespace numlab;
using namespace numlab::mechanisms;
using numlab::test::check_gepp_paths_agree;

namespace {
// Offsets of up to about 0.1 rad from the seed's estimates, different in every angle.
template <int N>
linalg::Vector<N> nudge(const linalg::Vector<N>& theta, int pose) {
  linalg::Vector<N> nudged = theta;
  for (int i = 0; i < N; ++i) nudged(i) += 0.02 * pose * std::sin(1.0 + 3.0 * i + pose);
  return nudged;
}

// J and f at poses near theta0; for each, the Newton step J dx = -f on both paths.
template <typename Closure, int N>
void check_newton_steps_near(const Closure& closure, const linalg::Vector<N>& theta0) {
  for (int pose = 0; pose <= 5; ++pose) {
    const linalg::Vector<N> theta = nudge<N>(theta0, pose);
    linalg::Vector<N> f;
    linalg::Matrix<N> J;
    closure.residual_and_jacobian(theta, f, J);
    INFO("pose " << pose);
    CHECK(check_gepp_paths_agree<N>(J, -f).status == Status::converged);
    // The same Jacobian as a dynamic-size system (the runtime-chosen solvers' path).
    check_gepp_paths_agree<Eigen::Dynamic>(Eigen::MatrixXd(J), Eigen::VectorXd(-f));
  }
}
}  // namespace

TEST_CASE("GEPP's two paths agree bit for bit on Jansen Jacobians (8 equations)", "[gepp][paths][jansen]") {
  for (double offset : {0.0, 0.3, -0.5, 1.0}) {
    INFO("crank angle " << JansenClosure::seed_crank_angle + offset);
    const JansenClosure closure(JansenClosure::seed_crank_angle + offset);
    check_newton_steps_near<JansenClosure, 8>(closure, JansenClosure::seed_estimates());
  }
}

TEST_CASE("GEPP's two paths agree bit for bit on Jansen Jacobians (10 equations)", "[gepp][paths][jansen]") {
  const linalg::Vector<10> seed = jansen_seed_estimates(JansenModel::ten_equations, JansenLeg());
  for (double offset : {0.0, 0.3, -0.5}) {
    INFO("crank angle " << JansenClosure::seed_crank_angle + offset);
    const Jansen10Closure closure(JansenClosure::seed_crank_angle + offset);
    check_newton_steps_near<Jansen10Closure, 10>(closure, seed);
  }
}
