#pragma once
// What every `numlab` sub-command shares: the common flags, exit codes, and --step pauses.

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "numlab/status.hpp"

namespace numlab::cli {

enum class Format { text, json, csv };

struct CommonOptions {
  Format format = Format::text;
  bool trace = false;
  bool step = false;
  std::optional<double> tolerance;
  std::optional<int> max_iterations;
  std::string out_dir = "out";
};

// Adds --format, --trace, --step, --tol, --max-iter and --out to a sub-command.
void add_common_options(CLI::App& command, CommonOptions& options);

// Exit codes of docs/cli.md: 0 the method succeeded, 1 it ran but did not succeed, 2 bad input.
constexpr int exit_success = 0;
constexpr int exit_method_failed = 1;
constexpr int exit_bad_input = 2;
int exit_code_for(Status status);

// With --step, waits for Enter; only when stdin is a terminal, so scripts and CI never block.
void pause_if_stepping(bool step);

// A number for JSON output, or null when it is NaN or infinite (JSON has no such numbers).
nlohmann::ordered_json number_or_null(double value);

// Creates the output folder (and parents); throws std::invalid_argument naming it on failure.
void ensure_directory(const std::string& path);

// Writes a file whole or not at all: to a temporary name first, then renamed into place.
void write_file_atomically(const std::string& path, const std::string& contents);

}  // namespace numlab::cli
