// jansen-jacobian: the student's f and J of seed 000's 8-equation Jansen closure, against
// numlab's JansenClosure (whose Jacobian is itself checked here by central differences).

#include <cmath>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <limits>

#include "exercises/detectors/mechanism_jacobian.hpp"
#include "exercises/exercise_list.hpp"
#include "exercises/jansen_poses.hpp"
#include "exercises/linkage_checks.hpp"
#include "exercises/numbers.hpp"
#include "exercises/reply_fields.hpp"
#include "exercises/session.hpp"
#include "exercises/task_texts.hpp"
#include "numlab/mechanisms/jansen_closure.hpp"

namespace numlab::exercises {

namespace {

using mechanisms::JansenAngles;
using mechanisms::JansenClosure;
constexpr double eps = std::numeric_limits<double>::epsilon();

struct Pose {
  double crank_angle;
  JansenAngles theta;
};

// Seed 000's start, four solved poses around the cycle, and two poses away from any root
// (jacobian_poses: with a variant, their crank angles and offsets drawn from it).
std::vector<Pose> poses(const Variant& variant, const mechanisms::JansenLeg& leg) {
  JansenAngles offset;
  offset << 0.3, -0.2, 0.5, -0.4, 0.25, -0.35, 0.45, -0.15;
  return jacobian_poses(variant, Pose{JansenClosure::seed_crank_angle, JansenClosure::seed_estimates()}, offset,
                        [&leg](double crank_angle) { return jansen_closed_form_angles(crank_angle, leg); });
}

using Battery = JacobianBattery<Pose>;

Battery battery_for(const Variant& variant) { return jacobian_battery<Pose>(variant, false, poses); }

std::string pose_text(const Pose& pose) {
  return fmt::format("crank_angle {:.4f} rad, theta = [{:.4f}]", pose.crank_angle,
                     fmt::join(pose.theta.data(), pose.theta.data() + 8, ", "));
}

// Rounding in f: each entry sums terms no larger than the links, so 1e3 eps of their sum is far
// above rounding and far below any wrong term.
double f_tolerance(const mechanisms::JansenLengths& L) { return 1e3 * eps * jansen_links_sum(L); }

std::vector<ReferenceTime> closure_time(const Pose& pose, const mechanisms::JansenLengths& L) {
  return {{"numlab JansenClosure (f and J)", residual_and_jacobian_seconds(JansenClosure(pose.crank_angle, L), pose.theta)}};
}

// An x row off by exactly b - a: the offset a where b belongs (a wrong_link detector).
std::optional<std::string> offset_mistake(int row, double got, double expected, const mechanisms::JansenLengths& L) {
  if (row % 2 == 1 && std::abs(std::abs(got - expected) - (L.b - L.a)) < 1e-6) {
    return fmt::format("f[{}] is off by exactly b - a = {:.4g}: the cosine rows use the offset a where b belongs (seed "
                       "000's printed eqs 23 and 25): X = li cos(ti) + b",
                       row, L.b - L.a);
  }
  return std::nullopt;
}

std::string f_hint() {
  return "compare the row with the task's equation: even rows are y components (sines), odd rows x components (cosines)";
}

// Under a variant, f from seed 000's lengths where the request's belong (a wrong_link detector).
std::optional<std::string> seed_lengths_used(const Eigen::VectorXd& f, const Pose& pose, const JansenVariant& lengths,
                                             double tolerance) {
  JansenClosure::Vector seed;
  JansenClosure(pose.crank_angle).residual(pose.theta, seed);
  return jansen_seed_lengths_used(f, Eigen::VectorXd(seed), lengths, tolerance);
}

Verdict check_f(Session& session, const Battery& battery) {
  const std::vector<Pose>& list = battery.list;
  const mechanisms::JansenLengths& L = battery.lengths.links;
  const double tolerance = f_tolerance(L);
  for (const Pose& pose : list) {
    const nlohmann::json reply = session.ask(jacobian_request(pose, battery.lengths));
    JansenClosure::Vector expected;
    JansenClosure(pose.crank_angle, L).residual(pose.theta, expected);
    session.expect({pose_text(pose), {{"f", to_json(Eigen::VectorXd(expected))}},
                    fmt::format("each f[i] within {} of numlab's JansenClosure above", sci(tolerance))});
    const Eigen::VectorXd f = vector_field(reply, "f", 8);
    for (int i = 0; i < 8; ++i) {
      if (std::abs(f(i) - expected(i)) <= tolerance) continue;
      return Verdict::fail(fmt::format("f[{}] = {}, expected {} from numlab's JansenClosure (seed 000 eq {}) at {}; {}, "
                                       "allowed |error| {} (1e3 eps times the links' sum {})",
                                       i, digits17(f(i)), digits17(expected(i)), i + 1, pose_text(pose),
                                       difference(f(i), expected(i)), sci(tolerance), jansen_links_sum(L)),
                           diagnose_residual({f, expected, pose.crank_angle, pose.theta, evaluator_of<JansenClosure>(L), tolerance,
                                              jansen_angle_name},
                                             {{"wrong_link", Specificity::exact,
                                               [&] { return seed_lengths_used(f, pose, battery.lengths, tolerance); }},
                                              {"wrong_link", Specificity::exact,
                                               [&] { return offset_mistake(i, f(i), expected(i), L); }}}),
                           f_hint());
    }
  }
  return Verdict::pass(closure_time(list.front(), L));
}

std::string J_hint(const Eigen::MatrixXd& got, const Eigen::MatrixXd& expected, const Pose& pose, int row, int col,
                   double tolerance, const mechanisms::JansenLengths& L) {
  if (const auto angle = column_from_angle(JansenClosure(pose.crank_angle, L), got, pose.theta, col, tolerance)) {
    return fmt::format("column {} (d/d {}) is evaluated at {}: a column from the wrong angle", col,
                       jansen_angle_name(col), jansen_angle_name(*angle));
  }
  if (std::abs(got(row, col) + expected(row, col)) <= tolerance) {
    return "a sign: d(l sin t)/dt = l cos t and d(l cos t)/dt = -l sin t";
  }
  return "an entry from the wrong link or a mistyped constant: J[i][k] is +-l cos or +-l sin of theta_(k+1), with the "
         "length l of that angle's link in row i";
}

// theta_(k+1)'s link is l(k+1): J's column k is +-l(k+1) sin or cos of theta_(k+1).
std::vector<ColumnLink> column_links(const mechanisms::JansenLengths& L) {
  return {{"l1", L.l1}, {"l2", L.l2}, {"l3", L.l3}, {"l4", L.l4}, {"l5", L.l5}, {"l6", L.l6}, {"l7", L.l7}, {"l8", L.l8}};
}

Verdict check_J(Session& session, const Battery& battery) {
  const std::vector<Pose>& list = battery.list;
  const mechanisms::JansenLengths& L = battery.lengths.links;
  for (const Pose& pose : list) {
    const nlohmann::json reply = session.ask(jacobian_request(pose, battery.lengths));
    JansenClosure::Matrix expected;
    JansenClosure(pose.crank_angle, L).jacobian(pose.theta, expected);
    // J's entries are at most a link long; rounding in them is a few eps of that.
    const double tolerance = 1e3 * eps * expected.cwiseAbs().maxCoeff();
    session.expect({pose_text(pose), {{"J", to_json(Eigen::MatrixXd(expected))}},
                    fmt::format("each J[i][k] within {} of numlab's analytic JansenClosure J above", sci(tolerance))});
    const Eigen::MatrixXd J = matrix_field(reply, "J", 8, 8);
    const Eigen::MatrixXd differences = central_differences(JansenClosure(pose.crank_angle, L), pose.theta);
    for (int i = 0; i < 8; ++i) {
      for (int k = 0; k < 8; ++k) {
        if (std::abs(J(i, k) - expected(i, k)) <= tolerance) continue;
        return Verdict::fail(
            fmt::format("J[{}][{}] = {}, expected {} ({}; d f[{}] / d {} from numlab's JansenClosure; "
                        "central differences of f give {}) at {}; allowed |error| {} (1e3 eps times max |J|)",
                        i, k, digits17(J(i, k)), digits17(expected(i, k)), difference(J(i, k), expected(i, k)), i,
                        jansen_angle_name(k), digits17(differences(i, k)), pose_text(pose),
                        sci(tolerance)),
            diagnose_jacobian({J, expected, pose.crank_angle, pose.theta, evaluator_of<JansenClosure>(L), tolerance,
                               jansen_angle_name, column_links(L)}),
            J_hint(J, expected, pose, i, k, tolerance, L));
      }
    }
  }
  return Verdict::pass(closure_time(list.front(), L));
}

}  // namespace

Exercise jansen_jacobian_exercise() {
  Exercise exercise;
  exercise.name = "jansen-jacobian";
  exercise.summary = "f and J of seed 000's 8-equation Jansen leg closure, entry by entry";
  exercise.task = task_text("jansen-jacobian");
  exercise.stubs.python = "    raise NotImplementedError(\"not implemented: f and J of the Jansen closure\")\n";
  exercise.stubs.cpp = "  throw std::runtime_error(\"not implemented: f and J of the Jansen closure\");\n";
  exercise.stubs.octave = "  error('not implemented: f and J of the Jansen closure');\n";
  exercise.variant_task = [](const Variant& variant) { return jansen_lengths_task_text(battery_for(variant).lengths); };
  exercise.battery = [](const Variant& variant) {
    const Battery list = battery_for(variant);
    return std::vector<Check>{
        {"f follows seed 000's closure equations (1)-(8) at 7 poses, to rounding (1e3 eps of the links' sum)", 1, [list](Session& session) { return check_f(session, list); }},
        {"J is the derivative of f: every entry matches numlab's analytic Jacobian (checked by central differences) at "
         "7 poses",
         2, [list](Session& session) { return check_J(session, list); }},
    };
  };
  return exercise;
}

}  // namespace numlab::exercises
