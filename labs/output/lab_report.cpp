#include "output/lab_report.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

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

std::string html_escape(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

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

std::string LabReport::html() const {
  return "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>numlab lab " +
         html_escape(title_) +
         "</title>\n<style>\n"
         "body { font-family: Helvetica, Arial, sans-serif; max-width: 1100px; margin: 2em auto; padding: 0 1em; "
         "color: #222; line-height: 1.45; }\n"
         "h1 { border-bottom: 2px solid #1f77b4; padding-bottom: 0.2em; }\n"
         "h2 { margin-top: 2em; color: #1f4e79; }\n"
         "table { border-collapse: collapse; margin: 0.8em 0; font-size: 0.9em; display: block; overflow-x: auto; }\n"
         "th, td { border: 1px solid #bbb; padding: 0.25em 0.6em; text-align: right; white-space: nowrap; }\n"
         "th { background: #e8eef5; } td:first-child, th:first-child { text-align: left; }\n"
         "tr:nth-child(even) td { background: #f7f9fb; }\n"
         "pre { background: #f4f4f4; padding: 0.8em; overflow-x: auto; font-size: 0.85em; }\n"
         "figure { margin: 1.5em 0; } figure svg, figure img { max-width: 100%; height: auto; border: 1px solid #ddd; }\n"
         "figcaption { font-size: 0.9em; color: #555; } .saved { font-size: 0.8em; color: #777; }\n"
         "</style>\n</head>\n<body>\n<h1>numlab lab " +
         html_escape(title_) + "</h1>\n<p><em>" + html_escape(summary_) + "</em></p>\n" + body_ + "</body>\n</html>\n";
}

}  // namespace numlab::cli
