#include "commands/common_options.hpp"

#include <CLI/CLI.hpp>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <iostream>

#include "numlab/printable_text.hpp"

namespace numlab::cli {

namespace {

namespace fs = std::filesystem;

// The largest --max-iter: beyond it a run is a hang, not a lesson.
constexpr long long max_iteration_limit = 100'000'000;

std::string lower_case(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return std::tolower(c); });
  return text;
}

std::optional<Format> format_named(const std::string& text) {
  const std::string name = lower_case(text);
  if (name == "text") return Format::text;
  if (name == "json") return Format::json;
  if (name == "csv") return Format::csv;
  return std::nullopt;
}

// The validators return "" when the value is good, else what is wrong (CLI11 puts "--flag: " before it).
std::string tolerance_problem(const std::string& text) {
  double value = 0.0;
  const char* first = text.data() + (text.starts_with('+') ? 1 : 0);
  const auto [end, error] = std::from_chars(first, text.data() + text.size(), value);
  const bool number = !text.empty() && error == std::errc() && end == text.data() + text.size();
  if (number && std::isfinite(value) && value >= 0.0) return "";
  return "must be a finite number >= 0 (e.g. 1e-10), got '" + text + "'";
}

std::string iteration_limit_problem(const std::string& text) {
  long long value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  const bool whole = !text.empty() && error == std::errc() && end == text.data() + text.size();
  if (whole && value >= 1 && value <= max_iteration_limit) return "";
  return "must be a whole number from 1 to " + std::to_string(max_iteration_limit) + ", got '" + text + "'";
}

std::string names_honouring(bool CommonFlagUse::*flag) {
  std::string names;
  for (const CommonFlagUse& use : common_flag_table()) {
    if (use.*flag) names += (names.empty() ? "" : ", ") + std::string(use.name);
  }
  return names;
}


}  // namespace

CLI::Validator finite_non_negative() { return CLI::Validator(tolerance_problem, "T>=0"); }

void add_common_options(CLI::App& command, CommonOptions& options) {
  options.command = &command;
  command
      .add_option_function<std::string>(
          "--format", [&options](const std::string& text) { options.format = *format_named(text); },
          "Output format: text, json or csv")
      ->check(CLI::Validator(
          [](std::string& text) { return format_named(text) ? "" : "must be text, json or csv, got '" + text + "'"; },
          "text|json|csv"));
  command.add_flag("--trace", options.trace, "Print every step (stderr in text and CSV, \"trace\" in JSON)");
  command.add_flag("--step", options.step, "Pause after each step (implies --trace); q + Enter stops (terminal only)");
  command.add_option("--tol", options.tolerance, "Override the method's tolerance (finite, >= 0)")
      ->check(finite_non_negative());
  command.add_option("--max-iter", options.max_iterations, "Override the iteration limit (1 to 100000000)")
      ->check(CLI::Validator(iteration_limit_problem, "N>=1"));
  command.add_option("--out", options.out_dir, "Folder for the files written (default out/)")
      ->check(CLI::Validator(
          [](std::string& text) {
            if (text.empty()) return std::string("must name a folder, got an empty name");
            // printable() escapes control bytes (C0, DEL, C1), bidi controls and invisible marks.
            const bool odd = text.find('\'') != std::string::npos || printable(text) != text;
            return odd ? "'" + text + "': a folder name without quotes, control or invisible characters, please"
                       : std::string();
          },
          "DIR"));
}

bool given(const CLI::App& command, std::string_view flag) { return command.count(std::string(flag)) > 0; }

bool given(const CommonOptions& options, std::string_view flag) {
  return options.command != nullptr && given(*options.command, flag);
}

const std::vector<CommonFlagUse>& common_flag_table() {
  // name               json   csv    trace  step   tol    max-iter out
  static const std::vector<CommonFlagUse> table = {
      {"solve linear", true, true, true, true, true, true, false},
      {"solve nonlinear", true, true, true, true, true, true, false},
      {"mechanism", true, true, true, true, true, true, true},
      {"fit", true, true, true, false, true, true, true},
      {"lab", false, false, false, true, false, false, true},
      {"bench all", true, false, false, false, false, false, true},
      {"bench linear", true, true, false, false, false, false, true},
      {"bench jansen", true, false, false, false, true, false, false},
      {"bench mustang", true, false, false, false, true, false, false},
      {"bench quick-return", true, false, false, false, true, false, false},
      {"bench fit", true, false, false, false, false, false, true},
      {"bench robustness", true, false, false, false, false, false, true},
      {"bench linkage-scaling", true, true, false, false, false, false, false},
      {"bench grade", false, false, false, false, false, false, false},
      {"exercise check", true, false, false, false, false, false, true},
      {"basins", true, true, false, false, false, true, true},
      {"bench basins", true, false, false, false, false, false, false},
      {"models", true, false, false, false, false, false, false},
  };
  return table;
}

void require_applies(bool was_given, bool applies, std::string_view flag, std::string_view where) {
  if (was_given && !applies) throw std::invalid_argument(std::string(flag) + " applies only to " + std::string(where));
}

CommonOptions checked_common_options(const CommonOptions& options, std::string_view name) {
  const auto found = std::find_if(common_flag_table().begin(), common_flag_table().end(),
                                  [&](const CommonFlagUse& use) { return use.name == name; });
  if (found == common_flag_table().end()) throw std::logic_error("no shared-flag row for " + std::string(name));
  const std::string command = "numlab " + std::string(name);
  const auto reject = [&](std::string_view flag, bool CommonFlagUse::*member) {
    if (given(options, flag) && !((*found).*member)) {
      throw std::invalid_argument(std::string(flag) + " does not apply to " + command + " (it applies to: " +
                                  names_honouring(member) + ")");
    }
  };
  const auto reject_format = [&](Format format, std::string_view word, bool CommonFlagUse::*member) {
    if (options.format == format && !((*found).*member)) {
      throw std::invalid_argument("--format " + std::string(word) + " does not apply to " + command +
                                  " (it applies to: " + names_honouring(member) + ")");
    }
  };
  reject_format(Format::json, "json", &CommonFlagUse::json);
  reject_format(Format::csv, "csv", &CommonFlagUse::csv);
  reject("--trace", &CommonFlagUse::trace);
  reject("--step", &CommonFlagUse::step);
  reject("--tol", &CommonFlagUse::tol);
  reject("--max-iter", &CommonFlagUse::max_iter);
  reject("--out", &CommonFlagUse::out);

  CommonOptions checked = options;
  // --step pauses after each traced step, so it shows the trace (a lab's steps are its own).
  if (checked.step && found->trace) checked.trace = true;
  return checked;
}

int report_stopped(const CommonOptions& options, nlohmann::ordered_json partial, const nlohmann::ordered_json& trace) {
  const std::size_t steps = trace.size();
  if (options.format == Format::json) {
    partial["status"] = std::string(stopped_status);
    partial["steps_done"] = steps;
    partial["trace"] = trace;
    std::cout << partial.dump(2) << '\n';
  } else if (options.format == Format::csv) {
    std::cout << "status,steps_done\n" << stopped_status << ',' << steps << '\n';
  } else {
    std::cout << "status             " << stopped_status << " (q after " << steps
              << " traced steps; the trace above shows them)\n";
  }
  return exit_method_failed;
}

std::string output_path(const CommonOptions& options, const std::string& path) {
  if (path.empty() || !given(options, "--out") || fs::path(path).is_absolute()) return path;
  return (fs::path(options.out_dir) / path).string();
}

}  // namespace numlab::cli
