#include "exercises/linkage_detectors.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <optional>
#include <string>

#include "exercises/detectors/entry_mismatches.hpp"
#include "exercises/numbers.hpp"

namespace numlab::exercises {

namespace {

using detectors::differing;
using detectors::Entry;
using detectors::negated_entries;
using detectors::swapped_pair;
using detectors::transposed_within;
using mechanisms::ConstraintKind;
using mechanisms::LinkageModel;
using Evidence = std::optional<std::string>;

bool close(double a, double b, double tolerance) { return std::abs(a - b) <= tolerance; }

// The constraint each row comes from.
std::vector<int> row_constraints(const LinkageModel& model) {
  std::vector<int> rows;
  for (std::size_t k = 0; k < model.constraints().size(); ++k) {
    for (int r = 0; r < model.constraints()[k].rows(); ++r) rows.push_back(static_cast<int>(k));
  }
  return rows;
}

// The length a distance row of f uses: (d^2 - L'^2) / (2 L') = f solved for L' > 0.
double length_from_f(double f, double squared_distance) { return -f + std::sqrt(f * f + squared_distance); }

double squared_distance(const LinkageModel& model, const Eigen::VectorXd& q, int constraint) {
  const auto p = model.positions(q);
  const auto& c = model.constraints()[static_cast<std::size_t>(constraint)];
  return (p[static_cast<std::size_t>(c.joints[0])] - p[static_cast<std::size_t>(c.joints[1])]).squaredNorm();
}

// The rows where any sample's values differ from numlab's beyond tolerance.
template <typename Get>
std::vector<int> wrong_rows(int rows, const std::vector<LinkageClosureSample>& samples, Get row_differs) {
  std::vector<int> wrong;
  for (int i = 0; i < rows; ++i) {
    for (std::size_t s = 0; s < samples.size(); ++s) {
      if (row_differs(samples[s], s, i)) {
        wrong.push_back(i);
        break;
      }
    }
  }
  return wrong;
}

// Every wrong row a distance row whose entries all follow one other length L' (the same at every
// pose): the evidence names the first such row, its length and the file's.
Evidence wrong_length(const LinkageModel& model, const std::vector<int>& wrong,
                      const std::function<std::optional<double>(std::size_t sample, int row)>& length_at,
                      std::size_t samples, const std::string& what) {
  if (wrong.empty()) return std::nullopt;
  const auto constraint_of = row_constraints(model);
  std::string first;
  for (int row : wrong) {
    const auto& c = model.constraints()[static_cast<std::size_t>(constraint_of[static_cast<std::size_t>(row)])];
    if (c.kind != ConstraintKind::distance) return std::nullopt;
    std::optional<double> length;
    for (std::size_t s = 0; s < samples; ++s) {
      const auto here = length_at(s, row);
      if (!here) continue;
      if (*here <= 0.0) return std::nullopt;
      if (length && std::abs(*here - *length) > 1e-7 * c.length) return std::nullopt;
      if (!length) length = here;
    }
    if (!length || std::abs(*length - c.length) <= 1e-9 * c.length) return std::nullopt;
    if (first.empty()) {
      first = fmt::format("row {} ({}) follows length {:.10g} at every pose, the file says {:.10g}", row, c.name,
                          *length, c.length);
    }
  }
  return fmt::format("your {} {}{}: a wrong link length (take each length from the file once, by name)", what, first,
                     wrong.size() > 1 ? fmt::format(", and {} more rows a length of their own", wrong.size() - 1) : "");
}

}  // namespace

std::vector<Detector> linkage_f_detectors(const LinkageModel& model, const std::vector<LinkageClosureSample>& samples,
                                          double tolerance) {
  const int m = model.equation_count();
  const auto differs = [&](const LinkageClosureSample& s, std::size_t, int i) {
    return !close(s.f(i), s.f_expected(i), tolerance);
  };
  const std::vector<int> wrong = wrong_rows(m, samples, differs);
  std::vector<Detector> detectors;
  detectors.push_back({"f_sign", Specificity::exact, [&model, &samples, wrong, tolerance]() -> Evidence {
                         if (wrong.empty()) return std::nullopt;
                         for (const auto& s : samples) {
                           for (int i : wrong) {
                             if (!close(s.f(i), -s.f_expected(i), tolerance)) return std::nullopt;
                           }
                         }
                         return fmt::format("your f[{}] ({}) is numlab's with the opposite sign at every pose{}: write "
                                            "each row exactly as TASK.md does (the joint minus the base, the squared "
                                            "distance minus the squared length)",
                                            wrong.front(), model.row_name(wrong.front()),
                                            wrong.size() > 1 ? fmt::format(", and {} more rows", wrong.size() - 1) : "");
                       }});
  if (model.crank_driven()) {
    detectors.push_back({"degrees_for_radians", Specificity::exact, [&model, &samples, tolerance]() -> Evidence {
                           Eigen::VectorXd f;
                           for (const auto& s : samples) {
                             model.residual(s.q, s.driver_user, f);
                             if ((f - s.f).cwiseAbs().maxCoeff() > tolerance) return std::nullopt;
                           }
                           return fmt::format("your f is numlab's with the crank angle {:g} taken as radians: the "
                                              "request's driver is in degrees, t = driver * pi / 180",
                                              samples.front().driver_user);
                         }});
  }
  detectors.push_back({"wrong_link", Specificity::exact, [&model, &samples, wrong]() -> Evidence {
                         const auto constraint_of = row_constraints(model);
                         return wrong_length(
                             model, wrong,
                             [&](std::size_t s, int row) -> std::optional<double> {
                               const double d2 = squared_distance(model, samples[s].q,
                                                                  constraint_of[static_cast<std::size_t>(row)]);
                               return length_from_f(samples[s].f(row), d2);
                             },
                             samples.size(), "f");
                       }});
  return detectors;
}

std::vector<Detector> linkage_J_detectors(const LinkageModel& model, const std::vector<LinkageClosureSample>& samples,
                                          const std::vector<double>& tolerances) {
  const auto all = [&samples, &tolerances](const std::function<bool(const LinkageClosureSample&, double)>& holds) {
    for (std::size_t s = 0; s < samples.size(); ++s) {
      if (!holds(samples[s], tolerances[s])) return false;
    }
    return true;
  };
  std::vector<Detector> detectors;
  detectors.push_back({"transposed_jacobian", Specificity::exact, [all]() -> Evidence {
                         const bool holds = all([](const LinkageClosureSample& s, double tolerance) {
                           return transposed_within(s.J, s.J_expected, tolerance).has_value();
                         });
                         if (!holds) return std::nullopt;
                         return std::string("your J is numlab's transposed at every pose: J[i][k] = d f[i] / d q[k], "
                                            "row i for equation i, column k for unknown k");
                       }});
  detectors.push_back({"transposed_pair", Specificity::exact, [&model, &samples, all]() -> Evidence {
                         // The first entry above the diagonal nearer numlab's mirror entry than its own.
                         const auto& first = samples.front();
                         std::optional<Entry> pair;
                         for (const Entry& e : differing(first.J, first.J_expected, 0.0)) {
                           if (e.col > e.row && e.col < first.J.rows() &&
                               std::abs(first.J(e.row, e.col) - first.J_expected(e.col, e.row)) <
                                   std::abs(first.J(e.row, e.col) - first.J_expected(e.row, e.col))) {
                             pair = e;
                             break;
                           }
                         }
                         if (!pair) return std::nullopt;
                         const int row = pair->row, col = pair->col;
                         const bool holds = all([&](const LinkageClosureSample& s, double tolerance) {
                           return swapped_pair(s.J, s.J_expected, *pair, tolerance);
                         });
                         if (!holds || first.J.rows() != first.J.cols()) return std::nullopt;
                         return fmt::format("your J[{0}][{1}] and J[{1}][{0}] are swapped at every pose: J[{0}][{1}] "
                                            "= d f[{0}] / d {2} ({3})",
                                            row, col, model.column_name(col), model.row_name(row));
                       }});
  detectors.push_back({"derivative_sign", Specificity::exact, [&model, all]() -> Evidence {
                         int row = -1, col = -1;
                         const bool holds = all([&](const LinkageClosureSample& s, double tolerance) {
                           const auto negated = negated_entries(s.J, s.J_expected, tolerance);
                           if (!negated) return false;
                           if (row < 0 && !negated->empty()) row = negated->front().row, col = negated->front().col;
                           return true;
                         });
                         if (!holds || row < 0) return std::nullopt;
                         return fmt::format("every wrong entry of your J is numlab's with the opposite sign (the "
                                            "first: J[{}][{}], d ({}) / d {}): differentiate the row as TASK.md writes it",
                                            row, col, model.row_name(row), model.column_name(col));
                       }});
  detectors.push_back({"wrong_link", Specificity::exact, [&model, &samples, tolerances]() -> Evidence {
                         // A distance row of J is (p_i - p_j) / L: a wrong L scales the whole row.
                         const auto differs = [&](const LinkageClosureSample& s, std::size_t k, int i) {
                           return (s.J.row(i) - s.J_expected.row(i)).cwiseAbs().maxCoeff() > tolerances[k];
                         };
                         const auto wrong = wrong_rows(model.equation_count(), samples, differs);
                         const auto constraint_of = row_constraints(model);
                         return wrong_length(
                             model, wrong,
                             [&](std::size_t s, int row) -> std::optional<double> {
                               Eigen::Index k;
                               const double largest = samples[s].J_expected.row(row).cwiseAbs().maxCoeff(&k);
                               if (largest == 0.0 || samples[s].J(row, k) == 0.0) return std::nullopt;
                               const double ratio = samples[s].J(row, k) / samples[s].J_expected(row, k);
                               if ((samples[s].J.row(row) - ratio * samples[s].J_expected.row(row)).cwiseAbs().maxCoeff() >
                                   tolerances[s]) {
                                 return -1.0;  // not a scaled row: no length fits
                               }
                               const auto& c = model.constraints()[static_cast<std::size_t>(
                                   constraint_of[static_cast<std::size_t>(row)])];
                               return c.length / ratio;
                             },
                             samples.size(), "J");
                       }});
  detectors.push_back({"finite_difference_jacobian", Specificity::family, [all]() -> Evidence {
                         double worst = 0.0;
                         bool beyond_tolerance = false;  // numlab's own J (to rounding) is not a finite difference
                         const bool holds = all([&](const LinkageClosureSample& s, double tolerance) {
                           const double scale = s.J_expected.cwiseAbs().maxCoeff();
                           const double difference = (s.J - s.J_expected).cwiseAbs().maxCoeff();
                           worst = std::max(worst, difference / scale);
                           beyond_tolerance = beyond_tolerance || difference > tolerance;
                           return difference <= 1e-5 * scale;
                         });
                         if (!holds || !beyond_tolerance) return std::nullopt;
                         return fmt::format("your J agrees with numlab's analytic J to {:.1e} of max |J| at every pose, "
                                            "as differences of f do, but not to rounding: J must be analytic",
                                            worst);
                       }});
  return detectors;
}

std::vector<Detector> linkage_velocity_detectors(const Eigen::VectorXd& got, const Eigen::VectorXd& expected,
                                                 const Eigen::MatrixXd& J, const Eigen::VectorXd& phi_t, bool crank,
                                                 double tolerance) {
  const auto matches = [got, tolerance](const Eigen::VectorXd& candidate) {
    return (got - candidate).cwiseAbs().maxCoeff() <= tolerance;
  };
  std::vector<Detector> detectors;
  detectors.push_back({"derivative_sign", Specificity::exact, [matches, expected]() -> Evidence {
                         if (!matches(-expected)) return std::nullopt;
                         return std::string("your velocity is numlab's negated: J qdot = -dPhi/dt (the minus sign "
                                            "moves dPhi/dt to the right-hand side)");
                       }});
  if (crank) {
    detectors.push_back({"degrees_for_radians", Specificity::exact, [matches, expected]() -> Evidence {
                           const double per_degree = std::numbers::pi / 180.0;
                           if (!matches(expected * per_degree) && !matches(expected / per_degree)) return std::nullopt;
                           return std::string("your velocity is numlab's times pi/180 or 180/pi: it is dq/dt per "
                                              "radian of crank angle");
                         }});
  }
  detectors.push_back({"transposed_jacobian", Specificity::exact, [matches, J, phi_t]() -> Evidence {
                         if (J.rows() != J.cols()) return std::nullopt;
                         const Eigen::VectorXd transposed = J.transpose().fullPivLu().solve(-phi_t);
                         if (!matches(transposed)) return std::nullopt;
                         return std::string("your velocity solves J^T qdot = -dPhi/dt: your J is transposed");
                       }});
  return detectors;
}

}  // namespace numlab::exercises
