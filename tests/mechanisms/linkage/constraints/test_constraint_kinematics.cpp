// The new constraints and drivers (a slider in a moving link's slot, an actuator, a motor between two
// links, a bar of collinear points) against their closed forms (constraint_mechanisms.hpp):
//  - positions over a range of the driver, at scales 1e-3, 1 and 1e3 (the same angles, lengths scaled);
//  - velocities and accelerations from J q' = -Phi_t, J q'' = gamma against 5-point central
//    differences of the closed form's positions;
//  - J against central differences of Phi, Phi_t against differences in t, and gamma against the
//    central difference of J v + Phi_t along (q + h v, t + h) for arbitrary v and q (gamma's second
//    derivatives are written by hand in linkage_rows.hpp);
//  - the mobility count and the rows' names.

#include <catch2/catch.hpp>

#include <Eigen/LU>
#include <cmath>
#include <random>

#include "constraint_mechanisms.hpp"
#include "newton_polish.hpp"
#include "numlab/mechanisms/linkage/link_motion.hpp"
#include "numlab/mechanisms/linkage/linkage_structure.hpp"
#include "numlab/mechanisms/linkage/linkage_sweep.hpp"

using namespace numlab::mechanisms;
using namespace numlab::mechanisms::testing;

namespace {

// The largest distance between the model's joints at q and the closed form's.
double distance_from(const LinkageModel& model, const Eigen::VectorXd& q, const Joints& closed) {
  const JointPositions p = model.positions(q);
  double worst = 0.0;
  for (std::size_t j = 0; j < p.size(); ++j) worst = std::max(worst, (p[j] - closed.at(model.description().joints[j].name)).norm());
  return worst;
}

// The closed form's joints stacked in the model's unknown order.
template <typename Closed>
Eigen::VectorXd closed_unknowns(const LinkageModel& model, const Closed& closed, double t) {
  const Joints j = closed(t);
  JointPositions p;
  for (const JointSpec& joint : model.description().joints) p.push_back(j.at(joint.name));
  return model.unknowns(p);
}

// Positions, velocities and accelerations against the closed form at each driver value (model
// units), the closed form's derivatives by 5-point central differences with step h.
template <typename Closed>
void check_against_closed_form(const LinkageModel& model, const Closed& closed, const std::vector<double>& drivers, double h,
                               double size) {
  LinkageSolverOptions options;
  options.newton.residual_tolerance = 1e-12;
  const LinkageSolver solver(model, options);
  Eigen::VectorXd q = solver.reference();
  for (double t : drivers) {
    INFO("driver " << t);
    const auto solved = solver.solve(t, q);
    REQUIRE(solved.outcome.status == numlab::Status::converged);
    q = polish(model, t, solved.q);
    CHECK(distance_from(model, q, closed(t)) <= 1e-12 * size);
    Eigen::VectorXd velocity, acceleration;
    linkage_kinematics(model, t, q, velocity, acceleration);
    REQUIRE(velocity.allFinite());
    REQUIRE(acceleration.allFinite());
    const auto at = [&](int k) { return closed_unknowns(model, closed, t + k * h); };
    const Eigen::VectorXd fd_velocity = (at(-2) - 8.0 * at(-1) + 8.0 * at(1) - at(2)) / (12.0 * h);
    const Eigen::VectorXd fd_acceleration = (-at(-2) + 16.0 * at(-1) - 30.0 * at(0) + 16.0 * at(1) - at(2)) / (12.0 * h * h);
    const double v_scale = std::max(fd_velocity.lpNorm<Eigen::Infinity>(), 1e-3 * size);
    const double a_scale = std::max(fd_acceleration.lpNorm<Eigen::Infinity>(), 1e-3 * size);
    CHECK((velocity - fd_velocity).lpNorm<Eigen::Infinity>() <= 1e-8 * v_scale);
    CHECK((acceleration - fd_acceleration).lpNorm<Eigen::Infinity>() <= 1e-6 * a_scale);
  }
}

// J, Phi_t and gamma against differences at (q, t), and with arbitrary v.
void check_derivatives_by_differences(const LinkageModel& model, const Eigen::VectorXd& q, double t, std::mt19937& random) {
  const int n = model.unknown_count();
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  Eigen::MatrixXd J, fd_J(n, n);
  model.jacobian(q, t, J);
  const double scale = q.lpNorm<Eigen::Infinity>() + 1.0;
  const double h = 1e-6 * scale;
  Eigen::VectorXd plus, minus;
  for (int c = 0; c < n; ++c) {
    Eigen::VectorXd a = q, b = q;
    a(c) += h, b(c) -= h;
    model.residual(a, t, plus);
    model.residual(b, t, minus);
    fd_J.col(c) = (plus - minus) / (2.0 * h);
  }
  CHECK((J - fd_J).lpNorm<Eigen::Infinity>() <= 1e-7 * (1.0 + J.lpNorm<Eigen::Infinity>()));
  // Entries: the same J.
  std::vector<LinkageModel::JacobianEntry> entries;
  model.jacobian_entries(q, t, entries);
  Eigen::MatrixXd from_entries = Eigen::MatrixXd::Zero(n, n);
  for (const auto& e : entries) from_entries(e.row, e.column) += e.value;
  CHECK((from_entries - J).lpNorm<Eigen::Infinity>() <= 1e-15 * (1.0 + J.lpNorm<Eigen::Infinity>()));
  // Phi_t.
  Eigen::VectorXd phi_t;
  model.driver_derivative(q, t, phi_t);
  const double ht = 1e-6;
  model.residual(q, t + ht, plus);
  model.residual(q, t - ht, minus);
  CHECK((phi_t - (plus - minus) / (2.0 * ht)).lpNorm<Eigen::Infinity>() <= 1e-7 * (1.0 + scale));
  // gamma = -d/ds (J v + Phi_t) along (q + s v, t + s), v arbitrary (of the unknowns' size).
  Eigen::VectorXd v(n);
  for (int k = 0; k < n; ++k) v(k) = scale * uniform(random);
  const auto rate = [&](double s) {
    Eigen::MatrixXd Js;
    Eigen::VectorXd ts;
    model.jacobian(q + s * v, t + s, Js);
    model.driver_derivative(q + s * v, t + s, ts);
    return Eigen::VectorXd(Js * v + ts);
  };
  Eigen::VectorXd gamma;
  model.acceleration_rhs(q, v, t, gamma);
  const double hs = 1e-5;
  const Eigen::VectorXd fd = -(rate(hs) - rate(-hs)) / (2.0 * hs);
  CHECK((gamma - fd).lpNorm<Eigen::Infinity>() <= 1e-6 * (1.0 + fd.lpNorm<Eigen::Infinity>()));
}

}  // namespace

