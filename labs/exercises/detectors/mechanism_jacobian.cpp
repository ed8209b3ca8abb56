#include "exercises/detectors/mechanism_jacobian.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <numbers>
#include <utility>

#include "exercises/detectors/entry_mismatches.hpp"
#include "exercises/linkage_checks.hpp"
#include "exercises/numbers.hpp"

namespace numlab::exercises {

namespace {

constexpr double pi = std::numbers::pi;

using detectors::differing;
using detectors::Entry;
using detectors::negated_entries;
using detectors::swapped_pair;
using detectors::transposed_within;

std::string entry_text(const JacobianEvidence& e, const Entry& entry) {
  return fmt::format("J[{}][{}] = {} where numlab's is {}", entry.row, entry.col, digits17(e.student(entry.row, entry.col)),
                     digits17(e.reference(entry.row, entry.col)));
}

// A relative match of a hypothesis to the student's numbers: 1e-6 of their scale (other roundings
// of pi and of the conversion stay far below it; a different cause stays far above it).
bool matches(const Eigen::MatrixXd& got, const Eigen::MatrixXd& hypothesis, double& worst) {
  worst = (got - hypothesis).cwiseAbs().maxCoeff();
  return worst <= 1e-6 * std::max(1.0, hypothesis.cwiseAbs().maxCoeff());
}

std::optional<std::string> transposed(const JacobianEvidence& e) {
  if ((e.reference - e.reference.transpose()).cwiseAbs().maxCoeff() <= e.tolerance) return std::nullopt;  // symmetric
  const auto worst = transposed_within(e.student, e.reference, e.tolerance);
  if (!worst) return std::nullopt;
  return fmt::format("your J is numlab's J transposed (J[i][k] equals numlab's J[k][i] to {}; J[0][1] = {} is numlab's "
                     "J[1][0]): row i holds f[i]'s derivatives, J[i][k] = d f[i] / d {} for k = 0",
                     sci(*worst), digits17(e.student(0, 1)), e.angle_name(0));
}

// J of a degrees mix-up carries the chain-rule factors (column k times angle k's scale), or not:
// both are tried. A mix that leaves J as it is (the driver alone, where J does not depend on it)
// explains nothing.
std::optional<std::string> degrees(const JacobianEvidence& e) {
  for (const AngleUnits& units : angle_units(static_cast<int>(e.theta.size()), e.angle_name)) {
    const ClosureValues values = evaluate_in(units, e.evaluate, e.driver, e.theta);
    for (const bool chain : {false, true}) {
      const Eigen::MatrixXd hypothesis = chain ? Eigen::MatrixXd(values.J * units.angle_scales.asDiagonal()) : values.J;
      if (chain && (units.angle_scales.array() == 1.0).all()) continue;
      if ((hypothesis - e.reference).cwiseAbs().maxCoeff() <= e.tolerance) continue;
      double worst = 0.0;
      if (!matches(e.student, hypothesis, worst)) continue;
      const double scale = units.angle_scales.cwiseAbs().maxCoeff() > 1.0 ? 180.0 / pi : pi / 180.0;
      return fmt::format("your J is numlab's J with {}{} (to {}; J[0][0] = {} where numlab's is {}): the request's "
                         "angles are radians, and sin and cos take radians",
                         units.what, chain ? fmt::format(", times {:.6g} by the chain rule", scale) : "", sci(worst),
                         digits17(e.student(0, 0)), digits17(e.reference(0, 0)));
    }
  }
  return std::nullopt;
}

// got's rows in another order: (your row, numlab's row) for each row that differs, when each equals
// exactly one other row of `expected` and those rows are the differing rows themselves (a
// permutation of them). Columns: the transposes; f: a one-column matrix.
std::optional<std::vector<std::pair<int, int>>> reordering(const Eigen::MatrixXd& got, const Eigen::MatrixXd& expected,
                                                           double tolerance) {
  const auto rows = static_cast<int>(got.rows());
  auto same = [&](int mine, int theirs) { return (got.row(mine) - expected.row(theirs)).cwiseAbs().maxCoeff() <= tolerance; };
  std::vector<bool> differs(static_cast<std::size_t>(rows)), taken(static_cast<std::size_t>(rows), false);
  for (int i = 0; i < rows; ++i) differs[static_cast<std::size_t>(i)] = !same(i, i);
  std::vector<std::pair<int, int>> moved;
  for (int i = 0; i < rows; ++i) {
    if (!differs[static_cast<std::size_t>(i)]) continue;
    int match = -1, matches_found = 0;
    for (int j = 0; j < rows; ++j) {
      if (j != i && same(i, j)) {
        match = j;
        ++matches_found;
      }
    }
    if (matches_found != 1 || !differs[static_cast<std::size_t>(match)] || taken[static_cast<std::size_t>(match)]) {
      return std::nullopt;
    }
    taken[static_cast<std::size_t>(match)] = true;
    moved.emplace_back(i, match);
  }
  if (moved.size() < 2) return std::nullopt;
  return moved;
}

// "your row 0 is numlab's row 1, your row 1 is numlab's row 0, ..." (the first four).
std::string reordering_text(const std::vector<std::pair<int, int>>& moved, const std::function<std::string(int)>& label) {
  std::string text;
  for (std::size_t m = 0; m < std::min<std::size_t>(4, moved.size()); ++m) {
    text += fmt::format("{}your {} is numlab's {}", m == 0 ? "" : ", ", label(moved[m].first), label(moved[m].second));
  }
  return text + (moved.size() > 4 ? fmt::format(", ... ({} in all)", moved.size()) : "");
}

std::optional<std::string> reordered(const JacobianEvidence& e) {
  if (const auto rows = reordering(e.student, e.reference, e.tolerance)) {
    return fmt::format("your J's rows are numlab's in another order ({}; each row to {}): row i holds the derivatives of "
                       "f[i], the task's equation i, in the task's order",
                       reordering_text(*rows, [](int i) { return fmt::format("row {}", i); }), sci(e.tolerance));
  }
  if (const auto columns = reordering(e.student.transpose(), e.reference.transpose(), e.tolerance)) {
    return fmt::format("your J's columns are numlab's in another order ({}; each column to {}): column k holds the "
                       "derivatives by the request's k-th angle, {} for k = 0, {} for k = 1, ...",
                       reordering_text(*columns, [&](int k) { return fmt::format("column {} (d/d {})", k, e.angle_name(k)); }),
                       sci(e.tolerance), e.angle_name(0), e.angle_name(1));
  }
  return std::nullopt;
}

std::optional<std::string> transposed_pair(const JacobianEvidence& e) {
  const auto wrong = differing(e.student, e.reference, e.tolerance);
  if (wrong.size() != 2) return std::nullopt;
  const Entry a = wrong[0], b = wrong[1];
  if (a.row != b.col || a.col != b.row || !swapped_pair(e.student, e.reference, a, e.tolerance)) {
    return std::nullopt;
  }
  return fmt::format("J[{0}][{1}] and J[{1}][{0}] are swapped ({2}, numlab's J[{1}][{0}]; {3}, numlab's J[{0}][{1}]): "
                     "J[i][k] = d f[i] / d {4} for row i's own equation",
                     a.row, a.col, digits17(e.student(a.row, a.col)), digits17(e.student(b.row, b.col)),
                     e.angle_name(a.col));
}

// Two columns j, k of the same rows whose entries are each other's: swapped outright, or with the
// two links' lengths swapped.
std::optional<std::string> mislabelled(const JacobianEvidence& e) {
  const auto wrong = differing(e.student, e.reference, e.tolerance);
  if (wrong.size() < 2) return std::nullopt;
  std::vector<int> columns;
  for (const Entry& entry : wrong) {
    if (std::find(columns.begin(), columns.end(), entry.col) == columns.end()) columns.push_back(entry.col);
  }
  if (columns.size() != 2) return std::nullopt;
  const int j = columns[0], k = columns[1];
  bool swapped = true, lengths_swapped = !e.links.empty();
  for (const Entry& entry : wrong) {
    const int other = entry.col == j ? k : j;
    const double got = e.student(entry.row, entry.col);
    if (std::abs(got - e.reference(entry.row, other)) > e.tolerance) swapped = false;
    if (lengths_swapped) {
      const double expected = e.reference(entry.row, entry.col);
      const auto& mine = e.links[static_cast<std::size_t>(entry.col)];
      const auto& theirs = e.links[static_cast<std::size_t>(other)];
      if (expected == 0.0 || std::abs(got - expected * theirs.length / mine.length) > 1e-9 * std::abs(got) + e.tolerance) {
        lengths_swapped = false;
      }
    }
  }
  if (swapped) {
    return fmt::format("the entries of columns {0} and {1} are swapped in row {2} ({3}, numlab's J[{2}][{1}]): column k "
                       "holds the derivatives by {4} for k = {0}, by {5} for k = {1}",
                       j, k, wrong[0].row, entry_text(e, wrong[0]), e.angle_name(j), e.angle_name(k));
  }
  if (lengths_swapped) {
    const auto& a = e.links[static_cast<std::size_t>(j)];
    const auto& b = e.links[static_cast<std::size_t>(k)];
    return fmt::format("the entries of columns {0} and {1} have each other's lengths ({2}: d/d {3} uses {4} = {5:.4g} and "
                       "d/d {6} uses {7} = {8:.4g}): entries under the wrong labels; each angle's entries take its own "
                       "link's length",
                       j, k, entry_text(e, wrong[0]), e.angle_name(j), b.name, b.length, e.angle_name(k), a.name,
                       a.length);
  }
  return std::nullopt;
}

std::optional<std::string> wrong_angle_column(const JacobianEvidence& e) {
  const auto wrong = differing(e.student, e.reference, e.tolerance);
  if (wrong.empty()) return std::nullopt;
  const int k = wrong.front().col;
  for (const Entry& entry : wrong) {
    if (entry.col != k) return std::nullopt;
  }
  for (int j = 0; j < e.theta.size(); ++j) {
    if (j == k) continue;
    Eigen::VectorXd swapped = e.theta;
    swapped(k) = e.theta(j);
    const Eigen::MatrixXd other = e.evaluate(e.driver, swapped).J;
    if ((e.student.col(k) - other.col(k)).cwiseAbs().maxCoeff() > e.tolerance) continue;
    return fmt::format("column {0} (d/d {1}) is evaluated at {2}: a column from the wrong angle ({3}, which is numlab's "
                       "entry with {1} = {2} = {4:.6g}); each column's sines and cosines take its own angle",
                       k, e.angle_name(k), e.angle_name(j), entry_text(e, wrong.front()), e.theta(j));
  }
  return std::nullopt;
}

std::optional<std::string> derivative_sign(const JacobianEvidence& e) {
  const auto negated = negated_entries(e.student, e.reference, e.tolerance);
  if (!negated || negated->empty()) return std::nullopt;
  const std::vector<Entry>& wrong = *negated;
  std::vector<int> rows;
  for (const Entry& entry : wrong) {
    if (std::find(rows.begin(), rows.end(), entry.row) == rows.end()) rows.push_back(entry.row);
  }
  std::string row_list;
  for (const int row : rows) row_list += (row_list.empty() ? "" : ", ") + std::to_string(row);
  return fmt::format("{} the opposite sign ({}; row{} {}): a sign: d(l sin t)/dt = l cos t and d(l cos t)/dt = -l sin t",
                     wrong.size() == 1 ? std::string("one entry has") : fmt::format("{} entries each have", wrong.size()),
                     entry_text(e, wrong.front()), rows.size() == 1 ? "" : "s", row_list);
}

// The differing entries of each column are one multiple r of numlab's (r not +-1): the column's
// link has a wrong length.
std::optional<std::string> wrong_link(const JacobianEvidence& e) {
  const auto wrong = differing(e.student, e.reference, e.tolerance);
  if (wrong.empty()) return std::nullopt;
  Entry first = wrong.front();
  double ratio = 0.0;
  for (const Entry& entry : wrong) {
    const double expected = e.reference(entry.row, entry.col);
    if (expected == 0.0 || entry.col != first.col) return std::nullopt;
    const double r = e.student(entry.row, entry.col) / expected;
    if (ratio == 0.0) ratio = r;
    if (std::abs(r - ratio) > 1e-9 * std::abs(ratio) + e.tolerance / std::abs(expected)) return std::nullopt;
  }
  if (std::abs(std::abs(ratio) - 1.0) < 1e-9) return std::nullopt;
  const std::string where = fmt::format("{}, {:.6g} times numlab's", entry_text(e, first), ratio);
  if (e.links.empty()) {
    return fmt::format("column {} (d/d {}) has a wrong length ({}): each entry is +-l sin or cos of {} with l the "
                       "length of that angle's link",
                       first.col, e.angle_name(first.col), where, e.angle_name(first.col));
  }
  const ColumnLink& link = e.links[static_cast<std::size_t>(first.col)];
  const double used = std::abs(ratio) * link.length;
  for (const ColumnLink& other : e.links) {
    if (&other != &link && std::abs(used - other.length) < 0.05) {
      return fmt::format("an entry from the wrong link: it has {} = {:.4g} where {} = {:.4g} belongs ({}; d/d {})",
                         other.name, other.length, link.name, link.length, where, e.angle_name(first.col));
    }
  }
  if (std::abs(used - link.length) >= 0.05 && sorted_digits(used) == sorted_digits(link.length)) {
    return fmt::format("a typed constant: the entry uses {:.1f} where {} = {:.4g}, digits transposed ({}); type each "
                       "length once, as a named constant",
                       used, link.name, link.length, where);
  }
  return fmt::format("a wrong length: the entries of column {} imply a length {:.6g} where {} = {:.4g} belongs ({})",
                     first.col, used, link.name, link.length, where);
}

// The error of a finite-difference J, E = J_fd - J, follows the reference's derivatives along
// column k: (h/2) d2f/dtheta_k2 for forward differences, (h^2/6) d3f/dtheta_k3 for central ones.
struct StepFit {
  const char* scheme;
  double step;
  double misfit;  // ||E - model|| / ||E||
};

std::optional<StepFit> fit_step(const JacobianEvidence& e, const Eigen::MatrixXd& error) {
  const int n = static_cast<int>(e.theta.size());
  const double delta = 1e-3;
  Eigen::MatrixXd second(error.rows(), n), third(error.rows(), n);
  const Eigen::MatrixXd at = e.evaluate(e.driver, e.theta).J;
  for (int k = 0; k < n; ++k) {
    Eigen::VectorXd up = e.theta, down = e.theta;
    up(k) += delta;
    down(k) -= delta;
    const Eigen::MatrixXd J_up = e.evaluate(e.driver, up).J, J_down = e.evaluate(e.driver, down).J;
    second.col(k) = (J_up.col(k) - J_down.col(k)) / (2.0 * delta);
    third.col(k) = (J_up.col(k) - 2.0 * at.col(k) + J_down.col(k)) / (delta * delta);
  }
  const double norm = error.norm();
  std::optional<StepFit> best;
  auto consider = [&](const char* scheme, const Eigen::MatrixXd& model, double coefficient, double step) {
    const double misfit = (error - coefficient * model).norm() / norm;
    if (!best || misfit < best->misfit) best = StepFit{scheme, step, misfit};
  };
  if (second.squaredNorm() > 0.0) {
    const double half_h = (error.cwiseProduct(second)).sum() / second.squaredNorm();
    consider(half_h > 0 ? "forward" : "backward", second, half_h, 2.0 * std::abs(half_h));
  }
  if (third.squaredNorm() > 0.0) {
    const double h2_6 = (error.cwiseProduct(third)).sum() / third.squaredNorm();
    if (h2_6 > 0) consider("central", third, h2_6, std::sqrt(6.0 * h2_6));
  }
  if (best && best->misfit <= 0.2) return best;
  return std::nullopt;
}

std::optional<std::string> finite_differences(const JacobianEvidence& e) {
  const Eigen::MatrixXd error = e.student - e.reference;
  const double scale = e.reference.cwiseAbs().maxCoeff();
  const double worst = error.cwiseAbs().maxCoeff();
  if (worst <= e.tolerance || worst > 1e-2 * scale) return std::nullopt;
  const auto wrong = differing(e.student, e.reference, e.tolerance);
  std::vector<int> columns;
  for (const Entry& entry : wrong) {
    if (std::find(columns.begin(), columns.end(), entry.col) == columns.end()) columns.push_back(entry.col);
  }
  if (static_cast<long>(columns.size()) < std::max<long>(2, (e.theta.size() + 1) / 2)) return std::nullopt;
  Entry largest = wrong.front();
  for (const Entry& entry : wrong) {
    if (std::abs(error(entry.row, entry.col)) > std::abs(error(largest.row, largest.col))) largest = entry;
  }
  const std::string agreement = fmt::format(
      "J agrees with numlab's analytic J only to {} relative ({}, {}), far above rounding ({}), in {} entries of {} "
      "columns",
      sci(worst / scale), entry_text(e, largest),
      difference(e.student(largest.row, largest.col), e.reference(largest.row, largest.col)), sci(e.tolerance),
      wrong.size(), columns.size());
  if (const auto fit = fit_step(e, error)) {
    return fmt::format("{}: the error is that of {} differences with a step h = {} (it fits the error to {:.0f}%): a "
                       "finite-difference J; the task asks for the analytic J (d(l sin t)/dt = l cos t, ...)",
                       agreement, fit->scheme, sci(fit->step), 100.0 * fit->misfit);
  }
  if (worst > 1e-5 * scale) return std::nullopt;
  return fmt::format("{}, about sqrt(eps) = 1.5e-08: the mark of a finite-difference J; the task asks for the analytic "
                     "J (d(l sin t)/dt = l cos t, ...)",
                     agreement);
}

std::optional<std::string> residual_sign(const ResidualEvidence& e) {
  const auto negated = negated_entries(e.student, e.reference, e.tolerance);
  if (!negated || negated->empty()) return std::nullopt;
  const auto wrong = static_cast<Eigen::Index>(negated->size());
  const int first = negated->front().row;
  return fmt::format("{} of f has the opposite sign (f[{}] = {} where numlab's is {}): f[i] is the task's equation as "
                     "written, left-hand side minus right-hand side",
                     wrong == e.student.size() ? "every entry" : fmt::format("{} entries", wrong), first,
                     digits17(e.student(first)), digits17(e.reference(first)));
}

std::string unknown_name(const ResidualEvidence& e, int k) { return e.angle_name ? e.angle_name(k) : fmt::format("angle {}", k); }

// One angle's terms entered with the opposite sign: f is a sum of +-l cos and +-l sin terms, so
// angle k's part of f is (f(theta) - f(theta with theta_k + pi)) / 2, and every differing entry is
// numlab's minus twice that part.
std::optional<std::string> term_sign(const ResidualEvidence& e) {
  std::vector<int> rows;
  for (int i = 0; i < e.student.size(); ++i) {
    if (std::abs(e.student(i) - e.reference(i)) > e.tolerance) rows.push_back(i);
  }
  if (rows.empty()) return std::nullopt;
  for (int k = 0; k < e.theta.size(); ++k) {
    Eigen::VectorXd turned = e.theta;
    turned(k) += pi;
    const Eigen::VectorXd part = (e.reference - e.evaluate(e.driver, turned).f) / 2.0;
    const bool flipped = std::all_of(rows.begin(), rows.end(), [&](int i) {
      return std::abs(part(i)) > e.tolerance && std::abs(e.student(i) - (e.reference(i) - 2.0 * part(i))) <= e.tolerance;
    });
    if (!flipped) continue;
    std::string row_list;
    for (const int row : rows) row_list += fmt::format("{}f[{}]", row_list.empty() ? "" : ", ", row);
    const int i = rows.front();
    return fmt::format("{0}'s term has the opposite sign in {1} (f[{2}] = {3} = numlab's {4} minus twice its {0} term "
                       "{5}): each link's vector enters its loop's equation with the sign the task's equation gives it",
                       unknown_name(e, k), row_list, i, digits17(e.student(i)), digits17(e.reference(i)),
                       digits17(part(i)));
  }
  return std::nullopt;
}

std::optional<std::string> residual_order(const ResidualEvidence& e) {
  const auto moved = reordering(e.student, e.reference, e.tolerance);
  if (!moved) return std::nullopt;
  return fmt::format("your f's entries are numlab's in another order ({}; each to {}): f[i] is the task's equation i, "
                     "in the task's order",
                     reordering_text(*moved, [](int i) { return fmt::format("f[{}]", i); }), sci(e.tolerance));
}

std::optional<std::string> residual_degrees(const ResidualEvidence& e) {
  for (const AngleUnits& units :
       angle_units(static_cast<int>(e.theta.size()), [&](int k) { return unknown_name(e, k); })) {
    const Eigen::VectorXd f = evaluate_in(units, e.evaluate, e.driver, e.theta).f;
    if ((f - e.reference).cwiseAbs().maxCoeff() <= e.tolerance) continue;  // the same f: it explains nothing
    const double worst = (e.student - f).cwiseAbs().maxCoeff();
    if (worst > 1e-6 * std::max(1.0, f.cwiseAbs().maxCoeff())) continue;
    return fmt::format("your f is numlab's f with {} (to {}; f[0] = {} where numlab's is {}): the request's angles are "
                       "radians, and sin and cos take radians",
                       units.what, sci(worst), digits17(e.student(0)), digits17(e.reference(0)));
  }
  return std::nullopt;
}

}  // namespace

std::vector<AngleUnits> angle_units(int unknowns, const std::function<std::string(int)>& angle_name) {
  const Eigen::VectorXd ones = Eigen::VectorXd::Ones(unknowns);
  const double to_degrees = 180.0 / pi, to_radians = pi / 180.0;
  std::vector<AngleUnits> units = {
      {1.0, ones * to_degrees, "the angles converted to degrees before sin and cos (sin(theta * 180/pi))"},
      {to_degrees, ones * to_degrees,
       "the angles and the driver converted to degrees before sin and cos (sin(theta * 180/pi))"},
      {1.0, ones * to_radians, "the angles read as degrees (sin(theta * pi/180), Octave's sind)"},
      {to_radians, ones * to_radians, "the angles and the driver read as degrees (sin(theta * pi/180), Octave's sind)"},
      {to_radians, ones, "the driver angle read as degrees (radians() or deg2rad of an angle already in radians)"},
      {to_degrees, ones, "the driver angle converted to degrees before sin and cos"}};
  for (int k = 0; k < unknowns; ++k) {
    for (const double scale : {to_degrees, to_radians}) {
      Eigen::VectorXd scales = ones;
      scales(k) = scale;
      units.push_back({1.0, scales,
                       scale == to_degrees ? fmt::format("{} alone converted to degrees before sin and cos", angle_name(k))
                                           : fmt::format("{} alone read as degrees (sind({}))", angle_name(k), angle_name(k))});
    }
  }
  return units;
}

ClosureValues evaluate_in(const AngleUnits& units, const ClosureEvaluator& evaluate, double driver,
                          const Eigen::VectorXd& theta) {
  return evaluate(driver * units.driver_scale, theta.cwiseProduct(units.angle_scales));
}

std::string sorted_digits(double length) {
  std::string digits = fmt::format("{:.1f}", length);
  std::sort(digits.begin(), digits.end());
  return digits;
}

std::vector<Detector> jacobian_detectors(const JacobianEvidence& evidence) {
  const JacobianEvidence* e = &evidence;
  return {
      {"transposed_jacobian", Specificity::exact, [e] { return transposed(*e); }},
      {"degrees_for_radians", Specificity::exact, [e] { return degrees(*e); }},
      {"transposed_pair", Specificity::exact, [e] { return transposed_pair(*e); }},
      {"mislabelled_entries", Specificity::exact, [e] { return mislabelled(*e); }},
      {"mislabelled_entries", Specificity::exact, [e] { return reordered(*e); }},
      {"wrong_angle_column", Specificity::exact, [e] { return wrong_angle_column(*e); }},
      {"derivative_sign", Specificity::exact, [e] { return derivative_sign(*e); }},
      {"wrong_link", Specificity::exact, [e] { return wrong_link(*e); }},
      {"finite_difference_jacobian", Specificity::exact, [e] { return finite_differences(*e); }},
  };
}

std::optional<Diagnosis> diagnose_jacobian(const JacobianEvidence& evidence) {
  return diagnose(jacobian_detectors(evidence));
}

std::optional<Diagnosis> diagnose_residual(const ResidualEvidence& evidence, std::vector<Detector> extra) {
  const ResidualEvidence* e = &evidence;
  std::vector<Detector> detectors = {
      {"f_sign", Specificity::exact, [e] { return residual_sign(*e); }},
      {"f_sign", Specificity::exact, [e] { return term_sign(*e); }},
      {"degrees_for_radians", Specificity::exact, [e] { return residual_degrees(*e); }},
      {"mislabelled_entries", Specificity::exact, [e] { return residual_order(*e); }},
  };
  for (Detector& detector : extra) detectors.push_back(std::move(detector));
  return diagnose(detectors);
}

}  // namespace numlab::exercises
