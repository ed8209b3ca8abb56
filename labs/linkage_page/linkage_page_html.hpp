#pragma once
// A linkage page: one self-contained HTML file (inline CSS, SVG and JavaScript written for numlab,
// no network) with the scene and a crank slider that scrubs the solved poses (docs/mechanisms.md,
// "A linkage you can drag"). The data is linkage_page_data's JSON, embedded as it is. Without
// scripts the page shows `static_svg` (one pose drawn by numlab's scenes) and a table of every pose.

#include <nlohmann/json.hpp>
#include <string>

namespace numlab::cli {

std::string linkage_page_html(const nlohmann::ordered_json& data, const std::string& static_svg,
                              const std::string& static_caption);

// The page's script and style, embedded in the program at build time from linkage_page.js and
// linkage_page.css (page_assets.cpp.in).
const char* linkage_page_script();
const char* linkage_page_style();

}  // namespace numlab::cli
