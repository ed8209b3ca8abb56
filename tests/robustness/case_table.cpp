#include "case_table.hpp"

#include <cctype>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>

namespace numlab::robustness {

namespace {

std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  std::string part;
  std::istringstream stream(text);
  while (std::getline(stream, part, separator)) {
    if (!part.empty() || separator == '\t') parts.push_back(part);
  }
  return parts;
}

int hex_digit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  throw std::runtime_error(std::string("bad hex digit '") + c + "'");
}

std::vector<int> parse_exit_codes(const std::string& field) {
  std::vector<int> codes;
  for (const std::string& code : split(field, '|')) {
    if (code != "0" && code != "1" && code != "2") throw std::runtime_error("exit code must be 0, 1 or 2: " + field);
    codes.push_back(code[0] - '0');
  }
  if (codes.empty()) throw std::runtime_error("no exit code");
  return codes;
}

// A misspelt check would never fail, so only these forms are accepted.
bool known_check(const std::string& check) {
  if (check == "json" || check == "short") return true;
  for (const char* prefix : {"status=", "out~", "out!~", "err~", "err!~", "made=", "mem="}) {
    if (check.starts_with(prefix) && check.size() > std::string(prefix).size()) return true;
  }
  return false;
}

Case parse_row(const std::string& line, const std::string& nist_dir) {
  // 1. Seven tab-separated fields: id, exit, seconds, writes, checks, arguments, note.
  const std::vector<std::string> fields = split(line, '\t');
  if (fields.size() != 7) throw std::runtime_error("expected 7 tab-separated fields, got " + std::to_string(fields.size()));
  Case row;
  row.id = fields[0];
  for (const char c : row.id) {
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_' && c != '.') {
      throw std::runtime_error("id '" + row.id + "' may hold only letters, digits, '-', '_' and '.'");
    }
  }
  // 2. The expected exit codes and the time limit.
  row.exit_codes = parse_exit_codes(fields[1]);
  row.seconds = std::stod(fields[2]);
  if (!(row.seconds > 0)) throw std::runtime_error("the time limit must be positive");
  // 3. The allowed new files ("-": none) and the extra checks ("-": none).
  if (fields[3] != "-") row.writes = split(fields[3], ',');
  if (fields[4] != "-") row.checks = split(fields[4], ' ');
  for (const std::string& check : row.checks) {
    if (!known_check(check)) throw std::runtime_error("unknown check '" + check + "'");
  }
  // 4. The arguments, one word per space, each decoded.
  for (const std::string& word : split(fields[5], ' ')) row.arguments.push_back(decode_word(word, nist_dir));
  row.note = fields[6];
  return row;
}

}  // namespace

std::string decode_word(const std::string& word, const std::string& nist_dir) {
  if (word == "''") return "";
  if (word == "{LONG}") return std::string(100000, 'a');
  std::string decoded;
  for (std::size_t i = 0; i < word.size(); ++i) {
    if (word.compare(i, 6, "{NIST}") == 0) {
      decoded += nist_dir;
      i += 5;
    } else if (word[i] != '\\' || i + 1 == word.size()) {
      decoded += word[i];
    } else if (word[i + 1] == 's') {
      decoded += ' ';
      ++i;
    } else if (word[i + 1] == '\\') {
      decoded += '\\';
      ++i;
    } else if (word[i + 1] == 'x' && i + 3 < word.size()) {
      decoded += static_cast<char>(hex_digit(word[i + 2]) * 16 + hex_digit(word[i + 3]));
      i += 3;
    } else {
      throw std::runtime_error("unknown escape in '" + word + "'");
    }
  }
  return decoded;
}

std::vector<Case> read_cases(const std::string& path, const std::string& nist_dir) {
  std::ifstream file(path);
  if (!file) throw std::runtime_error("cannot read " + path);
  std::vector<Case> cases;
  std::set<std::string> ids;
  std::string line;
  for (int number = 1; std::getline(file, line); ++number) {
    if (line.empty() || line[0] == '#') continue;
    try {
      cases.push_back(parse_row(line, nist_dir));
    } catch (const std::exception& error) {
      throw std::runtime_error(path + ":" + std::to_string(number) + ": " + error.what());
    }
    if (!ids.insert(cases.back().id).second) {
      throw std::runtime_error(path + ":" + std::to_string(number) + ": id '" + cases.back().id + "' repeated");
    }
  }
  return cases;
}

}  // namespace numlab::robustness
