#include "output/lab_report.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "output/html/stepper_css.hpp"
#include "output/html/stepper_js.hpp"

namespace numlab::cli {

namespace {

std::string read_whole_file(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  if (!file) throw std::runtime_error("report: cannot read the figure " + path);
  std::ostringstream contents;
  contents << file.rdbuf();
  return contents.str();
}

std::string base64(const std::string& bytes) {
  static constexpr char alphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  std::size_t i = 0;
  // Three bytes become four characters; the tail is padded with '='.
  for (; i + 2 < bytes.size(); i += 3) {
    const unsigned v = (static_cast<unsigned char>(bytes[i]) << 16) | (static_cast<unsigned char>(bytes[i + 1]) << 8) |
                       static_cast<unsigned char>(bytes[i + 2]);
    out += {alphabet[(v >> 18) & 63], alphabet[(v >> 12) & 63], alphabet[(v >> 6) & 63], alphabet[v & 63]};
  }
  if (i + 1 == bytes.size()) {
    const unsigned v = static_cast<unsigned char>(bytes[i]) << 16;
    out += {alphabet[(v >> 18) & 63], alphabet[(v >> 12) & 63], '=', '='};
  } else if (i + 2 == bytes.size()) {
    const unsigned v = (static_cast<unsigned char>(bytes[i]) << 16) | (static_cast<unsigned char>(bytes[i + 1]) << 8);
    out += {alphabet[(v >> 18) & 63], alphabet[(v >> 12) & 63], alphabet[(v >> 6) & 63], '='};
  }
  return out;
}

// An SVG file's <svg> element, without the XML declaration and DOCTYPE that may not appear inside HTML.
std::string inline_svg(const std::string& svg, const std::string& path) {
  const std::size_t start = svg.find("<svg");
  if (start == std::string::npos) throw std::runtime_error("report: " + path + " holds no <svg> element");
  return svg.substr(start);
}

}  // namespace

void LabReport::add_step(int number, const std::string& title) {
  body_ += "<h2 id=\"step" + std::to_string(number) + "\">Step " + std::to_string(number) + ": " + html_escape(title) +
           "</h2>\n";
}

void LabReport::add_paragraph(const std::string& text) { body_ += "<p>" + html_escape(text) + "</p>\n"; }

void LabReport::add_table(const Table& table, const std::string& saved_as) {
  body_ += "<table>\n<tr>";
  for (const auto& cell : table.header()) body_ += "<th>" + html_escape(cell) + "</th>";
  body_ += "</tr>\n";
  for (const auto& row : table.rows()) {
    body_ += "<tr>";
    for (const auto& cell : row) body_ += "<td>" + html_escape(cell) + "</td>";
    body_ += "</tr>\n";
  }
  const std::string file = std::filesystem::path(saved_as).filename().string();
  body_ += "</table>\n<p class=\"saved\">Table saved as <code>" + html_escape(file) + "</code>.</p>\n";
}

void LabReport::add_preformatted(const std::string& text) {
  if (text.find_first_not_of(" \n") == std::string::npos) return;
  body_ += "<pre>" + html_escape(text) + "</pre>\n";
}

void LabReport::add_figure(const std::string& path, const std::string& caption) {
  const std::string contents = read_whole_file(path);
  const std::string file = std::filesystem::path(path).filename().string();
  body_ += "<figure>\n";
  if (path.ends_with(".svg")) {
    body_ += inline_svg(contents, path) + "\n";
  } else {
    body_ += "<img alt=\"" + html_escape(file) + "\" src=\"data:image/png;base64," + base64(contents) + "\">\n";
  }
  body_ += "<figcaption><code>" + html_escape(file) + "</code>: " + html_escape(caption) + "</figcaption>\n</figure>\n";
  figures_.push_back(path);
}

void LabReport::add_stepper(const std::string& kind, const std::string& caption, const nlohmann::ordered_json& data) {
  // "</" is written "<\/" (the same string in JSON), so no value can end the <script> element.
  std::string json;
  for (const char c : data.dump()) {
    if (c == '/' && !json.empty() && json.back() == '<') json += '\\';
    json += c;
  }
  body_ += "<div class=\"stepper\" data-kind=\"" + html_escape(kind) + "\" data-caption=\"" + html_escape(caption) +
           "\">\n<script type=\"application/json\">" + json + "</script>\n</div>\n";
  has_steppers_ = true;
}

std::string LabReport::html() const {
  const std::string summary = "<p><em>" + html_escape(summary_) + "</em></p>\n";
  if (!has_steppers_) return html_page("numlab lab " + title_, summary + body_);
  const std::string script = "<script>\n" + std::string(html::stepper_js) + "</script>\n";
  return html_page("numlab lab " + title_, summary + body_ + script, std::string(html::stepper_css));
}

}  // namespace numlab::cli
