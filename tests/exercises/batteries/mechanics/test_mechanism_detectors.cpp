// The mechanism exercises' detectors (labs/exercises/detectors/) on constructed wrong answers:
// the Jansen closure's J transposed, in degrees, from forward differences, with a sign flipped, ...,
// and Newton loops with one mistake each (replayed by simulate_newton). Each must name its cause;
// none may fire on a correct answer.

#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <numbers>
#include <regex>

#include "exercises/detectors/mechanism_jacobian.hpp"
#include "exercises/detectors/mechanism_newton.hpp"
#include "exercises/jansen_poses.hpp"
#include "exercises/linkage_checks.hpp"
#include "numlab/mechanisms/jansen_closure.hpp"

using namespace numlab::exercises;
using numlab::mechanisms::JansenClosure;

namespace {

constexpr double eps = std::numeric_limits<double>::epsilon();
constexpr double pi = std::numbers::pi;
const double crank = 1.0;

// A pose away from any root, where f is large and every entry of J counts.
Eigen::VectorXd pose() {
  Eigen::VectorXd offset(8);
  offset << 0.3, -0.2, 0.5, -0.4, 0.25, -0.35, 0.45, -0.15;
  return Eigen::VectorXd(jansen_closed_form_angles(crank)) + offset;
}

ClosureValues at(const Eigen::VectorXd& theta, double driver = crank) { return evaluator_of<JansenClosure>()(driver, theta); }

std::vector<ColumnLink> links() {
  const numlab::mechanisms::JansenLengths L;
  return {{"l1", L.l1}, {"l2", L.l2}, {"l3", L.l3}, {"l4", L.l4}, {"l5", L.l5}, {"l6", L.l6}, {"l7", L.l7}, {"l8", L.l8}};
}

std::optional<Diagnosis> diagnose_J(const Eigen::MatrixXd& student) {
  const Eigen::VectorXd theta = pose();
  const Eigen::MatrixXd reference = at(theta).J;
  return diagnose_jacobian({student, reference, crank, theta, evaluator_of<JansenClosure>(),
                            1e3 * eps * reference.cwiseAbs().maxCoeff(), jansen_angle_name, links()});
}

// A forward (or central) difference J of numlab's f with step h.
Eigen::MatrixXd differences(double h, bool central) {
  const Eigen::VectorXd theta = pose();
  const Eigen::VectorXd f = at(theta).f;
  Eigen::MatrixXd D(8, 8);
  for (int k = 0; k < 8; ++k) {
    Eigen::VectorXd up = theta, down = theta;
    up(k) += h;
    down(k) -= h;
    D.col(k) = central ? Eigen::VectorXd((at(up).f - at(down).f) / (2 * h)) : Eigen::VectorXd((at(up).f - f) / h);
  }
  return D;
}

// The step the evidence estimates ("step h = 1.02e-06").
double estimated_step(const std::string& evidence) {
  std::smatch match;
  REQUIRE(std::regex_search(evidence, match, std::regex("step h = ([0-9.e+-]+)")));
  return std::stod(match[1]);
}

std::string cause_of(const std::optional<Diagnosis>& diagnosis) { return diagnosis ? diagnosis->cause : "(none)"; }
std::string shown(const std::optional<Diagnosis>& diagnosis) { return diagnosis ? diagnosis->evidence : "(none)"; }

}  // namespace

TEST_CASE("J detectors: none fires on numlab's own J, nor on it with rounding in every entry") {
  const Eigen::MatrixXd J = at(pose()).J;
  CHECK(cause_of(diagnose_J(J)) == "(none)");
  CHECK(cause_of(diagnose_J(J * (1.0 + 4 * eps))) == "(none)");
}

TEST_CASE("J detectors: the whole J transposed") {
  const auto diagnosis = diagnose_J(at(pose()).J.transpose());
  CHECK(cause_of(diagnosis) == "transposed_jacobian");
}

