#pragma once
// The look every numlab HTML report shares (the labs' report.html, the exercise checker's
// report.html): one self-contained page, styles inline, readable offline in any browser.

#include <string>

namespace numlab::cli {

// Text with &, <, > and " escaped for HTML.
std::string html_escape(const std::string& text);

// A whole HTML page in numlab's report style: `title` (plain text) is its <title> and <h1>;
// `body` is HTML placed after the heading; `extra_css` adds rules of the page's own.
std::string html_page(const std::string& title, const std::string& body, const std::string& extra_css = "");

}  // namespace numlab::cli
