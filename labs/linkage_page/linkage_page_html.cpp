#include "linkage_page/linkage_page_html.hpp"

#include <fmt/format.h>

#include "output/report_style.hpp"

namespace numlab::cli {

namespace {

using nlohmann::ordered_json;

// The JSON as a <script> element may hold it: every '<' written \u003c (it is only ever inside a
// string), so that no "</script>" can end the element early.
std::string embeddable(const ordered_json& data) {
  const std::string text = data.dump();
  std::string out;
  out.reserve(text.size());
  for (const char c : text) out += c == '<' ? std::string("\\u003c") : std::string(1, c);
  return out;
}

std::string cell(const ordered_json& value) {
  if (value.is_null()) return "&ndash;";
  if (value.is_number()) return fmt::format("{:.6g}", value.get<double>());
  return html_escape(value.get<std::string>());
}

// The table every reader gets, scripts or not: per pose the driver, the solve's status, iterations,
// kappa(J), each transmission angle, the driver torque (or force), and every moving joint's x, y.
std::string pose_table(const ordered_json& data) {
  const ordered_json& columns = data["columns"];
  std::vector<std::string> names{data["driver_column"].get<std::string>()};
  for (const char* name : {"status", "iterations", "residual_inf", "condition", "driver_torque", "driver_force", "statics"}) {
    if (columns.contains(name)) names.emplace_back(name);
  }
  for (const auto& [name, column] : columns.items()) {
    if (name.rfind("mu_", 0) == 0) names.push_back(name);
  }
  for (const auto& joint : data["joints"]) {
    if (joint["ground"].get<bool>()) continue;
    names.push_back("x_" + joint["name"].get<std::string>());
    names.push_back("y_" + joint["name"].get<std::string>());
  }
  std::string html = "<table id=\"pose-table\">\n<thead><tr>";
  for (const auto& name : names) html += "<th scope=\"col\">" + html_escape(name) + "</th>";
  html += "</tr></thead>\n<tbody>\n";
  const std::size_t rows = columns[names.front()].size();
  for (std::size_t r = 0; r < rows; ++r) {
    html += "<tr>";
    for (const auto& name : names) html += "<td>" + cell(columns[name][r]) + "</td>";
    html += "</tr>\n";
  }
  return html + "</tbody></table>\n";
}

}  // namespace

std::string linkage_page_html(const nlohmann::ordered_json& data, const std::string& static_svg,
                              const std::string& static_caption) {
  const std::string title = data["title"].get<std::string>();
  std::string body = "<p class=\"lede\" id=\"lede\">One pose drawn by numlab and the table of every pose; with "
                     "scripts on, a slider scrubs the solved poses.</p>\n";
  for (const auto& note : data["notes"]) body += "<p class=\"note\">" + html_escape(note.get<std::string>()) + "</p>\n";
  body += "<div id=\"live\"></div>\n";
  body += "<figure id=\"static-scene\">\n" + static_svg + "<figcaption>" + html_escape(static_caption) +
          "</figcaption>\n</figure>\n";
  const std::size_t rows = data["columns"][data["driver_column"].get<std::string>()].size();
  body += fmt::format("<details id=\"pose-details\" open>\n<summary>Every pose: {} rows (the CSV's numbers, 6 "
                      "significant digits)</summary>\n",
                      rows) +
          pose_table(data) + "</details>\n";
  body += "<script type=\"application/json\" id=\"linkage-data\">" + embeddable(data) + "</script>\n";
  body += std::string("<script>\n") + linkage_page_script() + "</script>\n";
  return html_page(title, body, linkage_page_style());
}

}  // namespace numlab::cli
