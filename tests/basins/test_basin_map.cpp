// Basin maps against closed forms: the cube roots of unity, the four-bar's circle intersection, the
// Jansen leg's 16 branches; thread-count determinism; failing points named by their status.

#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <set>
#include <stdexcept>

#include "basins/basin_run.hpp"
#include "basins/basin_systems.hpp"
#include "numlab/mechanisms/jansen_leg.hpp"

using namespace numlab;
using namespace numlab::basins;

namespace {
constexpr double pi = std::numbers::pi;

BasinRequest request(const std::string& system, int n, int threads = 1) {
  BasinRequest r;
  r.system = system;
  r.columns = r.rows = n;
  r.threads = threads;
  return r;
}

// The grid point nearest (u, v).
const nonlinear::BasinPoint& point_near(const nonlinear::BasinMap& map, double u, double v) {
  const auto& s = map.slice;
  const int i = static_cast<int>(std::lround((u - s.u_min) / (s.u_max - s.u_min) * (s.columns - 1)));
  const int j = static_cast<int>(std::lround((v - s.v_min) / (s.v_max - s.v_min) * (s.rows - 1)));
  return map.at(i, j);
}
}  // namespace

TEST_CASE("Fractal modes are the cube roots of unity, e^{2 pi i k/3}", "[basins][fractal]") {
  const CubeRoots system;
  for (int k = 0; k < 3; ++k) {
    const double angle = 2 * pi * k / 3;
    const Vector<2> root(std::cos(angle), std::sin(angle));
    Vector<2> f;
    system.residual(root, f);
    // cos and sin are rounded (half an ulp each); |f'| = 3 magnifies that, plus the rounding of z^3.
    CHECK(f.lpNorm<Eigen::Infinity>() <= 16 * std::numeric_limits<double>::epsilon());
    CHECK(CubeRoots::mode_of(root) == k);
    // Newton from a start near the root ends on it, and it is labelled k.
    const auto result = nonlinear::newton_solve(system, Vector<2>(root * 1.1));
    REQUIRE(result.status == Status::converged);
    CHECK(CubeRoots::mode_of(result.x) == k);
  }
  CHECK(CubeRoots::mode_of(Vector<2>(0.5, 0.5)) == nonlinear::unknown_mode);
}

TEST_CASE("Fractal: a start on the real axis near 1 reaches mode 0; the origin is singular", "[basins][fractal]") {
  const auto run = run_basins(request("fractal", 201));
  const auto& near_one = point_near(run.map, 1.2, 0.0);
  CHECK(near_one.status == Status::converged);
  CHECK(near_one.mode == 0);
  const auto& origin = run.map.at(100, 100);
  REQUIRE(run.map.slice.u(100) == 0.0);
  REQUIRE(run.map.slice.v(100) == 0.0);
  CHECK(origin.status == Status::singular);  // J = 3 z^2 = 0 there
  // By symmetry (conjugation) the three basins are the same size up to the grid: each holds a share.
  const auto counts = tally(run.map, 3);
  for (int k = 0; k < 3; ++k) CHECK(counts.per_mode[k] > counts.total / 4);
  CHECK(counts.unknown == 0);
  // The conjugate start reaches the conjugate root: modes 1 and 2 swap under v -> -v.
  for (int j = 0; j < 201; j += 7) {
    for (int i = 0; i < 201; i += 5) {
      const auto& p = run.map.at(i, j);
      const auto& q = run.map.at(i, 200 - j);
      if (p.status != Status::converged || q.status != Status::converged) continue;
      CHECK(q.mode == (p.mode == 0 ? 0 : 3 - p.mode));
    }
  }
}

TEST_CASE("Four-bar: both modes' roots solve the loop and match the circle-circle closed form", "[basins][four-bar]") {
  const FourBar system(pi / 3);
  for (int mode = 0; mode < 2; ++mode) {
    const Vector<2> exact = system.closed_form(mode);
    Vector<2> f;
    system.residual(exact, f);
    CHECK(f.lpNorm<Eigen::Infinity>() <= 1e-13);
    CHECK(system.mode_of(exact) == mode);
    const auto result = nonlinear::newton_solve(system, Vector<2>(exact.array() + 0.2));
    REQUIRE(result.status == Status::converged);
    CHECK(system.mode_of(result.x) == mode);
  }
  // J against central differences (h = 1e-6: error O(h^2) ~ 1e-12 times the third derivative, 7).
  const Vector<2> at(0.3, 1.1);
  Eigen::Matrix2d J;
  system.jacobian(at, J);
  for (int k = 0; k < 2; ++k) {
    Vector<2> plus = at, minus = at, f_plus, f_minus;
    plus(k) += 1e-6;
    minus(k) -= 1e-6;
    system.residual(plus, f_plus);
    system.residual(minus, f_minus);
    CHECK(((f_plus - f_minus) / 2e-6 - J.col(k)).lpNorm<Eigen::Infinity>() <= 1e-7);
  }
  const auto run = run_basins(request("four-bar", 121));
  const auto counts = tally(run.map, 2);
  CHECK(counts.per_mode[0] > 0);
  CHECK(counts.per_mode[1] > 0);
  CHECK(counts.unknown == 0);
  // A start exactly on a toggle line (theta3 = theta4) has a singular Jacobian.
  const auto& diagonal = run.map.at(60, 60);
  CHECK(diagonal.status == Status::singular);
}