TEST_CASE("A slider in a moving link's slot: the inverted slider-crank against its closed form", "[linkage][constraints]") {
  for (const double e : {0.0, 0.3, -0.4}) {
    for (const double k : {1e-3, 1.0, 1e3}) {
      INFO("offset " << e << ", scale " << k);
      const InvertedSliderCrank mechanism{k, e};
      const LinkageModel model(parse_linkage_description(mechanism.text(60.0), "isc.toml"));
      CHECK(model.row_name(1) == "slider A on B-C");
      CHECK(gruebler_kutzbach(model.description()).mobility == 1);
      std::vector<double> drivers;
      for (double d = 60.0; d <= 420.0; d += 7.5) drivers.push_back(d * deg);
      check_against_closed_form(model, [&](double t) { return mechanism.at(t); }, drivers, 1e-3, 5 * k);
    }
  }
}

TEST_CASE("An actuator: the boom's law of cosines, and a bar with its tip on its extension", "[linkage][constraints]") {
  for (const double k : {1e-3, 1.0, 1e3}) {
    INFO("scale " << k);
    const Boom boom{k};
    const LinkageModel model(parse_linkage_description(boom.text(1.8 * k), "boom.toml"));
    CHECK(model.description().bodies[0].collinear);
    CHECK(model.row_name(3) == "actuator G-P");
    // Gruebler-Kutzbach: ground, bar, cylinder, rod; pins O, P, G and the cylinder's sliding pair.
    const Mobility m = gruebler_kutzbach(model.description());
    CHECK(m.members == 4);
    CHECK(m.lower_pairs == 4);
    CHECK(m.mobility == 1);
    std::vector<double> drivers;
    for (double s = 1.2; s <= 2.9; s += 0.05) drivers.push_back(s * k);
    check_against_closed_form(model, [&](double s) { return boom.at(s); }, drivers, 1e-3 * k, 3 * k);
  }
}

