// Lab `fit`: seed 001's curve_fit (the normal equations), judged by NIST's certified digits; why
// centring and scaling x rescues it; the Jansen foot path's arcs fitted (seed 001 Figure 3); and
// the degree sweep that shows where each method stops being trustworthy.

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "output/exit_codes.hpp"
#include "output/files.hpp"
#include "output/format.hpp"
#include "methods/data_dir.hpp"
#include "output/fit_charts.hpp"
#include "scenes/foot_path.hpp"
#include "lessons/lab.hpp"
#include "numlab/fitting/data_set.hpp"
#include "numlab/fitting/log_relative_error.hpp"
#include "numlab/fitting/normal_equations.hpp"
#include "numlab/fitting/polynomial_fit.hpp"
#include "numlab/fitting/reference_fits.hpp"
#include "numlab/fitting/scaled_basis.hpp"
#include "numlab/linalg/measures.hpp"

namespace numlab::cli {

namespace {

using fitting::FitMethod;
using fitting::NormalSolver;

struct LabMethod {
  std::string label;
  FitMethod method;
  NormalSolver solver;
};

const std::vector<LabMethod>& lab_methods() {
  static const std::vector<LabMethod> methods = {{"normal", FitMethod::normal, NormalSolver::gepp},
                                                 {"normal (Gauss-Seidel)", FitMethod::normal, NormalSolver::gauss_seidel},
                                                 {"normal-scaled", FitMethod::normal_scaled, NormalSolver::gepp},
                                                 {"gsl", FitMethod::gsl, NormalSolver::gepp},
                                                 {"eigen-qr", FitMethod::eigen_qr, NormalSolver::gepp}};
  return methods;
}

fitting::PolynomialFit fit_by(const LabMethod& m, const Eigen::VectorXd& x, const Eigen::VectorXd& y, int degree) {
  fitting::FitOptions options;
  options.method = m.method;
  options.solver = m.solver;
  options.degree = degree;
  return fitting::fit_polynomial(x, y, options);
}

// Digits of a fit against a reference; 0 when the method gave no coefficients.
double digits_of(const fitting::PolynomialFit& fit, const Eigen::VectorXd& reference) {
  return fit.coefficients.size() > 0 ? fitting::min_log_relative_error(fit.coefficients, reference) : 0.0;
}

fitting::DataSet nist_set(const std::string& name) {
  return fitting::read_nist_data(nist_data_dir() + "/" + name + ".dat");
}

Eigen::VectorXd certified_of(const fitting::DataSet& data) {
  return Eigen::Map<const Eigen::VectorXd>(data.certified->parameters.data(),
                                           static_cast<Eigen::Index>(data.certified->parameters.size()));
}

void normal_equations_step(LabSession& session) {
  if (!session.begin_step("Seed 001's curve_fit: the normal equations",
                          "A degree-D least-squares polynomial minimises sum (y_i - b0 - b1 x_i - ... - bD x_i^D)^2. "
                          "Setting the derivatives to zero gives D+1 linear equations whose matrix holds the power sums "
                          "S_k = sum x_i^k: entry (j, k) is S_(j+k). That is (V^T V) b = V^T y for the Vandermonde matrix "
                          "V. Here is the system for NIST's Pontius data (load-cell calibration, x up to 3e6, degree 2), "
                          "then its solution by the hand-written GEPP.")) return;
  const fitting::DataSet pontius = nist_set("Pontius");
  const fitting::NormalEquations system = fitting::build_normal_equations(pontius.x, pontius.y, 2);
  Table table({"row", "S_j", "S_(j+1)", "S_(j+2)", "sum x^j y"});
  for (Eigen::Index j = 0; j < 3; ++j) {
    table.add_row({std::to_string(j), scientific(system.matrix(j, 0)), scientific(system.matrix(j, 1)),
                   scientific(system.matrix(j, 2)), scientific(system.rhs(j))});
  }
  session.show(table, "pontius-normal-equations");
  const fitting::PolynomialFit fit = fit_by(lab_methods()[0], pontius.x, pontius.y, 2);
  session.say(fmt::format(
      "The entries run from {:.2g} to {:.2g}: kappa_1(V^T V) is about {:.2g} as it stands (numlab's estimate from "
      "the LU factors). Scaling its rows and columns to a unit "
      "diagonal (which changes nothing in elimination's rounding, only the units of the unknowns) leaves {:.3g}; "
      "that is the number that predicts lost digits, and numlab reports it as condition_estimate. The fit keeps "
      "{:.1f} digits of NIST's certified values.",
      system.matrix.cwiseAbs().minCoeff(), system.matrix.cwiseAbs().maxCoeff(), fit.condition_unscaled,
      fit.condition_estimate, digits_of(fit, certified_of(pontius))));
}

// What the kappa columns of the NIST table and the degree sweeps are: the fit's own
// condition_estimate, the number `numlab fit --method M` prints for the same matrix.
std::string kappa_columns_legend() {
  return "The kappa columns are the condition numbers numlab fit prints for the same matrix (its "
         "condition_estimate). 'kappa normal' and 'kappa scaled': an estimate of kappa_1 (Hager-Higham, from the LU "
         "factors) of the normal matrix, V^T V or V^T V in t, with rows and columns scaled to a unit diagonal. "
         "'kappa gsl': GSL's 1/rcond, kappa_2 of V after GSL balances its columns by powers of two.";
}

// Step 2's reading of the NIST table, from its digits.
std::string nist_sentence(const std::map<std::string, std::map<std::string, double>>& lre,
                          const fitting::PolynomialFit& wampler_normal) {
  double normal_low = 16, normal_high = 0, seidel_high = 0, scaled_low = 16;
  for (const auto& [name, digits] : lre) {
    scaled_low = std::min(scaled_low, digits.at("normal-scaled"));
    if (!name.starts_with("Wampler")) continue;
    normal_low = std::min(normal_low, digits.at("normal"));
    normal_high = std::max(normal_high, digits.at("normal"));
    seidel_high = std::max(seidel_high, digits.at("normal (Gauss-Seidel)"));
  }
  const double scaled5 = lre.at("Wampler5").at("normal-scaled"), gsl5 = lre.at("Wampler5").at("gsl");
  return fmt::format(
      "The plain normal equations keep {:.1f} to {:.1f} digits on the Wampler sets, where x = 0..20 and degree 5 make "
      "V^T V's kappa_1 {:.2g} as it stands ({:.2g} at unit diagonal). Gauss-Seidel on that matrix keeps at most "
      "{:.1f}: its rate is set by kappa. The scaled normal equations keep {:.1f} digits or more everywhere; on "
      "Wampler5 they keep {:.1f}, GSL's SVD {:.1f}.",
      normal_low, normal_high, wampler_normal.condition_unscaled, wampler_normal.condition_estimate, seidel_high,
      scaled_low, scaled5, gsl5);
}

void nist_step(LabSession& session) {
  if (!session.begin_step("Judged by NIST: certified digits on every polynomial data set",
                          "NIST's Statistical Reference Datasets come with parameters certified to 15 digits. The log "
                          "relative error LRE = -log10(|b - b_cert| / |b_cert|) counts correct digits; each cell is the "
                          "fewest over the coefficients. Gauss-Seidel runs up to 100000 sweeps with a 1e-14 step test.")) return;
  std::vector<std::string> header = {"data", "D"};
  for (const auto& m : lab_methods()) header.push_back(m.label);
  header.insert(header.end(), {"kappa normal", "kappa scaled", "kappa gsl"});
  Table table(header);
  std::map<std::string, std::map<std::string, double>> lre;  // data set -> method -> digits
  bool starred = false;
  fitting::PolynomialFit wampler_normal;
  for (const std::string name : {"Norris", "Pontius", "Wampler1", "Wampler2", "Wampler3", "Wampler4", "Wampler5"}) {
    const fitting::DataSet data = nist_set(name);
    const Eigen::VectorXd certified = certified_of(data);
    const int degree = static_cast<int>(certified.size()) - 1;
    std::vector<std::string> row = {name, std::to_string(degree)};
    std::vector<double> kappas;
    for (const auto& m : lab_methods()) {
      const fitting::PolynomialFit fit = fit_by(m, data.x, data.y, degree);
      lre[name][m.label] = digits_of(fit, certified);
      starred = starred || fit.status != Status::converged;
      row.push_back(fmt::format("{:.1f}{}", lre[name][m.label], fit.status == Status::converged ? "" : " *"));
      if (m.solver == NormalSolver::gepp && m.method != FitMethod::eigen_qr) kappas.push_back(fit.condition_estimate);
      if (name == "Wampler4" && m.label == "normal") wampler_normal = fit;
    }
    for (double kappa : kappas) row.push_back(scientific(kappa));
    table.add_row(row);
  }
  session.show(table, "nist-lre");
  session.say(std::string(starred ? "(* = the solver did not converge: Gauss-Seidel used all its sweeps.) " : "") +
              kappa_columns_legend());
  session.say(nist_sentence(lre, wampler_normal));
}

void scaling_step(LabSession& session) {
  if (!session.begin_step("Why centring and scaling x works",
                          "On [0, 20] the columns 1, x, x^2, ..., x^5 of V all rise together: nearly parallel, so V is "
                          "ill-conditioned, and V^T V squares that. Substituting t = (x - 10) / 10 puts the data on "
                          "[-1, 1], where even and odd powers point different ways. The fit in t is then mapped back by "
                          "exact algebra, p(x) = q((x - c) / s), expanded by Horner's rule on polynomials.")) return;
  const fitting::DataSet wampler = nist_set("Wampler5");
  // 1. Each method's matrix, with the condition numbers numlab fit prints for it.
  Table table({"method", "matrix solved", "kappa as it stands", "kappa scaled", "measure; scaling"});
  std::map<std::string, fitting::PolynomialFit> fits;
  for (const auto& m : lab_methods()) {
    if (m.solver != NormalSolver::gepp) continue;
    const fitting::PolynomialFit fit = fit_by(m, wampler.x, wampler.y, 5);
    fits[m.label] = fit;
    const bool normal = m.method == FitMethod::normal || m.method == FitMethod::normal_scaled;
    const bool gsl = m.method == FitMethod::gsl;
    table.add_row({m.label, normal ? (m.method == FitMethod::normal ? "V^T V" : "V^T V in t") : "V",
                   scientific(fit.condition_unscaled), scientific(fit.condition_estimate),
                   normal ? "kappa_1 estimate; unit diagonal"
                          : (gsl ? "kappa_2; GSL's column balancing" : "kappa_2; unit columns")});
  }
  // 2. V in t, which no method solves directly, by the same measure as eigen-qr's V.
  const Eigen::MatrixXd Vt = fitting::vandermonde(fitting::to_scaled(wampler.x, fitting::scaling_for(wampler.x)), 5);
  const double vt = fitting::two_norm_condition(Vt), vt_unit = fitting::two_norm_condition(fitting::unit_columns(Vt));
  table.add_row({"-", "V in t", scientific(vt), scientific(vt_unit), "kappa_2; unit columns"});
  session.show(table, "scaling-conditions");
  // 3. What the numbers show, and why residual size matters on Wampler5.
  const fitting::PolynomialFit& gsl = fits.at("gsl");
  const double fitted = (fitting::vandermonde(wampler.x, 5) * gsl.coefficients).cwiseAbs().maxCoeff();
  const double gsl_kappa = gsl.condition_estimate, scaled_kappa = fits.at("normal-scaled").condition_estimate;
  session.say(fmt::format(
      "The first four rows are the numbers numlab fit --method M prints for the same matrix: 'unit diagonal' scales "
      "rows and columns of the normal matrix, GSL balances V's columns by powers of two (from their 1-norms) before "
      "its SVD. Scaling V's columns brings kappa_2(V) "
      "from {:.2g} to {:.3g} (unit norms) or {:.3g} (GSL's balancing), but cannot undo the collinearity of 1, x, x^2 "
      "on [0, 20]; centring does: V in t has kappa_2 {:.3g} ({:.3g} with unit columns). Even squared, the normal "
      "matrix in t ({:.3g} at unit diagonal) is {} conditioned than the column-balanced V GSL works with ({:.3g}), "
      "whose square is {:.2g} (kappa_1 and kappa_2 agree to within a factor n = 6). Why that matters most on "
      "Wampler5: its residuals are huge (sd {:.2g} against fitted values of at most {:.2g}), and a least-squares "
      "solution's sensitivity to rounding has a term kappa(V)^2 * eps * ||r|| / (||V|| ||b||). Every method pays "
      "kappa^2 on such data, the normal equations or not; the one that works with the smallest kappa wins.",
      fits.at("eigen-qr").condition_unscaled, fits.at("eigen-qr").condition_estimate, gsl_kappa, vt, vt_unit,
      scaled_kappa, scaled_kappa < gsl_kappa ? "better" : "worse", gsl_kappa, gsl_kappa * gsl_kappa, gsl.residual_sd,
      fitted));
}

void foot_path_step(LabSession& session) {
  if (!session.begin_step("The Jansen foot path, fitted (seed 001 eqs 22-23, Figure 3)",
                          "The foot's closed path over one crank cycle (360 closed-form poses) is cut at its leftmost and "
                          "rightmost points into an upper and a lower arc (seed 001 cut by hand at fixed indices). Each "
                          "arc gets a degree-5 polynomial y = p(x). The table compares the hand-written normal "
                          "equations' coefficients with GSL's.")) return;
  const fitting::SplitPath arcs = jansen_foot_arcs();
  Table table({"arc", "points", "power", "normal", "normal-scaled", "gsl", "digits normal vs gsl",
               "digits scaled vs gsl"});
  std::vector<FitSeries> series;
  double fewest_normal = fitting::max_lre, fewest_scaled = fitting::max_lre, largest_kappa = 0.0;
  for (const auto& [label, arc] : {std::pair{"upper", &arcs.upper}, std::pair{"lower", &arcs.lower}}) {
    const fitting::PolynomialFit normal = fit_by(lab_methods()[0], arc->x, arc->y, 5);
    const fitting::PolynomialFit scaled = fit_by(lab_methods()[2], arc->x, arc->y, 5);
    const fitting::PolynomialFit gsl = fit_by(lab_methods()[3], arc->x, arc->y, 5);
    fewest_normal = std::min(fewest_normal, fitting::min_log_relative_error(normal.coefficients, gsl.coefficients));
    fewest_scaled = std::min(fewest_scaled, fitting::min_log_relative_error(scaled.coefficients, gsl.coefficients));
    largest_kappa = std::max(largest_kappa, normal.condition_estimate);
    for (Eigen::Index k = 0; k <= 5; ++k) {
      table.add_row({label, std::to_string(arc->x.size()), std::to_string(k), fmt::format("{:.10g}", normal.coefficients(k)),
                     fmt::format("{:.10g}", scaled.coefficients(k)), fmt::format("{:.10g}", gsl.coefficients(k)),
                     fmt::format("{:.1f}", fitting::log_relative_error(normal.coefficients(k), gsl.coefficients(k))),
                     fmt::format("{:.1f}", fitting::log_relative_error(scaled.coefficients(k), gsl.coefficients(k)))});
    }
    session.say(fmt::format("{} arc: x from {:.2f} to {:.2f}; normal matrix kappa {:.2g} (scaled: {:.2g}); residual "
                            "sd {:.3g} length units.",
                            label, arc->x.minCoeff(), arc->x.maxCoeff(), normal.condition_estimate,
                            scaled.condition_estimate, gsl.residual_sd));
    series.push_back({std::string(label) + " arc", arc->x, arc->y, scaled.coefficients});
  }
  session.show(table, "foot-path-coefficients");
  ensure_directory(session.folder());
  const ChartFiles files = chart_files(session.folder() + "/figure3.svg");
  draw_fit_chart(files, "Jansen foot path: upper and lower arcs with degree-5 fits", series);
  session.figure(files.chart, "seed 001's Figure 3: the foot path's arcs and their degree-5 fits (normal-scaled)");
  session.say(fmt::format(
      "The plain normal equations agree with GSL to {:.1f} digits or more, where the condition predicts about 16 - "
      "log10(kappa) = {:.1f}; the scaled ones to {:.1f} or more. A degree-5 polynomial follows each arc to within "
      "the residual sd above: good enough to draw, not to replace the linkage.",
      fewest_normal, 16.0 - std::log10(largest_kappa), fewest_scaled));
}

// What a degree sweep shows about the plain normal equations: from which degree they keep fewer
// digits than every other method, and where GEPP first stops with 'singular' (0: never).
struct SweepSummary {
  int behind_from = 0;
  int singular_from = 0;
  double kappa_at_singular = 0.0;
};

// Prints one degree sweep (! marks a fit that carries a warning; the legend is printed once, under
// the first table with a mark) and charts it.
SweepSummary degree_sweep_step(LabSession& session, const std::string& title, const std::string& name,
                               const Eigen::VectorXd& x, const Eigen::VectorXd& y, int max_degree, bool& legend_shown) {
  const std::vector<fitting::DegreeSweepRow> rows = fitting::fit_degree_sweep(x, y, max_degree);
  const std::vector<std::string> methods = {"normal", "normal-scaled", "gsl", "eigen-qr"};
  Table table({"degree", "normal", "normal-scaled", "gsl", "eigen-qr", "kappa normal", "kappa scaled"});
  SweepSummary summary;
  bool marked = false;
  for (std::size_t first = 0; first < rows.size(); first += methods.size()) {
    // rows[first .. first + 3] are the four methods at one degree, in the order above.
    std::vector<std::string> cells = {std::to_string(rows[first].degree)};
    double others_fewest = 16.0;
    for (std::size_t m = 0; m < methods.size(); ++m) {
      const fitting::DegreeSweepRow& row = rows[first + m];
      const bool has_fit = std::isfinite(row.residual_sd);
      cells.push_back(has_fit ? fmt::format("{:.1f}{}", row.digits, row.warned ? " !" : "")
                              : std::string(to_string(row.status)));
      marked = marked || (has_fit && row.warned);
      if (m > 0) others_fewest = std::min(others_fewest, row.digits);
    }
    const fitting::DegreeSweepRow& normal = rows[first];
    if (summary.behind_from == 0 && normal.digits < others_fewest) summary.behind_from = normal.degree;
    if (summary.singular_from == 0 && normal.status == Status::singular) {
      summary.singular_from = normal.degree;
      summary.kappa_at_singular = normal.condition;
    }
    cells.push_back(scientific(rows[first].condition));
    cells.push_back(scientific(rows[first + 1].condition));
    table.add_row(cells);
  }
  session.show(table, "degree-sweep-" + name);
  ensure_directory(session.folder());
  const ChartFiles files = chart_files(session.folder() + "/degree-sweep-" + name + ".svg");
  draw_degree_sweep_chart(files, title, rows);
  session.figure(files.chart, title + " (a gap: no coefficients at that degree)");
  if (marked && !legend_shown) {
    session.say("(! in the table = the fit carries a warning.)");
    legend_shown = true;
  }
  return summary;
}

// Where the plain normal equations fall behind and stop, on one data set.
std::string sweep_phrase(const std::string& data, const SweepSummary& s) {
  const std::string behind = s.behind_from == 0 ? "never fall behind the others"
                                                : fmt::format("fall behind the others from degree {}", s.behind_from);
  const std::string stop = s.singular_from == 0 ? "never stop"
                                                : fmt::format("stop with 'singular' at degree {} (kappa normal {:.2g})",
                                                              s.singular_from, s.kappa_at_singular);
  return fmt::format("on {} they {} and {}", data, behind, stop);
}

}  // namespace

int run_fit_lab(LabSession& session) {
  normal_equations_step(session);
  nist_step(session);
  scaling_step(session);
  foot_path_step(session);

  if (!session.begin_step("Degree sweep: where each method stops being trustworthy",
                          "Digits of each method's coefficients against an extended-precision reference (Householder QR "
                          "in long double on the scaled variable, good to 11+ digits on every NIST set), and the residual "
                          "sd, for degrees 1 and up. Digits here are of the whole coefficient vector, each coefficient "
                          "weighted by the size of its term (max |x|^k), because at some degrees a coefficient of the "
                          "reference is nearly zero and its own LRE would read 0 however small the error. First the foot "
                          "path's upper arc, then Wampler4 (x = 0..20).")) return {};
  const fitting::SplitPath arcs = jansen_foot_arcs();
  bool legend_shown = false;
  const SweepSummary foot = degree_sweep_step(session, "Jansen foot path, upper arc: digits and residual against degree",
                                              "foot-path", arcs.upper.x, arcs.upper.y, 14, legend_shown);
  const fitting::DataSet wampler = nist_set("Wampler4");
  const SweepSummary nist = degree_sweep_step(session, "NIST Wampler4: digits and residual against degree", "wampler4",
                                              wampler.x, wampler.y, 12, legend_shown);
  session.say(fmt::format(
      "The plain normal equations work with kappa(V)^2: {}; {}. GEPP stops with 'singular' rather than print "
      "noise: its pivot test compares each pivot with the largest entry, and power sums spanning many orders of "
      "magnitude push the last pivots below n * eps times it, even where the unit-diagonal kappa would leave a few "
      "digits. On the scaled variable the normal equations stay with QR and SVD for many more degrees. The residual "
      "curves show the other side: past the degree the data support, extra terms stop reducing the residual.",
      sweep_phrase("the foot path", foot), sweep_phrase("Wampler4", nist)));
  return exit_success;
}

}  // namespace numlab::cli