TEST_CASE("J detectors: one pair J[i][k] <-> J[k][i] swapped") {
  Eigen::MatrixXd J = at(pose()).J;
  REQUIRE(std::abs(J(2, 0) - J(0, 2)) > 1.0);
  std::swap(J(2, 0), J(0, 2));
  const auto diagnosis = diagnose_J(J);
  CHECK(cause_of(diagnosis) == "transposed_pair");
  CHECK(diagnosis->evidence.find("J[0][2] and J[2][0] are swapped") != std::string::npos);
}

TEST_CASE("J detectors: degrees for radians, sin(theta * 180/pi) and sind(theta) with its chain factor") {
  const Eigen::VectorXd theta = pose();
  CHECK(cause_of(diagnose_J(at(theta * 180.0 / pi).J)) == "degrees_for_radians");
  CHECK(cause_of(diagnose_J(at(theta * pi / 180.0).J * (pi / 180.0))) == "degrees_for_radians");
  CHECK(cause_of(diagnose_J(at(theta * pi / 180.0, crank * pi / 180.0).J)) == "degrees_for_radians");
}

TEST_CASE("J detectors: forward differences with h = 1e-6 and 1e-3, the step estimated from the error") {
  for (const double h : {1e-6, 1e-3}) {
    const auto diagnosis = diagnose_J(differences(h, false));
    INFO("h = " << h << ": " << shown(diagnosis));
    REQUIRE(cause_of(diagnosis) == "finite_difference_jacobian");
    CHECK(diagnosis->evidence.find("forward differences") != std::string::npos);
    CHECK(estimated_step(diagnosis->evidence) == Approx(h).epsilon(0.1));
  }
}

TEST_CASE("J detectors: central differences with h = 1e-4, and forward with h = 1e-8 (rounding-dominated)") {
  const auto central = diagnose_J(differences(1e-4, true));
  INFO(shown(central));
  REQUIRE(cause_of(central) == "finite_difference_jacobian");
  CHECK(central->evidence.find("central differences") != std::string::npos);
  CHECK(estimated_step(central->evidence) == Approx(1e-4).epsilon(0.1));
  const auto tiny = diagnose_J(differences(1e-8, false));
  INFO(shown(tiny));
  CHECK(cause_of(tiny) == "finite_difference_jacobian");
}

TEST_CASE("J detectors: one entry with the opposite sign") {
  Eigen::MatrixXd J = at(pose()).J;
  J(3, 2) = -J(3, 2);
  const auto diagnosis = diagnose_J(J);
  CHECK(cause_of(diagnosis) == "derivative_sign");
  CHECK(diagnosis->evidence.find("one entry has the opposite sign") != std::string::npos);
}

TEST_CASE("J detectors: a column from the wrong angle") {
  const Eigen::VectorXd theta = pose();
  Eigen::VectorXd swapped = theta;
  swapped(2) = theta(4);
  Eigen::MatrixXd J = at(theta).J;
  J.col(2) = at(swapped).J.col(2);
  const auto diagnosis = diagnose_J(J);
  CHECK(cause_of(diagnosis) == "wrong_angle_column");
  CHECK(diagnosis->evidence.find("column 2 (d/d theta3) is evaluated at theta5") != std::string::npos);
}

TEST_CASE("J detectors: a wrong link length, named as another link, a transposed constant, or a mistyped one") {
  const numlab::mechanisms::JansenLengths L;
  Eigen::MatrixXd J = at(pose()).J;
  Eigen::MatrixXd other = J;
  other.col(6) *= L.l5 / L.l7;  // theta7's entries with l5 = 39.4 for l7 = 39.3
  auto diagnosis = diagnose_J(other);
  CHECK(cause_of(diagnosis) == "wrong_link");
  CHECK(diagnosis->evidence.find("it has l5 = 39.4 where l7 = 39.3 belongs") != std::string::npos);
  other = J;
  other.col(5) *= 69.1 / L.l6;
  diagnosis = diagnose_J(other);
  CHECK(cause_of(diagnosis) == "wrong_link");
  CHECK(diagnosis->evidence.find("uses 69.1 where l6 = 61.9, digits transposed") != std::string::npos);
  other = J;
  other.col(5) *= 70.0 / L.l6;
  diagnosis = diagnose_J(other);
  CHECK(cause_of(diagnosis) == "wrong_link");
  CHECK(diagnosis->evidence.find("imply a length 70 where l6 = 61.9") != std::string::npos);
}