TEST_CASE("Jansen: the solution's grid point converges at once to the seed's mode; labels match each branch",
          "[basins][jansen]") {
  const double crank = mechanisms::JansenClosure::seed_crank_angle;
  const JansenModes modes(crank);
  // The seed's branch is the one mechanisms' closed form takes.
  const mechanisms::JansenLeg leg;
  const auto joints = leg.closed_form_joints(crank);
  REQUIRE(joints);
  std::array<Eigen::Vector2d, 4> seed;
  REQUIRE(modes.closed_form(JansenModes::seed_mode(), seed));
  using J = mechanisms::JansenJoint;
  CHECK((seed[0] - (*joints)[static_cast<int>(J::B)]).norm() <= 1e-12);
  CHECK((seed[3] - (*joints)[static_cast<int>(J::E)]).norm() <= 1e-12);
  CHECK(JansenModes::label(JansenModes::seed_mode()) == "B- C- D+ E-");

  // Newton from seed 000's estimates reaches the seed's mode.
  const mechanisms::JansenClosure closure(crank);
  const auto from_seed = nonlinear::newton_solve(closure, mechanisms::JansenClosure::seed_estimates());
  REQUIRE(from_seed.status == Status::converged);
  CHECK(modes.mode_of(from_seed.x) == JansenModes::seed_mode());

  // Every branch that closes: its closed-form angles solve the closure and are labelled with it.
  int closing = 0;
  for (int mode = 0; mode < JansenModes::count; ++mode) {
    Vector<8> theta;
    if (!modes.closed_form_angles(mode, from_seed.x, theta)) continue;
    ++closing;
    Vector<8> f;
    Eigen::Matrix<double, 8, 8> jac;
    closure.residual_and_jacobian(theta, f, jac);
    CHECK(f.lpNorm<Eigen::Infinity>() <= 1e-12);
    CHECK(modes.mode_of(theta) == mode);
  }
  CHECK(closing >= 2);

  BasinRequest r = request("jansen", 41);
  const auto run = run_basins(r);
  const auto& center = run.map.at(20, 20);  // the slice is centred on the solution
  CHECK(center.status == Status::converged);
  CHECK(center.mode == JansenModes::seed_mode());
  CHECK(center.iterations <= 2);
  // Plain Newton from theta1 = 0.5 (the other angles at the solution) falls into a 2-cycle on the
  // (theta1, theta2) dyad, ||f|| staying near 80 (seen independently with numpy's solve and a
  // finite-difference J): the start ends max_iterations, not converged and not mislabelled.
  const auto& cycling = point_near(run.map, 0.5, run.marks[0].v);
  CHECK(cycling.status == Status::max_iterations);
  // Every reached mode is one whose closed form closes, and verified (mode_of checks each point).
  const auto counts = tally(run.map, JansenModes::count);
  std::array<Eigen::Vector2d, 4> unused;
  for (int mode = 0; mode < JansenModes::count; ++mode) {
    if (counts.per_mode[mode] > 0) CHECK(modes.closed_form(mode, unused));
  }
}

TEST_CASE("A basin map is the same for any number of threads", "[basins][threads]") {
  for (const std::string system : {"fractal", "jansen"}) {
    BasinRequest one = request(system, 61, 1), three = request(system, 61, 3);
    one.columns = three.columns = 53;  // not square, rows not a multiple of the threads
    const auto a = run_basins(one), b = run_basins(three);
    REQUIRE(a.map.points.size() == b.map.points.size());
    int differences = 0;
    for (std::size_t k = 0; k < a.map.points.size(); ++k) {
      const auto &p = a.map.points[k], &q = b.map.points[k];
      differences += p.status != q.status || p.mode != q.mode || p.iterations != q.iterations;
    }
    CHECK(differences == 0);
  }
}

TEST_CASE("Bad slices and requests are refused, naming the problem", "[basins][input]") {
  BasinRequest r = request("fractal", 0);
  CHECK_THROWS_WITH(run_basins(r), Catch::Contains("grid"));
  r = request("fractal", 10, 0);
  CHECK_THROWS_WITH(run_basins(r), Catch::Contains("threads"));
  r = request("pendulum", 10);
  CHECK_THROWS_WITH(run_basins(r), Catch::Contains("unknown system"));
  r = request("jansen", 10);
  r.axis_u = "theta9";
  CHECK_THROWS_WITH(run_basins(r), Catch::Contains("theta9"));
  r = request("fractal", 10, 2);
  r.max_iterations = 0;  // refused by Newton before any worker starts
  CHECK_THROWS_WITH(run_basins(r), Catch::Contains("iteration limit"));
  r = request("fractal", 10);
  r.u_min = 1.0;
  r.u_max = -1.0;
  CHECK_THROWS_WITH(run_basins(r), Catch::Contains("min < max"));
}

TEST_CASE("A range whose width overflows is refused before any worker starts", "[basins][input]") {
  BasinRequest r = request("fractal", 10, 3);
  r.u_min = -1e308;
  r.u_max = 1e308;  // each finite, but u_max - u_min = inf: every start would be inf
  CHECK_THROWS_WITH(run_basins(r), Catch::Contains("finite width"));
  r = request("jansen", 10, 3);
  r.v_min = -1e308;
  r.v_max = 1e308;
  CHECK_THROWS_WITH(run_basins(r), Catch::Contains("finite width"));
}

TEST_CASE("An exception in a worker thread reaches the caller, whatever the thread count", "[basins][threads]") {
  nonlinear::BasinSlice slice;
  slice.columns = slice.rows = 9;
  // The classifier throws for the roots of one mode, met by starts in several rows, so in the
  // workers as well as in the calling thread.
  const auto classify = [](const Vector<2>& z) {
    if (z(1) > 0.5) throw std::runtime_error("classifier failed");
    return CubeRoots::mode_of(z);
  };
  for (const int threads : {1, 2, 4}) {
    INFO(threads << " threads");
    CHECK_THROWS_WITH(nonlinear::basin_map(CubeRoots{}, Vector<2>(0.0, 0.0), slice, nonlinear::NewtonOptions{}, classify,
                                           threads),
                      "classifier failed");
  }
}
