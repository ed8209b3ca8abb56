#include "output/report_style.hpp"

namespace numlab::cli {

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

std::string html_page(const std::string& title, const std::string& body, const std::string& extra_css) {
  return "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>" + html_escape(title) +
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
         "figcaption { font-size: 0.9em; color: #555; } .saved { font-size: 0.8em; color: #777; }\n" +
         extra_css + "</style>\n</head>\n<body>\n<h1>" + html_escape(title) + "</h1>\n" + body + "</body>\n</html>\n";
}

}  // namespace numlab::cli