TEST_CASE("J detectors: entries under each other's labels, swapped outright or with each other's lengths") {
  const numlab::mechanisms::JansenLengths L;
  Eigen::MatrixXd J = at(pose()).J;
  Eigen::MatrixXd lengths = J;
  for (int row : {6, 7}) {
    lengths(row, 2) *= L.l5 / L.l3;
    lengths(row, 4) *= L.l3 / L.l5;
  }
  CHECK(cause_of(diagnose_J(lengths)) == "mislabelled_entries");
  Eigen::MatrixXd swapped = J;
  std::swap(swapped(6, 2), swapped(6, 4));
  CHECK(cause_of(diagnose_J(swapped)) == "mislabelled_entries");
}

TEST_CASE("f detectors: f negated, f in degrees, none on numlab's f") {
  const Eigen::VectorXd theta = pose();
  const Eigen::VectorXd f = at(theta).f;
  const double tolerance = 1e3 * eps * jansen_links_sum();
  auto diagnose_f = [&](const Eigen::VectorXd& student) {
    return diagnose_residual({student, f, crank, theta, evaluator_of<JansenClosure>(), tolerance});
  };
  CHECK(cause_of(diagnose_f(f)) == "(none)");
  CHECK(cause_of(diagnose_f(-f)) == "f_sign");
  CHECK(cause_of(diagnose_f(at(theta * 180.0 / pi).f)) == "degrees_for_radians");
}

// ---------------------------------------------------------------------------------------------
// Newton: a request at crank 30 deg from the closed-form pose 20 deg back, answered by a loop with
// one mistake.

namespace {

// numlab's Jansen closure with other lengths: a student's f and J with a wrong constant.
ClosureEvaluator with_lengths(const numlab::mechanisms::JansenLengths& lengths) {
  return [lengths](double driver, const Eigen::VectorXd& theta) {
    JansenClosure::Vector f;
    JansenClosure::Matrix J;
    JansenClosure(driver, lengths).residual_and_jacobian(JansenClosure::Vector(theta), f, J);
    return ClosureValues{Eigen::VectorXd(f), Eigen::MatrixXd(J)};
  };
}

NewtonEvidence newton_reply(const NewtonLoop& loop, const Eigen::VectorXd* start_override = nullptr,
                            ClosureEvaluator student_closure = evaluator_of<JansenClosure>()) {
  NewtonEvidence e;
  e.driver = 30.0 * degrees;
  e.start = Eigen::VectorXd(jansen_closed_form_angles(10.0 * degrees));
  e.tolerance = 1e-10;
  e.max_iterations = 20;
  e.evaluate = evaluator_of<JansenClosure>();
  e.seed_start = Eigen::VectorXd(JansenClosure::seed_estimates());
  e.exact = Eigen::VectorXd(jansen_closed_form_angles(e.driver));
  e.rounding = 1e3 * eps * jansen_links_sum();
  e.links_sum = jansen_links_sum();
  e.angle_name = jansen_angle_name;
  Eigen::VectorXd end;
  e.trace = simulate_newton(student_closure, e.driver, start_override ? *start_override : e.start, e.tolerance,
                            e.max_iterations, loop, &end);
  e.x = end;
  e.iterations = static_cast<long long>(e.trace->size());
  e.status = student_closure(e.driver, end).f.lpNorm<Eigen::Infinity>() <= e.tolerance ? "converged" : "max_iterations";
  return e;
}

}  // namespace

