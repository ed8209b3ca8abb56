#include "verdict.hpp"

#include <fnmatch.h>

#include <algorithm>
#include <nlohmann/json.hpp>
#include <sstream>

namespace numlab::robustness {

namespace {

// Shows a text in a failure message: control and non-ASCII bytes as \xNN, at most 300 bytes.
std::string shown(const std::string& text) {
  std::string result;
  for (const char c : text.substr(0, 300)) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte >= 0x20 && byte < 0x7f) {
      result += c;
    } else {
      constexpr char digits[] = "0123456789abcdef";
      result += std::string("\\x") + digits[byte >> 4] + digits[byte & 15];
    }
  }
  return text.size() > 300 ? result + "... (" + std::to_string(text.size()) + " bytes)" : result;
}

bool valid_utf8(const std::string& text) {
  for (std::size_t i = 0; i < text.size();) {
    const auto lead = static_cast<unsigned char>(text[i]);
    const int length = lead < 0x80 ? 1 : (lead >> 5) == 6 ? 2 : (lead >> 4) == 14 ? 3 : (lead >> 3) == 30 ? 4 : 0;
    if (length == 0 || i + length > text.size()) return false;
    for (int k = 1; k < length; ++k) {
      if ((static_cast<unsigned char>(text[i + k]) & 0xc0) != 0x80) return false;
    }
    i += length;
  }
  return true;
}

// The C0 controls and DEL, which can move a terminal's cursor or retitle it; UTF-8's C1 controls
// (U+0080..U+009F) are checked too.
bool has_control(const std::string& line) {
  for (std::size_t i = 0; i < line.size(); ++i) {
    const auto byte = static_cast<unsigned char>(line[i]);
    if (byte < 0x20 || byte == 0x7f) return true;
    if (byte == 0xc2 && i + 1 < line.size() && static_cast<unsigned char>(line[i + 1]) < 0xa0) return true;
  }
  return false;
}

bool asks_for_json(const std::vector<std::string>& arguments) {
  for (std::size_t i = 0; i < arguments.size(); ++i) {
    if (arguments[i] == "--format=json") return true;
    if (arguments[i] == "--format" && i + 1 < arguments.size() && arguments[i + 1] == "json") return true;
  }
  return false;
}

// One line on stderr that starts "numlab: error:", printable, without a 100 kB echo.
void judge_error_line(const std::string& out, const std::string& err, std::vector<std::string>& failures) {
  if (!out.empty()) failures.push_back("exit 2 but stdout is not empty: " + shown(out));
  const auto lines = std::count(err.begin(), err.end(), '\n');
  if (lines != 1 || err.back() != '\n') {
    failures.push_back("stderr is not exactly one line (" + std::to_string(lines) + " newlines): " + shown(err));
    return;
  }
  const std::string line = err.substr(0, err.size() - 1);
  if (!line.starts_with("numlab: error: ")) failures.push_back("stderr does not start 'numlab: error: ': " + shown(err));
  if (has_control(line)) failures.push_back("stderr carries raw control bytes: " + shown(line));
  if (!valid_utf8(line)) failures.push_back("stderr is not valid UTF-8: " + shown(line));
  if (line.size() > 1000) failures.push_back("stderr line is " + std::to_string(line.size()) + " bytes long");
}

// The row's extra checks on the run: json, status=S, out~T, out!~T, err~T, err!~T, short, mem=MB
// (made=PATH is judged with the files).
void judge_extra(const std::string& check, const ChildResult& run, const std::string& out, const std::string& err,
                 std::vector<std::string>& failures) {
  const auto contains = [](const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
  };
  const std::string raw = check.substr(check.find_first_of("~=") + 1);
  std::string wanted;  // \s stands for a space
  for (std::size_t i = 0; i < raw.size(); ++i) {
    const bool space = raw[i] == '\\' && i + 1 < raw.size() && raw[i + 1] == 's';
    wanted += space ? ' ' : raw[i];
    i += space ? 1 : 0;
  }
  if (check == "json") {
    // checked with the exit code below
  } else if (check.starts_with("status=")) {
    const auto json = nlohmann::json::parse(out, nullptr, false);
    const std::string status = json.is_object() && json.contains("status") ? json["status"].dump() : "(none)";
    if (status != "\"" + wanted + "\"") failures.push_back("JSON status is " + status + ", expected " + wanted);
  } else if (check.starts_with("out~") && !contains(out, wanted)) {
    failures.push_back("stdout lacks '" + wanted + "'");
  } else if (check.starts_with("out!~") && contains(out, wanted)) {
    failures.push_back("stdout contains '" + wanted + "'");
  } else if (check.starts_with("err~") && !contains(err, wanted)) {
    failures.push_back("stderr lacks '" + wanted + "': " + shown(err));
  } else if (check.starts_with("err!~") && contains(err, wanted)) {
    failures.push_back("stderr contains '" + wanted + "': " + shown(err));
  } else if (check == "short" && err.size() > 161) {
    failures.push_back("error line longer than 160 characters: " + shown(err));
  } else if (check.starts_with("mem=")) {
    // A refused input is refused before it is read whole; AddressSanitizer's shadow memory
    // triples a program's resident size.
    const double limit = std::stod(wanted) * (NUMLAB_CHILD_SANITIZED ? 3 : 1);
    if (run.peak_mb > limit) {
      failures.push_back("used " + std::to_string(static_cast<long>(run.peak_mb)) + " MB, more than " +
                         std::to_string(static_cast<long>(limit)) + " MB");
    }
  }
}

