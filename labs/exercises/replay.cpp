#include "exercises/replay.hpp"

#include <fmt/format.h>

#include <cctype>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace numlab::exercises {

namespace {

constexpr std::size_t max_slug = 60;
constexpr std::size_t shown_columns = 240;

std::invalid_argument bad_file(const std::string& path, const std::string& why) {
  return std::invalid_argument(fmt::format("exercise replay: {}: {}", path, why));
}

// JSON on one line, cut to `shown_columns` with the length left out said.
std::string one_line(const nlohmann::json& value) {
  std::string text = value.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  if (text.size() <= shown_columns) return text;
  return fmt::format("{} ... ({} characters more)", text.substr(0, shown_columns), text.size() - shown_columns);
}

// The reply without the "id" it echoes.
nlohmann::json without_id(nlohmann::json reply) {
  if (reply.is_object()) reply.erase("id");
  return reply;
}

}  // namespace

std::string replay_file_name(int place, const std::string& check_name) {
  std::string slug;
  bool gap = false;
  for (const char c : check_name) {
    const unsigned char u = static_cast<unsigned char>(c);
    if (std::isalnum(u) && u < 128) {
      if (gap && !slug.empty()) slug += '-';
      slug += static_cast<char>(std::tolower(u));
      gap = false;
    } else {
      gap = true;
    }
  }
  if (slug.size() > max_slug) {
    const std::size_t cut = slug.rfind('-', max_slug);
    slug.resize(cut == std::string::npos || cut == 0 ? max_slug : cut);
  }
  return fmt::format("{:02}-{}.jsonl", place, slug.empty() ? "check" : slug);
}

std::string replay_lines(const CheckResult& result, const Variant& variant) {
  std::string text;
  for (const Exchange& exchange : result.exchanges) {
    nlohmann::ordered_json line;
    line["check"] = result.name;
    if (variant.active()) line["variant"] = *variant.id();
    line["inputs"] = exchange.expected.inputs;
    line["request"] = exchange.request;
    line["expected"] = exchange.expected.reply;
    line["property"] = exchange.expected.property.empty() ? result.name : exchange.expected.property;
    if (exchange.error.empty()) {
      line["your_reply"] = exchange.reply;
    } else {
      line["your_error"] = exchange.error;
    }
    text += line.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) + '\n';
  }
  return text;
}

ReplayFile read_replay_file(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw bad_file(path, "cannot be read (no such file, or not readable)");
  ReplayFile file;
  std::string text;
  int number = 0;
  while (std::getline(in, text)) {
    ++number;
    if (text.find_first_not_of(" \t\r") == std::string::npos) continue;
    nlohmann::json line;
    try {
      line = nlohmann::json::parse(text);
    } catch (const nlohmann::json::exception&) {
      throw bad_file(path, fmt::format("line {} is not JSON (a replay file is JSON Lines, as `exercise check --out` "
                                       "writes it)", number));
    }
    if (!line.is_object() || !line.contains("check") || !line["check"].is_string() || !line.contains("request") ||
        !line["request"].is_object() || !line["request"].contains("exercise") ||
        !line["request"]["exercise"].is_string()) {
      throw bad_file(path, fmt::format("line {} is not a replay line: it needs \"check\" and a \"request\" object "
                                       "with \"exercise\"", number));
    }
    const std::string exercise = line["request"]["exercise"].get<std::string>();
    const std::string check = line["check"].get<std::string>();
    if (file.requests.empty()) {
      file.exercise = exercise;
      file.check = check;
    } else if (exercise != file.exercise || check != file.check) {
      throw bad_file(path, fmt::format("line {} is from another check than line 1 (one file replays one check)", number));
    }
    if (line.contains("variant")) {
      const auto& id = line["variant"];
      if (!id.is_string() || !variant_id_problem(id.get<std::string>()).empty()) {
        throw bad_file(path, fmt::format("line {}: \"variant\" is not a variant ID (a non-empty string without "
                                         "control characters)", number));
      }
      if (file.requests.empty()) file.variant = Variant(id.get<std::string>());
    }
    const std::string variant_id = file.variant.active() ? *file.variant.id() : "";
    if (!file.requests.empty() && line.value("variant", std::string()) != variant_id) {
      throw bad_file(path, fmt::format("line {} is from another variant than line 1 (one file replays one check)", number));
    }
    file.requests.push_back(line["request"]);
  }
  if (in.bad()) throw bad_file(path, "cannot be read");
  if (file.requests.empty()) throw bad_file(path, "holds no request");
  return file;
}

Check find_check(const Exercise& exercise, const std::string& name, const Variant& variant) {
  for (Check& check : exercise.battery(variant)) {
    if (check.name == name) return check;
  }
  throw std::invalid_argument(
      fmt::format("exercise replay: the exercise '{}' has no check \"{}\" (`numlab exercise check {}` lists them)",
                  exercise.name, name, exercise.name));
}

std::string requests_mismatch(const ReplayFile& file, const CheckResult& result) {
  const std::size_t both = std::min(file.requests.size(), result.exchanges.size());
  for (std::size_t k = 0; k < both; ++k) {
    if (file.requests[k] != result.exchanges[k].request) {
      return fmt::format("request {} is not the file's: the check now sends other inputs (an edited file, or one "
                         "written by another numlab version)", k + 1);
    }
  }
  return "";
}

std::string replay_text(const CheckResult& result, const std::string& mismatch) {
  std::string text = fmt::format("Replaying \"{}\": {} request{}\n", result.name, result.exchanges.size(),
                                 result.exchanges.size() == 1 ? "" : "s");
  if (!mismatch.empty()) text += "Note: " + mismatch + '\n';
  for (std::size_t k = 0; k < result.exchanges.size(); ++k) {
    const Exchange& exchange = result.exchanges[k];
    text += fmt::format("\nrequest {}{}\n", k + 1, exchange.expected.inputs.empty() ? "" : ": " + exchange.expected.inputs);
    text += "  sent:     " + one_line(exchange.request) + '\n';
    text += "  yours:    " + (exchange.error.empty() ? one_line(without_id(exchange.reply)) : "(" + exchange.error + ")") + '\n';
    text += "  expected: " + (exchange.expected.reply.is_null() ? std::string("(no single reply; see below)")
                                                                 : one_line(exchange.expected.reply)) + '\n';
    text += "  checked:  " + (exchange.expected.property.empty() ? result.name : exchange.expected.property) + '\n';
  }
  text += '\n';
  if (result.status == CheckStatus::pass) {
    text += "✓ " + result.name + "\nEvery reply agrees with numlab's within the check's tolerance.\n";
  } else {
    text += "✗ " + result.name + (result.status == CheckStatus::error ? " (error)" : "") + '\n';
    std::string told = result.message;
    if (const std::string why = explanation(result); !why.empty()) told.append("\n").append(why);
    std::istringstream lines(told);
    std::string line;
    while (std::getline(lines, line)) text += "    " + line + '\n';
  }
  return text;
}

}  // namespace numlab::exercises