TEST_CASE("Newton detectors: none fires on numlab's own Newton") {
  const NewtonEvidence e = newton_reply({});
  REQUIRE(e.status == "converged");
  CHECK(cause_of(diagnose_newton(e)) == "(none)");
}

TEST_CASE("Newton detectors: x <- x - dx, the trace before the step, x never updated, J transposed") {
  NewtonLoop minus;
  minus.minus_step = true;
  CHECK(cause_of(diagnose_newton(newton_reply(minus))) == "step_sign");
  NewtonLoop before;
  before.record_before = true;
  CHECK(cause_of(diagnose_newton(newton_reply(before))) == "trace_before_step");
  NewtonLoop frozen;
  frozen.never_update = true;
  CHECK(cause_of(diagnose_newton(newton_reply(frozen))) == "x_never_updated");
  NewtonLoop transposed;
  transposed.jacobian = [](const Eigen::VectorXd&, const Eigen::MatrixXd& J) { return Eigen::MatrixXd(J.transpose()); };
  CHECK(cause_of(diagnose_newton(newton_reply(transposed))) == "transposed_jacobian");
}

TEST_CASE("Newton detectors: a forward-difference J with h = 1e-4, a J with one wrong length (quadratic convergence lost)") {
  NewtonLoop forward;
  forward.jacobian = [](const Eigen::VectorXd& x, const Eigen::MatrixXd& J) {
    Eigen::MatrixXd D = J;
    const auto f = evaluator_of<JansenClosure>();
    for (int k = 0; k < 8; ++k) {
      Eigen::VectorXd up = x;
      up(k) += 1e-4;
      D.col(k) = (f(30.0 * degrees, up).f - f(30.0 * degrees, x).f) / 1e-4;
    }
    return D;
  };
  const auto fd = diagnose_newton(newton_reply(forward));
  INFO(shown(fd));
  CHECK(cause_of(fd) == "finite_difference_jacobian");
  NewtonLoop typo;
  typo.jacobian = [](const Eigen::VectorXd&, const Eigen::MatrixXd& J) {
    Eigen::MatrixXd wrong = J;
    wrong.col(5) *= 69.1 / 61.9;
    return wrong;
  };
  const auto family = diagnose_newton(newton_reply(typo));
  INFO(shown(family));
  CHECK(cause_of(family) == "wrong_jacobian");
  CHECK(family->specificity == Specificity::family);
}

TEST_CASE("Newton detectors: restart from the seed's guess, rounded constants in f") {
  const Eigen::VectorXd seed = JansenClosure::seed_estimates();
  CHECK(cause_of(diagnose_newton(newton_reply({}, &seed))) == "restart_from_seed_guess");
  numlab::mechanisms::JansenLengths rounded;
  rounded.l6 = 62.0;
  CHECK(cause_of(diagnose_newton(newton_reply({}, nullptr, with_lengths(rounded)))) == "rounded_constants");
}

TEST_CASE("Newton detectors: stop tests (signed, pair sum), converged at the limit, one iteration too many") {
  NewtonEvidence e = newton_reply({});
  const JansenClosure closure(e.driver);
  // Signed: every f_i = -0.5 passes max f_i <= tol.
  e.x = Eigen::VectorXd(start_with_residual(closure, JansenClosure::Vector(*e.exact), JansenClosure::Vector::Constant(-0.5)));
  e.status = "converged";
  e.iterations = 0;
  e.trace = std::vector<TraceRow>{};
  auto diagnosis = diagnose_newton(e);
  CHECK(cause_of(diagnosis) == "stop_test");
  CHECK(diagnosis->evidence.find("signed stop test") != std::string::npos);
  // Pair sum: +0.05, -0.05 in each pair.
  JansenClosure::Vector cancelling;
  cancelling << 0.05, -0.05, 0.05, -0.05, 0.05, -0.05, 0.05, -0.05;
  e.x = Eigen::VectorXd(start_with_residual(closure, JansenClosure::Vector(*e.exact), cancelling));
  diagnosis = diagnose_newton(e);
  CHECK(cause_of(diagnosis) == "stop_test");
  CHECK(diagnosis->evidence.find("pair") != std::string::npos);
  // Stopped by max_iterations = 2 from far away, reported converged.
  NewtonEvidence limited = newton_reply({});
  limited.max_iterations = 2;
  limited.start = Eigen::VectorXd(jansen_closed_form_angles(-30.0 * degrees));
  Eigen::VectorXd end;
  limited.trace = simulate_newton(limited.evaluate, limited.driver, limited.start, limited.tolerance, 2, {}, &end);
  limited.x = end;
  limited.iterations = 2;
  limited.status = "converged";
  CHECK(cause_of(diagnose_newton(limited)) == "converged_when_stopped");
  limited.iterations = 3;
  limited.status = "max_iterations";
  CHECK(cause_of(diagnose_newton(limited)) == "one_iteration_too_many");
}

