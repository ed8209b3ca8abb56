#pragma once
// A shipped linkage file at another length scale: every length in its TOML text multiplied by k
// (the joints' rough positions, link lengths, body points, a slider's through, offset and travel, an
// actuator's length, a torque load: N times the length unit). Angles, forces and masses stay. The
// text is rewritten, not the parsed description, so the reader sees the scaled numbers too.

#include <fmt/format.h>

#include <cstddef>
#include <regex>
#include <set>
#include <sstream>
#include <string>

namespace numlab::mechanisms::testing {

// `value` (the right side of `key = value`, comment removed) with every number times k.
inline std::string scaled_numbers(const std::string& value, double k) {
  static const std::regex number(R"([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)");
  std::string out;
  std::size_t done = 0;
  for (auto it = std::sregex_iterator(value.begin(), value.end(), number); it != std::sregex_iterator(); ++it) {
    out += value.substr(done, static_cast<std::size_t>(it->position()) - done);
    out += fmt::format("{:.17g}", std::stod(it->str()) * k);
    done = static_cast<std::size_t>(it->position() + it->length());
  }
  return out + value.substr(done);
}

// The TOML text with every length times k, line by line:
//  1. a table header ([ground], [[link]], ...) names the section;
//  2. in [ground] and [joints] every value is a position; elsewhere the keys below are lengths;
//  3. a length's numbers are multiplied, the rest of the line kept (comments dropped).
inline std::string scaled_model_text(const std::string& text, double k) {
  static const std::set<std::string> lengths = {"length", "offset", "travel", "through", "local", "torque"};
  static const std::regex header(R"(^\s*\[\[?\s*([A-Za-z_]+)\s*\]\]?)");
  static const std::regex assignment(R"(^(\s*([A-Za-z0-9_-]+)\s*=)([^#]*))");
  std::istringstream lines(text);
  std::string line, section, out;
  while (std::getline(lines, line)) {
    std::smatch m;
    if (std::regex_search(line, m, header)) {
      section = m[1];
    } else if (std::regex_search(line, m, assignment) &&
               (section == "ground" || section == "joints" || lengths.count(m[2].str()) > 0)) {
      line = m[1].str() + scaled_numbers(m[3].str(), k);
    }
    out += line + "\n";
  }
  return out;
}

}  // namespace numlab::mechanisms::testing
