#include "exercises/results.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <optional>
#include <sstream>

#include "exercises/trace_page.hpp"
#include "output/report_style.hpp"

namespace numlab::exercises {

namespace {

using cli::html_escape;

int count(const std::vector<CheckResult>& results, CheckStatus status) {
  int n = 0;
  for (const CheckResult& result : results) n += result.status == status ? 1 : 0;
  return n;
}

// The check's message and its diagnosis (or, when no detector fired, its hint).
std::string message_with_hint(const CheckResult& result) {
  const std::string why = explanation(result);
  return why.empty() ? result.message : result.message + "\n" + why;
}

std::string milliseconds(double seconds) { return fmt::format("{:.3g} ms", seconds * 1e3); }

// "you 0.41 ms/request, numlab GEPP 0.012 ms, GSL LU 0.009 ms"; "" when the program was not timed.
std::string timing_line(const CheckResult& result) {
  if (result.seconds_per_request <= 0.0) return "";
  std::string line = "you " + milliseconds(result.seconds_per_request) + "/request";
  for (const ReferenceTime& reference : result.references) {
    line += ", " + reference.name + " " + milliseconds(reference.seconds_per_request);
  }
  return line;
}

// The program's stderr cut to its first lines (each cut too), for the terminal.
std::string shortened(const std::string& output) {
  constexpr std::size_t max_lines = 8, max_columns = 160;
  std::istringstream lines(output);
  std::string line, out;
  std::size_t shown = 0, total = 0;
  while (std::getline(lines, line)) {
    ++total;
    if (shown == max_lines) continue;
    if (line.size() > max_columns) line = line.substr(0, max_columns) + " ...";
    out += line + '\n';
    ++shown;
  }
  if (total > shown) out += fmt::format("... ({} more lines)\n", total - shown);
  return out;
}

std::string indented(const std::string& text, const std::string& indent) {
  std::istringstream lines(text);
  std::string line, out;
  while (std::getline(lines, line)) out += indent + line + '\n';
  return out;
}

// The first check that does not pass: the one to fix first (a later failure often follows from it).
const CheckResult* first_failure(const std::vector<CheckResult>& results) {
  for (const CheckResult& result : results) {
    if (result.status != CheckStatus::pass) return &result;
  }
  return nullptr;
}

// " (variant ID)", or "" without one.
std::string variant_words(const Variant& variant) {
  return variant.active() ? " (variant " + *variant.id() + ")" : "";
}

std::string first_line(const std::string& text) { return text.substr(0, text.find('\n')); }

std::string mark(const CheckResult& result) {
  switch (result.status) {
    case CheckStatus::pass: return "✓ " + result.name;
    case CheckStatus::fail: return "✗ " + result.name;
    case CheckStatus::error: return "✗ " + result.name + " (error)";
  }
  return result.name;
}

}  // namespace

nlohmann::ordered_json results_json(const std::vector<CheckResult>& results, const std::string& error_message,
                                    const Variant& variant) {
  const int errors = count(results, CheckStatus::error);
  const int passes = count(results, CheckStatus::pass);
  const bool all_errored = errors == static_cast<int>(results.size());
  const char* status = all_errored ? "error" : passes == static_cast<int>(results.size()) ? "pass" : "fail";

  nlohmann::ordered_json json;
  json["version"] = 3;
  json["status"] = status;
  if (!error_message.empty()) {
    json["message"] = error_message;
  } else if (!all_errored) {
    json["message"] = nullptr;
  } else if (results.empty()) {
    json["message"] = "no check was run";
  } else {
    json["message"] = fmt::format("every check errored; the first, '{}': {}", results.front().name,
                                  results.front().message);
  }
  // Extra top-level fields (Exercism's runner ignores unknown keys): the cause found, or null.
  const std::optional<Diagnosis> diagnosis = overall_diagnosis(results);
  json["diagnosis"] = diagnosis ? nlohmann::ordered_json(diagnosis->evidence) : nlohmann::ordered_json();
  json["diagnosis_cause"] = diagnosis ? nlohmann::ordered_json(diagnosis->cause) : nlohmann::ordered_json();
  json["variant"] = variant.active() ? nlohmann::ordered_json(*variant.id()) : nlohmann::ordered_json();
  json["tests"] = nlohmann::ordered_json::array();
  for (const CheckResult& result : results) {
    nlohmann::ordered_json test;
    test["name"] = result.name;
    test["status"] = to_string(result.status);
    test["message"] = result.status == CheckStatus::pass ? nlohmann::ordered_json() : nlohmann::ordered_json(message_with_hint(result));
    test["task_id"] = result.task_id;
    test["output"] = result.output.empty() ? nlohmann::ordered_json() : nlohmann::ordered_json(result.output);
    // An extra field of a failing trace check: both traces and where they part (trace.html draws it).
    if (result.status != CheckStatus::pass && result.trace) test["trace"] = trace_json(*result.trace);
    nlohmann::ordered_json timing;
    timing["you"] = result.seconds_per_request > 0.0 ? nlohmann::ordered_json(result.seconds_per_request)
                                                      : nlohmann::ordered_json();
    for (const ReferenceTime& reference : result.references) timing[reference.name] = reference.seconds_per_request;
    test["timing"] = timing;
    json["tests"].push_back(test);
  }
  return json;
}

std::string results_summary(const std::vector<CheckResult>& results) {
  const int total = static_cast<int>(results.size());
  const int fails = count(results, CheckStatus::fail), errors = count(results, CheckStatus::error);
  std::string line = fmt::format("{} of {} checks pass", count(results, CheckStatus::pass), total);
  if (fails > 0) line += fmt::format("; {} fail", fails);
  if (errors > 0) line += fmt::format("{} {} error{}", fails > 0 ? "," : ";", errors, errors == 1 ? "" : "s");
  return line;
}

std::string results_text(const Exercise& exercise, const std::vector<CheckResult>& results, const Variant& variant) {
  std::string text;
  if (const std::optional<Diagnosis> diagnosis = overall_diagnosis(results)) {
    text += "Diagnosis: " + diagnosis->evidence + '\n';
  }
  if (const CheckResult* first = first_failure(results)) {
    text += "Fix first: " + first->name + " — " + first_line(first->message) + '\n';
    if (!first->replay.empty()) text += "Replay it: " + first->replay + '\n';
    text += '\n';
  }
  text += fmt::format("numlab exercise {}{}: {}\n\n", exercise.name, variant_words(variant), exercise.summary);
  for (const CheckResult& result : results) {
    text += mark(result) + '\n';
    if (const std::string timing = timing_line(result); !timing.empty()) text += "    " + timing + '\n';
  }
  if (count(results, CheckStatus::pass) < static_cast<int>(results.size())) {
    text += "\nFailures\n--------\n";
    for (const CheckResult& result : results) {
      if (result.status == CheckStatus::pass) continue;
      text += '\n' + mark(result) + '\n' + indented(message_with_hint(result), "    ");
      if (!result.output.empty()) text += "    Output (stderr):\n" + indented(shortened(result.output), "      | ");
      if (!result.replay.empty()) text += "    Replay: " + result.replay + '\n';
    }
  }
  return text + '\n' + results_summary(results) + '\n';
}

std::string results_html(const Exercise& exercise, const std::vector<CheckResult>& results,
                         const std::string& command, const Variant& variant) {
  std::string body;
  if (const CheckResult* first = first_failure(results)) {
    body += "<div class=\"first\">";
    if (const std::optional<Diagnosis> diagnosis = overall_diagnosis(results)) {
      body += "<p class=\"diagnosis\"><strong>Diagnosis:</strong> " + html_escape(diagnosis->evidence) + "</p>\n";
    }
    body += "<p><strong>Fix first:</strong> " + html_escape(first->name) + " — " +
            html_escape(first_line(first->message)) + "</p>\n";
    if (!first->replay.empty()) body += "<p>Replay it: <code>" + html_escape(first->replay) + "</code></p>\n";
    if (const CheckResult* traced = failing_trace_check(results)) {
      body += "<p>Your trace beside numlab's, step by step: <a href=\"trace.html\">trace.html</a> (" +
              html_escape(traced->trace->sentence) + ")</p>\n";
    }
    body += "</div>\n";
  }
  if (variant.active()) body += "<p>Variant: <code>" + html_escape(*variant.id()) + "</code></p>\n";
  body += "<p><em>" + html_escape(exercise.summary) + "</em></p>\n<p>Checked: <code>" +
                     html_escape(command) + "</code></p>\n<p class=\"summary\">" +
                     html_escape(results_summary(results)) + "</p>\n";
  // One column per reference, in the order they first appear.
  std::vector<std::string> references;
  for (const CheckResult& result : results) {
    for (const ReferenceTime& reference : result.references) {
      if (std::find(references.begin(), references.end(), reference.name) == references.end())
        references.push_back(reference.name);
    }
  }
  body += "<h2>Checks</h2>\n<table>\n<tr><th>check</th><th>task</th><th>result</th><th>you (ms/request)</th>";
  for (const std::string& reference : references) body += "<th>" + html_escape(reference) + " (ms)</th>";
  body += "</tr>\n";
  for (const CheckResult& result : results) {
    const std::string status = to_string(result.status);
    body += fmt::format("<tr><td>{}</td><td>{}</td><td class=\"{}\">{} {}</td><td>{}</td>", html_escape(result.name),
                        result.task_id, status, result.status == CheckStatus::pass ? "✓" : "✗", status,
                        result.seconds_per_request > 0.0 ? fmt::format("{:.3g}", result.seconds_per_request * 1e3) : "-");
    for (const std::string& name : references) {
      const auto found = std::find_if(result.references.begin(), result.references.end(),
                                      [&](const ReferenceTime& reference) { return reference.name == name; });
      body += "<td>" + (found == result.references.end() ? std::string("-")
                                                          : fmt::format("{:.3g}", found->seconds_per_request * 1e3)) +
              "</td>";
    }
    body += "</tr>\n";
  }
  body += "</table>\n";
  if (count(results, CheckStatus::pass) < static_cast<int>(results.size())) {
    body += "<h2>Failures</h2>\n";
    for (const CheckResult& result : results) {
      if (result.status == CheckStatus::pass) continue;
      body += fmt::format("<h3 class=\"{}\">✗ {}</h3>\n<p class=\"message\">{}</p>\n", to_string(result.status),
                          html_escape(result.name), html_escape(result.message));
      if (const std::string why = explanation(result); !why.empty()) {
        body += "<p class=\"hint\">" + html_escape(why) + "</p>\n";
      }
      if (!result.output.empty()) body += "<p>Output (stderr):</p>\n<pre>" + html_escape(result.output) + "</pre>\n";
      if (!result.replay.empty()) body += "<p>Replay: <code>" + html_escape(result.replay) + "</code></p>\n";
    }
  }
  const std::string css =
      ".pass { color: #1a7f37; font-weight: bold; } .fail { color: #b42318; font-weight: bold; }\n"
      ".error { color: #b54708; font-weight: bold; } .summary { font-size: 1.15em; font-weight: bold; }\n"
      ".message { white-space: pre-wrap; font-family: monospace; } .hint { background: #fff8e1; padding: 0.4em; }\n"
      "td:first-child { white-space: normal; min-width: 28em; } td:nth-child(2) { text-align: center; }\n"
      "td:nth-child(3) { text-align: left; }\n"
      ".first { border-left: 4px solid #b42318; background: #fdf2f2; padding: 0.2em 0.8em; margin-bottom: 1em; }\n";
  return cli::html_page("numlab exercise " + exercise.name + variant_words(variant), body, css);
}

}  // namespace numlab::exercises