TEST_CASE("Newton detectors: angles in degrees, one angle reported as pi minus itself") {
  NewtonEvidence e = newton_reply({});
  e.x = *e.exact * (180.0 / pi);  // a root of f(theta * pi/180): sind on radians
  CHECK(cause_of(diagnose_newton(e)) == "degrees_for_radians");
  e = newton_reply({});
  e.x(4) = pi - e.x(4);
  const auto diagnosis = diagnose_newton(e);
  CHECK(cause_of(diagnosis) == "angle_from_other_axis");
  CHECK(diagnosis->evidence.find("theta5 is reported as pi minus the angle") != std::string::npos);
}

// ---------------------------------------------------------------------------------------------
// Degrees in one place only, entries in another order, one link's term with the opposite sign.

TEST_CASE("J detectors: one angle alone in degrees, with or without its chain factor") {
  Eigen::VectorXd theta = pose();
  theta(6) *= pi / 180.0;  // sind(theta7) where sin(theta7) belongs
  const Eigen::MatrixXd sind = at(theta).J;
  auto diagnosis = diagnose_J(sind);
  CHECK(cause_of(diagnosis) == "degrees_for_radians");
  CHECK(shown(diagnosis).find("theta7 alone read as degrees") != std::string::npos);
  Eigen::MatrixXd chained = sind;
  chained.col(6) *= pi / 180.0;
  CHECK(cause_of(diagnose_J(chained)) == "degrees_for_radians");
}

TEST_CASE("J detectors: whole rows or whole columns in another order are mislabelled entries") {
  const Eigen::MatrixXd J = at(pose()).J;
  Eigen::MatrixXd rows = J;
  rows.row(2) = J.row(3);  // loop 2's y row first
  rows.row(3) = J.row(2);
  rows.row(6) = J.row(7);
  rows.row(7) = J.row(6);
  auto diagnosis = diagnose_J(rows);
  CHECK(cause_of(diagnosis) == "mislabelled_entries");
  CHECK(shown(diagnosis).find("your row 2 is numlab's row 3") != std::string::npos);
  Eigen::MatrixXd columns = J;  // theta2, theta4, theta8 rotated
  columns.col(1) = J.col(3);
  columns.col(3) = J.col(7);
  columns.col(7) = J.col(1);
  diagnosis = diagnose_J(columns);
  CHECK(cause_of(diagnosis) == "mislabelled_entries");
  CHECK(shown(diagnosis).find("your column 3 (d/d theta4) is numlab's column 7 (d/d theta8)") != std::string::npos);
  // Two rows that each match no other row are no reordering.
  Eigen::MatrixXd scaled = J;
  scaled.row(2) *= 1.5;
  scaled.row(3) *= 1.5;
  CHECK(cause_of(diagnose_J(scaled)) != "mislabelled_entries");
}

