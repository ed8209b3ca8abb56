#include "exercises/trace_comparison.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <optional>

namespace numlab::exercises {

namespace {

// A number of a student's trace entry, or nothing when the entry lacks it (a trace is read leniently
// here: the check has judged it already, the page only shows it).
std::optional<double> number_in(const nlohmann::json& entry, const char* field) {
  if (!entry.is_object()) return std::nullopt;
  const auto found = entry.find(field);
  if (found == entry.end() || !found->is_number()) return std::nullopt;
  return found->get<double>();
}

// A number of a trace entry as it was sent (a whole number stays whole), or null.
nlohmann::json sent_number(const nlohmann::json& entry, const char* field) {
  if (!entry.is_object()) return nullptr;
  const auto found = entry.find(field);
  return found != entry.end() && found->is_number() ? *found : nlohmann::json();
}

// A list of numbers of a trace entry, as sent, or null when it is not one.
nlohmann::json numbers_in(const nlohmann::json& entry, const char* field) {
  if (!entry.is_object()) return nullptr;
  const auto found = entry.find(field);
  if (found == entry.end() || !found->is_array()) return nullptr;
  for (const nlohmann::json& value : *found) {
    if (!value.is_number()) return nullptr;
  }
  return *found;
}

nlohmann::json vector_json(const Eigen::VectorXd& v) {
  nlohmann::json list = nlohmann::json::array();
  for (Eigen::Index i = 0; i < v.size(); ++i) list.push_back(v(i));
  return list;
}

// How many steps of a trace of `total` to keep: all up to kept_trace_steps, and the parting step.
std::size_t kept(std::size_t total, std::size_t parting) {
  return std::min(total, std::max(kept_trace_steps, parting + 1));
}

// "step 3 (column 2)"
std::string step_words(const TraceComparison& comparison, std::size_t k) {
  return fmt::format("step {} ({} {})", k + 1, comparison.step_name, static_cast<long long>(k) + comparison.first_number);
}

// ">" , "=" or "<" between two magnitudes.
const char* order(double a, double b) { return a > b ? ">" : a == b ? "=" : "<"; }

TraceComparison started(const std::string& inputs, const char* step_name, int first_number,
                        std::vector<std::string> fields, std::size_t parting) {
  TraceComparison comparison;
  comparison.inputs = inputs;
  comparison.step_name = step_name;
  comparison.first_number = first_number;
  comparison.fields = std::move(fields);
  comparison.parting = parting;
  return comparison;
}

}  // namespace

std::pair<std::string, std::string> told_apart(double a, double b) {
  for (int digits = 3; digits < 17; ++digits) {
    std::string x = fmt::format("{:.{}g}", a, digits), y = fmt::format("{:.{}g}", b, digits);
    if (x != y || a == b) return {x, y};
  }
  return {fmt::format("{:.17g}", a), fmt::format("{:.17g}", b)};
}

TraceComparison pivot_comparison(const std::string& inputs, const nlohmann::json& trace, const std::vector<int>& rows,
                                 const std::vector<double>& pivots, const std::vector<Eigen::VectorXd>& candidates,
                                 std::size_t parting) {
  TraceComparison comparison = started(inputs, "column", 0, {"pivot_row", "pivot"}, parting);
  // 1. Both traces as steps, and numlab's column of candidates at each.
  comparison.yours_total = trace.size();
  comparison.numlab_total = rows.size();
  for (std::size_t k = 0; k < kept(trace.size(), parting); ++k) {
    comparison.yours.push_back(
        {{"pivot_row", sent_number(trace[k], "pivot_row")}, {"pivot", sent_number(trace[k], "pivot")}});
  }
  comparison.context = nlohmann::json::array();
  for (std::size_t k = 0; k < kept(rows.size(), parting); ++k) {
    comparison.numlab.push_back({{"pivot_row", rows[k]}, {"pivot", pivots[k]}});
    comparison.context.push_back({{"first_row", k}, {"candidates", vector_json(candidates[k])}});
  }
  // 2. The sentence, from the numbers at the parting column.
  const std::size_t k = parting;
  const std::string step = step_words(comparison, k);
  comparison.parting_field = "pivot_row";
  if (k >= rows.size()) {
    comparison.parting_field.clear();
    comparison.sentence = fmt::format("{}: your trace goes on; numlab's GEPP pivots on {} columns only", step, rows.size());
    return comparison;
  }
  const int p = rows[k];
  const Eigen::VectorXd& column = candidates[k];
  const int n = static_cast<int>(k + column.size());
  const double numlab_size = std::abs(column(p - static_cast<int>(k)));
  if (k >= trace.size()) {
    comparison.parting_field.clear();
    comparison.sentence = fmt::format("{}: your trace stops after {} columns; numlab takes row {} as the pivot (|a| = {:.3g})",
                                      step, trace.size(), p, numlab_size);
    return comparison;
  }
  const std::optional<double> column_sent = number_in(trace[k], "column");
  const std::optional<double> row = number_in(trace[k], "pivot_row");
  if (column_sent && *column_sent != static_cast<double>(k)) {
    comparison.sentence = fmt::format("{}: your entry is for column {}; numlab's step {} is column {}: one entry per "
                                      "column, in order, counted from 0",
                                      step, *column_sent, k + 1, k);
  } else if (!row || *row != std::floor(*row)) {
    comparison.sentence = fmt::format("{}: your entry has no whole pivot_row; numlab takes row {} (|a| = {:.3g})", step, p,
                                      numlab_size);
  } else if (*row != p && (*row < static_cast<double>(k) || *row >= n)) {
    comparison.sentence = fmt::format("{}: you took row {} as the pivot, not a row on or below the diagonal ({} ... {}); "
                                      "numlab row {} (|a| = {:.3g})",
                                      step, *row, k, n - 1, p, numlab_size);
  } else if (*row != p) {
    const int r = static_cast<int>(*row);
    const double your_size = std::abs(column(r - static_cast<int>(k)));
    const auto [theirs, yours] = told_apart(numlab_size, your_size);
    comparison.sentence = fmt::format("{}: you took row {} as the pivot, numlab row {} (|a| = {} {} {})", step, r, p,
                                      theirs, order(numlab_size, your_size), yours);
  } else {
    comparison.parting_field = "pivot";
    const std::optional<double> pivot = number_in(trace[k], "pivot");
    if (!pivot) {
      comparison.sentence = fmt::format("{}: you and numlab both took row {}, but your entry has no pivot", step, p);
    } else {
      const auto [yours, theirs] = told_apart(*pivot, pivots[k]);
      comparison.sentence = fmt::format("{}: you and numlab both took row {}, but your pivot is {} where numlab's is {}: an "
                                        "earlier column left other numbers below the diagonal",
                                        step, p, yours, theirs);
    }
  }
  return comparison;
}

TraceComparison sweep_comparison(const std::string& inputs, const nlohmann::json& trace,
                                 const std::vector<Eigen::VectorXd>& xs, const std::vector<double>& updates,
                                 std::size_t parting, double allowed) {
  TraceComparison comparison = started(inputs, "sweep", 1, {"x", "update_inf"}, parting);
  // 1. Both traces as steps.
  comparison.yours_total = trace.size();
  comparison.numlab_total = xs.size();
  for (std::size_t s = 0; s < kept(trace.size(), parting); ++s) {
    comparison.yours.push_back({{"x", numbers_in(trace[s], "x")}, {"update_inf", sent_number(trace[s], "update_inf")}});
  }
  for (std::size_t s = 0; s < kept(xs.size(), parting); ++s) {
    comparison.numlab.push_back({{"x", vector_json(xs[s])}, {"update_inf", updates[s]}});
  }
  // 2. The sentence, from the numbers at the parting sweep.
  const std::size_t s = parting;
  const std::string step = step_words(comparison, s);
  if (s >= xs.size()) {
    comparison.sentence = fmt::format("{}: your trace goes on to sweep {}; numlab's stops after {} sweeps", step,
                                      trace.size(), xs.size());
    return comparison;
  }
  if (s >= trace.size()) {
    comparison.sentence = fmt::format("{}: your trace ends after {} sweeps; numlab's goes on to sweep {} (update_inf {:.3g} "
                                      "after sweep {})",
                                      step, trace.size(), xs.size(), updates[s], s + 1);
    return comparison;
  }
  const nlohmann::json x = numbers_in(trace[s], "x");
  const Eigen::Index n = xs[s].size();
  if (x.is_null() || static_cast<Eigen::Index>(x.size()) != n) {
    comparison.parting_field = "x";
    comparison.sentence = fmt::format("{}: your entry has no x of {} numbers", step, n);
    return comparison;
  }
  Eigen::Index worst = 0;
  double largest = -1.0;
  for (Eigen::Index i = 0; i < n; ++i) {
    const double d = std::abs(x[static_cast<std::size_t>(i)].get<double>() - xs[s](i));
    if (d > largest) {
      largest = d;
      worst = i;
    }
  }
  if (largest > allowed) {
    comparison.parting_field = "x";
    comparison.parting_entry = worst;
    const auto [yours, theirs] = told_apart(x[static_cast<std::size_t>(worst)].get<double>(), xs[s](worst));
    comparison.sentence = fmt::format("{}: your x[{}] = {} where numlab's is {} (they differ by {:.2g}, allowed {:.2g})",
                                      step, worst, yours, theirs, largest, allowed);
    return comparison;
  }
  comparison.parting_field = "update_inf";
  const std::optional<double> update = number_in(trace[s], "update_inf");
  const auto [yours, theirs] = told_apart(update.value_or(std::nan("")), updates[s]);
  comparison.sentence = fmt::format("{}: your x is numlab's, but your update_inf = {} where numlab's is {} "
                                    "(max_i |x_i(new) - x_i(old)| over the sweep)",
                                    step, update ? yours : std::string("missing"), theirs);
  return comparison;
}

TraceComparison newton_comparison(const std::string& inputs, const std::vector<double>& your_residuals,
                                  const std::vector<double>& your_steps, const std::vector<double>& residuals,
                                  const std::vector<double>& steps, std::size_t parting,
                                  const NewtonTolerances& tolerances) {
  TraceComparison comparison = started(inputs, "iteration", 1, {"residual_inf", "step_inf"}, parting);
  // 1. Both traces as steps.
  comparison.yours_total = your_residuals.size();
  comparison.numlab_total = residuals.size();
  for (std::size_t k = 0; k < kept(your_residuals.size(), parting); ++k) {
    comparison.yours.push_back({{"residual_inf", your_residuals[k]}, {"step_inf", your_steps[k]}});
  }
  for (std::size_t k = 0; k < kept(residuals.size(), parting); ++k) {
    comparison.numlab.push_back({{"residual_inf", residuals[k]}, {"step_inf", steps[k]}});
  }
  // 2. The sentence, from the numbers at the parting iteration.
  const std::size_t k = parting;
  const std::string step = step_words(comparison, k);
  if (k >= residuals.size()) {
    const double last = residuals.empty() ? std::nan("") : residuals.back();
    comparison.sentence =
        residuals.empty() ? fmt::format("{}: your trace goes on to iteration {}; numlab's Newton takes no step from this "
                                        "start", step, your_residuals.size())
        : last <= tolerances.tolerance
            ? fmt::format("{}: your trace goes on to iteration {}; numlab's Newton stops after {}: ||f||_inf = {:.3g} "
                          "passes the test (tolerance {:.3g})",
                          step, your_residuals.size(), residuals.size(), last, tolerances.tolerance)
            : fmt::format("{}: your trace goes on to iteration {}; numlab's Newton stops after {} (||f||_inf = {:.3g})",
                          step, your_residuals.size(), residuals.size(), last);
    return comparison;
  }
  if (k >= your_residuals.size()) {
    comparison.sentence = fmt::format("{}: your trace ends after {} iterations; numlab's Newton goes on: ||f||_inf = {:.3g} "
                                      "after iteration {} (tolerance {:.3g})",
                                      step, your_residuals.size(), residuals[k], k + 1, tolerances.tolerance);
    return comparison;
  }
  const bool residual_ok = std::abs(your_residuals[k] - residuals[k]) <= tolerances.relative * residuals[k] + tolerances.residual_floor;
  const bool step_ok = std::abs(your_steps[k] - steps[k]) <= tolerances.relative * steps[k] + tolerances.step_floor;
  const auto [your_f, numlab_f] = told_apart(your_residuals[k], residuals[k]);
  const auto [your_dx, numlab_dx] = told_apart(your_steps[k], steps[k]);
  comparison.parting_field = residual_ok && !step_ok ? "step_inf" : "residual_inf";
  if (!residual_ok && !step_ok) {
    comparison.sentence = fmt::format("{}: your ||f||_inf = {} where numlab's is {}, and your ||dx||_inf = {} where "
                                      "numlab's is {}",
                                      step, your_f, numlab_f, your_dx, numlab_dx);
  } else if (!residual_ok) {
    comparison.sentence = fmt::format("{}: your ||f||_inf = {} where numlab's is {} (your ||dx||_inf = {:.3g} is numlab's)",
                                      step, your_f, numlab_f, your_steps[k]);
  } else {
    comparison.sentence = fmt::format("{}: your ||dx||_inf = {} where numlab's is {} (your ||f||_inf = {:.3g} is numlab's)",
                                      step, your_dx, numlab_dx, your_residuals[k]);
  }
  return comparison;
}

nlohmann::ordered_json trace_json(const TraceComparison& comparison) {
  nlohmann::ordered_json json;
  json["inputs"] = comparison.inputs;
  json["step_name"] = comparison.step_name;
  json["first_number"] = comparison.first_number;
  json["fields"] = comparison.fields;
  json["yours"] = comparison.yours;
  json["numlab"] = comparison.numlab;
  json["yours_total"] = comparison.yours_total;
  json["numlab_total"] = comparison.numlab_total;
  json["context"] = comparison.context;
  json["parting"] = comparison.parting;
  json["parting_field"] = comparison.parting_field;
  json["parting_entry"] = comparison.parting_entry;
  json["sentence"] = comparison.sentence;
  return json;
}

}  // namespace numlab::exercises
