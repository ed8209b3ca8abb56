#include "cli/cli_common.hpp"

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <stdexcept>

namespace numlab::cli {

void add_common_options(CLI::App& command, CommonOptions& options) {
  const std::map<std::string, Format> formats = {{"text", Format::text}, {"json", Format::json}, {"csv", Format::csv}};
  command.add_option("--format", options.format, "Output format: text, json or csv")
      ->transform(CLI::CheckedTransformer(formats, CLI::ignore_case));
  command.add_flag("--trace", options.trace, "Print every step (stderr in text mode, \"trace\" in JSON)");
  command.add_flag("--step", options.step, "Pause after each step until Enter (only when stdin is a terminal)");
  command.add_option("--tol", options.tolerance, "Override the method's tolerance (non-negative)")
      ->check(CLI::Validator(
          [](std::string& value) -> std::string {
            const double number = std::stod(value);
            return number >= 0.0 ? "" : "tolerance must be non-negative, got " + value;
          },
          "NONNEGATIVE"));
  command.add_option("--max-iter", options.max_iterations, "Override the iteration limit (at least 1)")
      ->check(CLI::PositiveNumber);
  command.add_option("--out", options.out_dir, "Folder for the files written (default out/)");
}

nlohmann::ordered_json number_or_null(double value) {
  return std::isfinite(value) ? nlohmann::ordered_json(value) : nlohmann::ordered_json();
}

int exit_code_for(Status status) { return status == Status::converged ? exit_success : exit_method_failed; }

void pause_if_stepping(bool step) {
  if (!step || isatty(STDIN_FILENO) == 0) return;
  std::cerr << "  -- press Enter to continue --" << std::flush;
  std::string ignored;
  std::getline(std::cin, ignored);
}

void ensure_directory(const std::string& path) {
  std::error_code error;
  std::filesystem::create_directories(path, error);
  if (error || !std::filesystem::is_directory(path)) {
    throw std::invalid_argument("cannot create output folder '" + path + "'");
  }
}

void write_file_atomically(const std::string& path, const std::string& contents) {
  const std::string temporary = path + ".partial";
  {
    std::ofstream file(temporary, std::ios::binary | std::ios::trunc);
    if (!file) throw std::invalid_argument("cannot write '" + path + "'");
    file << contents;
    if (!file.flush()) throw std::invalid_argument("cannot write '" + path + "'");
  }
  std::filesystem::rename(temporary, path);
}

}  // namespace numlab::cli