bool allowed(const std::string& path, const std::vector<std::string>& writes) {
  for (const std::string& pattern : writes) {
    if (pattern.ends_with("/") && (path + "/" == pattern || path.starts_with(pattern))) return true;  // a folder's tree
    if (pattern.starts_with(path + "/")) return true;  // a folder on the way to an allowed file
    if (fnmatch(pattern.c_str(), path.c_str(), FNM_PATHNAME) == 0) return true;
  }
  return false;
}

}  // namespace

std::vector<std::string> judge_run(const Case& row, const ChildResult& run, double time_limit, const std::string& out,
                                   const std::string& err) {
  std::vector<std::string> failures;
  // 1. It ended by itself, in time.
  if (run.timed_out) {
    failures.push_back("no answer within " + std::to_string(time_limit) + " s: killed (a hang)");
    return failures;
  }
  if (run.signal != 0) {
    failures.push_back("killed by signal " + std::to_string(run.signal) + "; stderr: " + shown(err));
    return failures;
  }
  // 2. The exit code the contract names.
  if (std::find(row.exit_codes.begin(), row.exit_codes.end(), run.exit_code) == row.exit_codes.end()) {
    std::ostringstream message;
    message << "exit " << run.exit_code << ", expected " << row.exit_codes.front();
    for (std::size_t i = 1; i < row.exit_codes.size(); ++i) message << " or " << row.exit_codes[i];
    failures.push_back(message.str() + "; stderr: " + shown(err));
  }
  // 3. No crash report, whatever the exit code.
  for (const std::string report : {"terminate called", "Sanitizer", "runtime error:"}) {
    if (err.find(report) != std::string::npos) failures.push_back("stderr reports a crash: " + shown(err));
  }
  // 4. The shape of the output: an error line, or valid JSON when JSON was asked for.
  if (run.exit_code == 2) judge_error_line(out, err, failures);
  const bool json_wanted = asks_for_json(row.arguments) || std::find(row.checks.begin(), row.checks.end(), "json") != row.checks.end();
  if ((run.exit_code == 0 || run.exit_code == 1) && json_wanted && !nlohmann::json::accept(out)) {
    failures.push_back("stdout is not valid JSON: " + shown(out));
  }
  // 5. The row's own checks.
  for (const std::string& check : row.checks) judge_extra(check, run, out, err, failures);
  return failures;
}

std::vector<std::string> judge_files(const Case& row, int exit_code, const std::map<std::string, std::string>& before,
                                     const std::map<std::string, std::string>& after) {
  std::vector<std::string> failures;
  // 1. Every prepared file still there, unchanged.
  for (const auto& [path, state] : before) {
    const auto now = after.find(path);
    if (now == after.end()) {
      failures.push_back("prepared '" + shown(path) + "' was removed");
    } else if (now->second != state) {
      failures.push_back("prepared '" + shown(path) + "' was changed");
    }
  }
  // 2. New entries only where the row allows, and no half-written files.
  for (const auto& [path, state] : after) {
    if (path.ends_with(".partial")) failures.push_back("leftover '" + shown(path) + "'");
    if (before.count(path) != 0 || allowed(path, row.writes)) continue;
    // A new folder that is not allowed is named once, not with every file inside it.
    const std::string parent = path.substr(0, path.rfind('/') == std::string::npos ? 0 : path.rfind('/'));
    if (parent.empty() || before.count(parent) != 0 || allowed(parent, row.writes)) {
      failures.push_back("wrote '" + shown(path) + (state == "dir" ? "/', not asked for" : "', not asked for"));
    }
  }
  // 3. The files a success promises.
  for (const std::string& check : row.checks) {
    if (exit_code == 0 && check.starts_with("made=") && after.count(check.substr(5)) == 0) {
      failures.push_back("exit 0 but '" + check.substr(5) + "' was not written");
    }
  }
  return failures;
}

}  // namespace numlab::robustness
