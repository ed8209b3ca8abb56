#include "exercises/trace_page.hpp"

#include <fmt/format.h>

#include "output/report_style.hpp"

namespace numlab::exercises {

namespace {

using cli::html_escape;

// The page's own style and script, labs/exercises/html/trace_page.css and .js, embedded at build
// time (labs/exercises/CMakeLists.txt).
#include "exercises/trace_page_assets.inc"

// A field's heading: the protocol's name, or the norm it is.
std::string heading(const std::string& field) {
  if (field == "pivot_row") return "pivot row";
  if (field == "residual_inf") return "||f||_inf";
  if (field == "step_inf") return "||dx||_inf";
  return field;
}

// One value of a step for the static table: 6 significant digits, a list in brackets, "—" for none.
std::string cell_text(const nlohmann::json& value) {
  if (value.is_number_integer()) return std::to_string(value.get<long long>());
  if (value.is_number()) return fmt::format("{:.6g}", value.get<double>());
  if (value.is_array()) {
    std::string text = "[";
    for (std::size_t i = 0; i < value.size(); ++i) text += (i > 0 ? ", " : "") + cell_text(value[i]);
    return text + "]";
  }
  return "—";
}

// The fields of step k of one trace as table cells (empty cells past its end).
std::string step_cells(const TraceComparison& comparison, const nlohmann::json& steps, std::size_t k,
                       const char* side) {
  std::string cells;
  for (const std::string& field : comparison.fields) {
    const bool parts = k == comparison.parting && field == comparison.parting_field;
    const nlohmann::json value = k < steps.size() ? steps[k].value(field, nlohmann::json()) : nlohmann::json();
    const std::string text = k < steps.size() ? cell_text(value) : "";
    cells += fmt::format("<td class=\"{}{}{}\">{}</td>", side, value.is_array() ? " list" : "", parts ? " differs" : "",
                         html_escape(text));
  }
  return cells;
}

// The static view: one row per step, yours beside numlab's, the parting row marked. The protocol's
// number of the step is a column of its own where it is not the step's (GEPP's columns count from 0).
std::string steps_table(const TraceComparison& comparison) {
  const std::size_t fields = comparison.fields.size();
  const bool numbered = comparison.first_number != 1;
  std::string table = fmt::format(
      "<table id=\"trace-table\">\n<caption>Your trace (left) beside numlab's (right), one row per {}</caption>\n"
      "<thead><tr><th rowspan=\"2\" scope=\"col\">{}</th>{}"
      "<th colspan=\"{}\" scope=\"colgroup\" class=\"yours\">yours</th><th colspan=\"{}\" scope=\"colgroup\" "
      "class=\"numlab\">numlab's</th><th rowspan=\"2\" scope=\"col\"></th></tr>\n<tr>",
      comparison.step_name, numbered ? "step" : comparison.step_name,
      numbered ? "<th rowspan=\"2\" scope=\"col\">" + html_escape(comparison.step_name) + "</th>" : "", fields, fields);
  for (int side = 0; side < 2; ++side) {
    for (const std::string& field : comparison.fields) table += "<th scope=\"col\">" + html_escape(heading(field)) + "</th>";
  }
  table += "</tr></thead>\n<tbody>\n";
  const std::size_t rows = std::max(comparison.yours.size(), comparison.numlab.size());
  for (std::size_t k = 0; k < rows; ++k) {
    const char* where = k < comparison.parting ? "same" : k == comparison.parting ? "parting" : "after";
    const std::string number =
        numbered ? fmt::format("<td>{}</td>", static_cast<long long>(k) + comparison.first_number) : "";
    table += fmt::format("<tr id=\"step-{}\" class=\"{}\"><th scope=\"row\">{}</th>{}{}{}<td class=\"mark\">{}</td></tr>\n",
                         k + 1, where, k + 1, number,
                         step_cells(comparison, comparison.yours, k, "yours"),
                         step_cells(comparison, comparison.numlab, k, "numlab"),
                         k == comparison.parting ? "← they part here" : "");
  }
  return table + "</tbody>\n</table>\n";
}

// "your trace has 2000 steps shown of 5000" notes, when a trace was cut.
std::string cut_note(const TraceComparison& comparison) {
  std::string note;
  if (comparison.yours_total > comparison.yours.size()) {
    note += fmt::format("Your trace has {} {}s; the first {} are shown. ", comparison.yours_total, comparison.step_name,
                        comparison.yours.size());
  }
  if (comparison.numlab_total > comparison.numlab.size()) {
    note += fmt::format("numlab's has {} {}s; the first {} are shown.", comparison.numlab_total, comparison.step_name,
                        comparison.numlab.size());
  }
  return note.empty() ? "" : "<p class=\"note\">" + html_escape(note) + "</p>\n";
}

// The JSON the script reads, safe inside <script>: every '<' (only ever inside a string) escaped.
std::string embedded(const nlohmann::ordered_json& data) {
  std::string text = data.dump();
  std::string out;
  out.reserve(text.size());
  for (char c : text) out += c == '<' ? std::string("\\u003c") : std::string(1, c);
  return out;
}

// The stepper's controls, hidden until the script shows them (scripts off: the table alone).
std::string stepper(const TraceComparison& comparison, std::size_t steps) {
  return fmt::format(
      "<section id=\"stepper\" aria-label=\"Step through both traces\" hidden>\n"
      "<div class=\"controls\" role=\"group\" aria-label=\"Steps\">\n"
      "<button type=\"button\" id=\"first\">&laquo; First</button>\n"
      "<button type=\"button\" id=\"previous\">&lsaquo; Previous</button>\n"
      "<label class=\"slider\">Step <input type=\"range\" id=\"slider\" min=\"1\" max=\"{}\" value=\"{}\" "
      "aria-describedby=\"position\"></label>\n"
      "<button type=\"button\" id=\"next\">Next &rsaquo;</button>\n"
      "<button type=\"button\" id=\"last\">Last &raquo;</button>\n"
      "<button type=\"button\" id=\"to-parting\">Where they part (step {})</button>\n"
      "</div>\n"
      "<p id=\"position\" aria-live=\"polite\"></p>\n"
      "<p id=\"step-sentence\" class=\"sentence\"></p>\n"
      "<div class=\"side-by-side\">\n<div id=\"step-values\"></div>\n<div id=\"step-context\"></div>\n</div>\n"
      "<p class=\"keys\">Keys: &larr; and &rarr; step back and on, Home and End go to the first and last step.</p>\n"
      "</section>\n",
      steps, comparison.parting + 1, comparison.parting + 1);
}

}  // namespace

const CheckResult* failing_trace_check(const std::vector<CheckResult>& results) {
  for (const CheckResult& result : results) {
    if (result.status != CheckStatus::pass && result.trace) return &result;
  }
  return nullptr;
}

std::string trace_page_html(const Exercise& exercise, const CheckResult& result, const Variant& variant) {
  const TraceComparison& comparison = *result.trace;
  const std::size_t steps = std::max(comparison.yours.size(), comparison.numlab.size());
  std::string body;
  body += "<p class=\"check\">Check: <strong>" + html_escape(result.name) + "</strong> (task " +
          std::to_string(result.task_id) + ")<br>Request: <code>" + html_escape(comparison.inputs) + "</code>";
  if (variant.active()) body += "<br>Variant: <code>" + html_escape(*variant.id()) + "</code>";
  body += "</p>\n<div class=\"first\"><p id=\"parting-sentence\"><strong>Where your trace parts from numlab's:</strong> " +
          html_escape(comparison.sentence) + "</p>\n";
  if (const std::string why = explanation(result); !why.empty()) body += "<p class=\"hint\">" + html_escape(why) + "</p>\n";
  body += "<p class=\"message\">The check says: " + html_escape(result.message) + "</p>\n</div>\n";
  body += stepper(comparison, steps);
  body += "<h2>Both traces, " + html_escape(comparison.step_name) + " by " + html_escape(comparison.step_name) + "</h2>\n";
  body += cut_note(comparison) + steps_table(comparison);
  body += "<p class=\"back\">The whole report: <a href=\"report.html\">report.html</a>.</p>\n";
  nlohmann::ordered_json data = trace_json(comparison);
  data["check"] = result.name;
  body += "<script type=\"application/json\" id=\"trace-data\">" + embedded(data) + "</script>\n";
  body += "<script>\n" + std::string(trace_page_script) + "</script>\n";
  return cli::html_page("numlab exercise " + exercise.name + ": your trace beside numlab's", body, trace_page_style);
}

}  // namespace numlab::exercises