TEST_CASE("f detectors: the crank alone in degrees, one angle in degrees, entries in another order, one link's sign") {
  const Eigen::VectorXd theta = pose();
  const Eigen::VectorXd f = at(theta).f;
  const double tolerance = 1e3 * eps * jansen_links_sum();
  auto diagnose_f = [&](const Eigen::VectorXd& student) {
    return diagnose_residual({student, f, crank, theta, evaluator_of<JansenClosure>(), tolerance, jansen_angle_name});
  };
  // radians(crank) on a crank already in radians.
  auto diagnosis = diagnose_f(at(theta, crank * pi / 180.0).f);
  CHECK(cause_of(diagnosis) == "degrees_for_radians");
  CHECK(shown(diagnosis).find("the driver angle read as degrees") != std::string::npos);
  Eigen::VectorXd one = theta;
  one(2) *= 180.0 / pi;
  diagnosis = diagnose_f(at(one).f);
  CHECK(cause_of(diagnosis) == "degrees_for_radians");
  CHECK(shown(diagnosis).find("theta3 alone converted to degrees") != std::string::npos);
  // Each loop's equations in the order (y, x): f's entries permuted in pairs.
  Eigen::VectorXd swapped = f;
  for (int i = 0; i < 8; i += 2) std::swap(swapped(i), swapped(i + 1));
  diagnosis = diagnose_f(swapped);
  CHECK(cause_of(diagnosis) == "mislabelled_entries");
  CHECK(shown(diagnosis).find("your f[0] is numlab's f[1]") != std::string::npos);
  // l5's vector (theta5, rows 6 and 7 only) entered with a plus sign: numlab's closure with l5 negated.
  numlab::mechanisms::JansenLengths flipped;
  flipped.l5 = -flipped.l5;
  JansenClosure::Vector plus;
  JansenClosure(crank, flipped).residual(JansenClosure::Vector(theta), plus);
  diagnosis = diagnose_f(Eigen::VectorXd(plus));
  CHECK(cause_of(diagnosis) == "f_sign");
  CHECK(shown(diagnosis).find("theta5's term has the opposite sign in f[6], f[7]") != std::string::npos);
  // A wrong length for l5 is not a sign.
  numlab::mechanisms::JansenLengths longer;
  longer.l5 = 41.0;
  JansenClosure(crank, longer).residual(JansenClosure::Vector(theta), plus);
  CHECK(cause_of(diagnose_f(Eigen::VectorXd(plus))) == "(none)");
}

namespace {

// Every request of newton_reply: numlab's count where the stop rule decides it.
std::optional<long long> decided_count(const NewtonEvidence& e) {
  const auto rows = simulate_newton(e.evaluate, e.driver, e.start, e.tolerance, e.max_iterations, {});
  const double start_residual = e.evaluate(e.driver, e.start).f.lpNorm<Eigen::Infinity>();
  return decided_iterations(rows, start_residual, e.tolerance, e.max_iterations,
                            !rows.empty() && rows.back().residual_inf <= e.tolerance, 1e-6, e.rounding / 10.0);
}

}  // namespace

TEST_CASE("decided_iterations: the count where no residual is near the tolerance, nothing where one is") {
  const std::vector<TraceRow> rows = {{1e-2, 0.1}, {1e-5, 1e-2}, {1e-11, 1e-5}};
  CHECK(decided_iterations(rows, 1.0, 1e-9, 20, true, 1e-6, 1e-14) == 3);
  CHECK(decided_iterations(rows, 1.0, 1e-11, 20, true, 1e-6, 1e-14) == std::nullopt);  // 1e-11 is the tolerance
  CHECK(decided_iterations(rows, 1.0, 1.8e-11, 20, true, 1e-6, 1e-14) == std::nullopt);  // within a factor 2 of it
  CHECK(decided_iterations(rows, 1.0, 2.1e-11, 20, true, 1e-6, 1e-14) == 3);            // just beyond it
  CHECK(decided_iterations(rows, 1.0, 1e-12, 3, false, 1e-6, 1e-14) == 3);             // stopped at the limit
  CHECK(decided_iterations(rows, 1.0, 1e-12, 20, false, 1e-6, 1e-14) == std::nullopt);  // stopped for another reason
}

