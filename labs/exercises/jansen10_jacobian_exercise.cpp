// jansen10-jacobian: the student's f and J of seed 001's 10-equation Jansen closure, against
// numlab's Jansen10Closure (with central differences of its f shown beside it).

#include <algorithm>
#include <array>
#include <cmath>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <limits>
#include <optional>

#include "exercises/detectors/mechanism_jacobian.hpp"
#include "exercises/exercise_list.hpp"
#include "exercises/jansen_poses.hpp"
#include "exercises/linkage_checks.hpp"
#include "exercises/numbers.hpp"
#include "exercises/reply_fields.hpp"
#include "exercises/session.hpp"
#include "exercises/task_texts.hpp"
#include "numlab/mechanisms/jansen10_closure.hpp"
#include "numlab/mechanisms/jansen_leg.hpp"
#include "numlab/mechanisms/jansen_solvers.hpp"

namespace numlab::exercises {

namespace {

using mechanisms::Jansen10Closure;
using mechanisms::JansenModel;
constexpr double eps = std::numeric_limits<double>::epsilon();

// The unknown theta_(k+3) is the direction of seed 001's vector r_(k+3).
struct Link {
  const char* vector;
  const char* joints;
  double length;
};

std::array<Link, 10> links(const JansenVariant& lengths) {
  const mechanisms::JansenLengths& L = lengths.links;
  const mechanisms::JansenFootLengths& foot = lengths.foot;
  return {{{"r3", "A->B", L.l1},
           {"r4", "B->P1", L.l2},
           {"r5", "B->C", L.l3},
           {"r6", "C->P1", L.l4},
           {"r7", "C->E", L.l5},
           {"r8", "P1->D", L.l7},
           {"r9", "E->D", L.l8},
           {"r10", "D->A", L.l6},
           {"r11", "D->F", foot.l9},
           {"r12", "F->E", foot.l10}}};
}

std::string angle_name(int k) { return mechanisms::jansen_angle_names(JansenModel::ten_equations)[static_cast<std::size_t>(k)]; }

// f's scale: the crank, the ten links and the offsets of P1.
double links_sum(const JansenVariant& lengths) {
  const mechanisms::JansenLengths& L = lengths.links;
  double sum = L.crank + L.a + L.b;
  for (const Link& link : links(lengths)) sum += link.length;
  return sum;
}

struct Pose {
  double crank_angle;
  Jansen10Closure::Vector theta;
};

// The model's start (seed 000's estimates read through their joints), four solved poses around
// the cycle, and two poses away from any root (jacobian_poses: with a variant, their crank angles
// and offsets drawn from it).
std::vector<Pose> poses(const Variant& variant, const mechanisms::JansenLeg& leg) {
  Jansen10Closure::Vector offset;
  offset << 0.3, -0.2, 0.5, -0.4, 0.25, -0.35, 0.45, -0.15, 0.2, -0.3;
  const Pose start{mechanisms::JansenClosure::seed_crank_angle, mechanisms::jansen_seed_estimates(JansenModel::ten_equations, leg)};
  return jacobian_poses(variant, start, offset,
                        [&leg](double crank_angle) { return jansen10_closed_form_angles(crank_angle, leg); });
}

using Battery = JacobianBattery<Pose>;

Battery battery_for(const Variant& variant) { return jacobian_battery<Pose>(variant, true, poses); }

// The 10-equation closure with the battery's lengths at `crank_angle`.
Jansen10Closure closure_at(const Battery& battery, double crank_angle) {
  return Jansen10Closure(crank_angle, battery.lengths.links, battery.lengths.foot);
}

std::string pose_text(const Pose& pose) {
  return fmt::format("crank_angle (theta2) {:.4f} rad, theta3 ... theta12 = [{:.4f}]", pose.crank_angle,
                     fmt::join(pose.theta.data(), pose.theta.data() + 10, ", "));
}

std::vector<ReferenceTime> closure_time(const Pose& pose, const Battery& battery) {
  return {{"numlab Jansen10Closure (f and J)", residual_and_jacobian_seconds(closure_at(battery, pose.crank_angle), pose.theta)}};
}

// Rows 0, 1, 6 and 7 start from P1->A = (b + li cos theta2, a + li sin theta2): one of them off by
// exactly b - a has the offsets swapped (a wrong_link detector).
std::optional<std::string> offset_mistake(int row, double got, double expected, const mechanisms::JansenLengths& L) {
  const bool from_crank = row == 0 || row == 1 || row == 6 || row == 7;
  if (from_crank && std::abs(std::abs(got - expected) - (L.b - L.a)) < 1e-6) {
    return fmt::format("f[{}] is off by exactly b - a = {:.4g}: the offsets of P1 are swapped: X = b + li cos(theta2) "
                       "with b = {:.6g}, Y = a + li sin(theta2) with a = {:.6g}",
                       row, L.b - L.a, L.b, L.a);
  }
  return std::nullopt;
}

std::string f_hint() {
  return "compare the row with the task's equation: even rows are x components (cosines), odd rows y components "
         "(sines), each loop's vectors with the signs of its direction";
}

// Under a variant, f from seed 000's lengths where the request's belong (a wrong_link detector).
std::optional<std::string> seed_lengths_used(const Eigen::VectorXd& f, const Pose& pose, const JansenVariant& lengths,
                                             double tolerance) {
  Jansen10Closure::Vector seed;
  Jansen10Closure(pose.crank_angle).residual(pose.theta, seed);
  return jansen_seed_lengths_used(f, Eigen::VectorXd(seed), lengths, tolerance);
}

Verdict check_f(Session& session, const Battery& battery) {
  const std::vector<Pose>& list = battery.list;
  const mechanisms::JansenLengths& L = battery.lengths.links;
  const double tolerance = 1e3 * eps * links_sum(battery.lengths);  // far above rounding, far below any wrong term
  for (const Pose& pose : list) {
    const nlohmann::json reply = session.ask(jacobian_request(pose, battery.lengths));
    Jansen10Closure::Vector expected;
    closure_at(battery, pose.crank_angle).residual(pose.theta, expected);
    session.expect({pose_text(pose), {{"f", to_json(Eigen::VectorXd(expected))}},
                    fmt::format("each f[i] within {} of numlab's Jansen10Closure above", sci(tolerance))});
    const Eigen::VectorXd f = vector_field(reply, "f", 10);
    for (int i = 0; i < 10; ++i) {
      if (std::abs(f(i) - expected(i)) <= tolerance) continue;
      return Verdict::fail(fmt::format("f[{}] = {}, expected {} from numlab's Jansen10Closure (seed 001's f{}, eq {}) at {}; "
                                       "{}, allowed |error| {} (1e3 eps times the links' sum {:.4g})",
                                       i, digits17(f(i)), digits17(expected(i)), i + 1, i + 8, pose_text(pose),
                                       difference(f(i), expected(i)), sci(tolerance), links_sum(battery.lengths)),
                           diagnose_residual({f, expected, pose.crank_angle, pose.theta,
                                              evaluator_of<Jansen10Closure>(L, battery.lengths.foot), tolerance, angle_name},
                                             {{"wrong_link", Specificity::exact,
                                               [&] { return seed_lengths_used(f, pose, battery.lengths, tolerance); }},
                                              {"wrong_link", Specificity::exact,
                                               [&] { return offset_mistake(i, f(i), expected(i), L); }}}),
                           f_hint());
    }
  }
  return Verdict::pass(closure_time(list.front(), battery));
}

// Column k's link, named as the detectors name it: "|r8|".
std::vector<ColumnLink> column_links(const JansenVariant& lengths) {
  std::vector<ColumnLink> named;
  for (const Link& link : links(lengths)) named.push_back({fmt::format("|{}|", link.vector), link.length});
  return named;
}

// The length a student's J[row][col] implies: even (x) rows hold -+L sin, odd (y) rows +-L cos.
// Nothing where that sine or cosine is too small to read a length from.
std::optional<double> length_used(double entry, double angle, int row) {
  const double trig = row % 2 == 0 ? std::sin(angle) : std::cos(angle);
  if (std::abs(trig) < 0.2) return std::nullopt;
  return std::abs(entry / trig);
}

std::string length_hint(double used, int col, const JansenVariant& lengths) {
  const auto list = links(lengths);
  const Link& link = list[static_cast<std::size_t>(col)];
  for (const Link& other : list) {
    if (&other != &link && std::abs(used - other.length) < 0.05) {
      return fmt::format("an entry from the wrong link: it has |{}| = {:.4g} ({}) where |{}| = {:.4g} ({}) belongs",
                         other.vector, other.length, other.joints, link.vector, link.length, link.joints);
    }
  }
  if (std::abs(used - link.length) >= 0.05 && sorted_digits(used) == sorted_digits(link.length)) {
    return fmt::format("a typed constant: the entry uses {:.1f} where |{}| = {:.4g} ({}), digits transposed, as in seed "
                       "001's Jacobian (20), whose rows 9-10 have 67.5 for 65.7; type each length once, as a named "
                       "constant",
                       used, link.vector, link.length, link.joints);
  }
  return fmt::format("an entry from the wrong link or a mistyped constant: the entry implies a length {:.4g}; {} is "
                     "|{}| = {:.4g} long",
                     used, link.joints, link.vector, link.length);
}

std::string J_hint(const Eigen::MatrixXd& got, const Eigen::MatrixXd& expected, const Pose& pose, int row, int col,
                   double tolerance, const Battery& battery) {
  if (const auto angle = column_from_angle(closure_at(battery, pose.crank_angle), got, pose.theta, col, tolerance)) {
    return fmt::format("column {} (d/d {}) is evaluated at {}: a column from the wrong angle", col, angle_name(col),
                       angle_name(*angle));
  }
  if (expected(row, col) == 0.0) {
    return fmt::format("f[{}] has no {} term, so J[{}][{}] is 0: a term in the wrong row or column", row,
                       angle_name(col), row, col);
  }
  if (std::abs(got(row, col) + expected(row, col)) <= tolerance) {
    return "a sign: d(l sin t)/dt = l cos t and d(l cos t)/dt = -l sin t";
  }
  if (const auto used = length_used(got(row, col), pose.theta(col), row)) return length_hint(*used, col, battery.lengths);
  return "an entry from the wrong link or a mistyped constant: J[i][k] is +-l sin or +-l cos of theta_(k+3), with the "
         "length l of that angle's link";
}

Verdict check_J(Session& session, const Battery& battery) {
  const std::vector<Pose>& list = battery.list;
  for (const Pose& pose : list) {
    const nlohmann::json reply = session.ask(jacobian_request(pose, battery.lengths));
    const Jansen10Closure closure = closure_at(battery, pose.crank_angle);
    Jansen10Closure::Matrix expected;
    closure.jacobian(pose.theta, expected);
    // J's entries are at most a link long; rounding in them is a few eps of that.
    const double tolerance = 1e3 * eps * expected.cwiseAbs().maxCoeff();
    session.expect({pose_text(pose), {{"J", to_json(Eigen::MatrixXd(expected))}},
                    fmt::format("each J[i][k] within {} of numlab's analytic Jansen10Closure J above", sci(tolerance))});
    const Eigen::MatrixXd J = matrix_field(reply, "J", 10, 10);
    const Eigen::MatrixXd differences = central_differences(closure, pose.theta);
    for (int i = 0; i < 10; ++i) {
      for (int k = 0; k < 10; ++k) {
        if (std::abs(J(i, k) - expected(i, k)) <= tolerance) continue;
        return Verdict::fail(
            fmt::format("J[{}][{}] = {}, expected {} ({}; d f[{}] / d {} from numlab's Jansen10Closure; "
                        "central differences of f give {}) at {}; allowed |error| {} (1e3 eps times max |J|)",
                        i, k, digits17(J(i, k)), digits17(expected(i, k)), difference(J(i, k), expected(i, k)), i,
                        angle_name(k), digits17(differences(i, k)), pose_text(pose),
                        sci(tolerance)),
            diagnose_jacobian({J, expected, pose.crank_angle, pose.theta,
                               evaluator_of<Jansen10Closure>(battery.lengths.links, battery.lengths.foot), tolerance,
                               angle_name, column_links(battery.lengths)}),
            J_hint(J, expected, pose, i, k, tolerance, battery));
      }
    }
  }
  return Verdict::pass(closure_time(list.front(), battery));
}

}  // namespace

Exercise jansen10_jacobian_exercise() {
  Exercise exercise;
  exercise.name = "jansen10-jacobian";
  exercise.summary = "f and J of seed 001's 10-equation Jansen leg closure, entry by entry";
  exercise.task = task_text("jansen10-jacobian");
  exercise.stubs.python = "    raise NotImplementedError(\"not implemented: f and J of the 10-equation Jansen closure\")\n";
  exercise.stubs.cpp = "  throw std::runtime_error(\"not implemented: f and J of the 10-equation Jansen closure\");\n";
  exercise.stubs.octave = "  error('not implemented: f and J of the 10-equation Jansen closure');\n";
  exercise.variant_task = [](const Variant& variant) { return jansen_lengths_task_text(battery_for(variant).lengths); };
  exercise.battery = [](const Variant& variant) {
    const Battery list = battery_for(variant);
    return std::vector<Check>{
        {"f follows seed 001's closure equations f1-f10 (its eqs 8-17) at 7 poses, to rounding (1e3 eps of the "
         "links' sum)",
         1, [list](Session& session) { return check_f(session, list); }},
        {"J is the derivative of f: every entry matches numlab's analytic Jacobian of the 10 equations at 7 poses", 2,
         [list](Session& session) { return check_J(session, list); }},
    };
  };
  return exercise;
}

}  // namespace numlab::exercises