TEST_CASE("A motor between two moving links: the four-bar driven at its coupler joint", "[linkage][constraints]") {
  for (const double k : {1e-3, 1.0, 1e3}) {
    INFO("scale " << k);
    const MotorFourBar four_bar{k};
    const LinkageModel model(parse_linkage_description(four_bar.text(100.0), "motor.toml"));
    CHECK(model.row_name(3) == "motor O-A-B");
    CHECK(model.driver_to_user(model.driver_from_user(100.0)) == Approx(100.0));
    // The closed form's own angle is the motor's (A's side picked right).
    const Joints j = four_bar.at(100.0 * deg);
    const Eigen::Vector2d u = j.at("O") - j.at("A"), v = j.at("B") - j.at("A");
    CHECK(std::atan2(u.x() * v.y() - u.y() * v.x(), u.dot(v)) == Approx(100.0 * deg).epsilon(1e-14));
    std::vector<double> drivers;
    for (double d = 100.0; d <= 170.0; d += 5.0) drivers.push_back(d * deg);  // sin t > 0: the closed form's A side
    check_against_closed_form(model, [&](double t) { return four_bar.at(t); }, drivers, 1e-3, 4.5 * k);
  }
}

TEST_CASE("The new rows' J, Phi_t and gamma agree with differences, on and off the constraint manifold",
          "[linkage][constraints]") {
  std::mt19937 random(30);
  std::uniform_real_distribution<double> uniform(-0.3, 0.3);
  const std::vector<std::pair<std::string, double>> files = {
      {InvertedSliderCrank{1.0, 0.3}.text(60.0), 60.0 * deg}, {Boom{}.text(1.8), 1.8}, {MotorFourBar{}.text(100.0), 100.0 * deg}};
  for (const auto& [text, t] : files) {
    const LinkageModel model(parse_linkage_description(text, "f.toml"));
    const Eigen::VectorXd q = polish(model, t, model.unknowns(model.rough_positions()));
    check_derivatives_by_differences(model, q, t, random);
    Eigen::VectorXd off = q;
    for (Eigen::Index k = 0; k < off.size(); ++k) off(k) += uniform(random);
    check_derivatives_by_differences(model, off, t + 0.2, random);
  }
}

TEST_CASE("The output may name a slot's joint: its travel along the slot and that travel's rate", "[linkage][constraints]") {
  // Offset 0: the block A is on the rocker's line on C's side of B, so its travel along B -> C is
  // s = |A - B| = sqrt(10 - 6 cos theta), and ds/dtheta = 3 sin theta / s (crank 1, |OB| = 3).
  const InvertedSliderCrank mechanism{1.0, 0.0};
  const LinkageModel model(parse_linkage_description(mechanism.text(60.0), "isc.toml"));
  const auto output = find_output(model.description(), "A");
  REQUIRE(output);
  CHECK_FALSE(output->angle());
  CHECK(output->line_from == model.description().joint_index("B"));
  const auto lines = link_lines(model.description());
  for (double degrees = 60.0; degrees < 420.0; degrees += 15.0) {
    INFO("crank " << degrees);
    const double t = degrees * deg;
    const Eigen::VectorXd q = polish(model, t, closed_unknowns(model, [&](double s) { return mechanism.at(s); }, t));
    const Eigen::VectorXd velocity = linkage_velocity(model, t, q);
    const double s = std::sqrt(10.0 - 6.0 * std::cos(t));
    CHECK(output_rate(*output, lines, joint_motions(model, q, velocity, {})) == Approx(3.0 * std::sin(t) / s).margin(1e-12));
  }
}