TEST_CASE("Newton detectors: one step after the residual passed, not at the limit, is one iteration too many") {
  NewtonEvidence e = newton_reply({});
  e.decided_iterations = decided_count(e);
  REQUIRE(e.decided_iterations == static_cast<long long>(e.trace->size()));
  CHECK(cause_of(diagnose_newton(e)) == "(none)");
  // The extra step: Newton's rows, then one more from the converged x.
  Eigen::VectorXd x = e.x;
  const ClosureValues values = e.evaluate(e.driver, x);
  const Eigen::VectorXd dx = values.J.partialPivLu().solve(-values.f);
  x += dx;
  e.trace->push_back({e.evaluate(e.driver, x).f.lpNorm<Eigen::Infinity>(), dx.lpNorm<Eigen::Infinity>()});
  e.x = x;
  e.iterations += 1;
  const auto diagnosis = diagnose_newton(e);
  CHECK(cause_of(diagnosis) == "one_iteration_too_many");
  CHECK(shown(diagnosis).find("your trace is numlab's for " + std::to_string(*e.decided_iterations) + " rows") !=
        std::string::npos);
  // Without a decided count (a residual near the tolerance) it is not named.
  e.decided_iterations.reset();
  CHECK(cause_of(diagnose_newton(e)) != "one_iteration_too_many");
}

TEST_CASE("Newton detectors: x frozen while the trace records the first step again and again") {
  NewtonEvidence e = newton_reply({});
  const ClosureValues values = e.evaluate(e.driver, e.start);
  const Eigen::VectorXd dx = values.J.partialPivLu().solve(-values.f);
  const TraceRow row{e.evaluate(e.driver, e.start + dx).f.lpNorm<Eigen::Infinity>(), dx.lpNorm<Eigen::Infinity>()};
  e.trace = std::vector<TraceRow>(static_cast<std::size_t>(e.max_iterations), row);
  e.x = e.start + dx;  // the new angles kept aside, returned at the end
  e.iterations = e.max_iterations;
  e.status = "max_iterations";
  const auto diagnosis = diagnose_newton(e);
  CHECK(cause_of(diagnosis) == "x_never_updated");
  CHECK(shown(diagnosis).find("repeats row 1") != std::string::npos);
}

TEST_CASE("Newton detectors: the crank in degrees, and a closure with a constant angle typed in degrees") {
  const ClosureEvaluator radians_of_radians = [](double driver, const Eigen::VectorXd& theta) {
    return evaluator_of<JansenClosure>()(driver * pi / 180.0, theta);
  };
  auto diagnosis = diagnose_newton(newton_reply({}, nullptr, radians_of_radians));
  CHECK(cause_of(diagnosis) == "degrees_for_radians");
  CHECK(shown(diagnosis).find("the driver angle read as degrees") != std::string::npos);
  // A slip the exercise lists (here l6 = 61.9 read as another constant: any other closure will do):
  // a Newton on it that does not converge is named by its trace.
  numlab::mechanisms::JansenLengths other;
  other.l6 = 20.0;
  const ClosureEvaluator slipped = with_lengths(other);
  NewtonEvidence e = newton_reply({}, nullptr, slipped);
  REQUIRE(e.status != "converged");
  CHECK(cause_of(diagnose_newton(e)) != "degrees_for_radians");
  e.constant_angle_slips = {{"the test's slip", slipped}};
  diagnosis = diagnose_newton(e);
  CHECK(cause_of(diagnosis) == "degrees_for_radians");
  CHECK(shown(diagnosis).find("is numlab's Newton on that closure") != std::string::npos);
  // The slip listed, numlab's own Newton: nothing.
  NewtonEvidence correct = newton_reply({});
  correct.constant_angle_slips = {{"the test's slip", slipped}};
  CHECK(cause_of(diagnose_newton(correct)) == "(none)");
}
