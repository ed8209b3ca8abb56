#pragma once
// What every `numlab` sub-command shares: the common flags and where each applies, exit codes,
// --step pauses, and the rules for the files a command writes.

#include <nlohmann/json.hpp>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "numlab/status.hpp"

// CLI11 is only named here (a sub-command and a validator): the files that build commands include
// <CLI/CLI.hpp> themselves, so the ~30 files that only print and compute do not compile it.
namespace CLI {
class App;
class Validator;
}  // namespace CLI

namespace numlab::cli {

enum class Format { text, json, csv };

struct CommonOptions {
  Format format = Format::text;
  bool trace = false;
  bool step = false;
  std::optional<double> tolerance;
  std::optional<int> max_iterations;
  std::string out_dir = "out";
  const CLI::App* command = nullptr;  // where they were parsed: given() asks it
};

// Adds --format, --trace, --step, --tol, --max-iter and --out to a sub-command, each value checked
// as it is parsed (docs/cli.md, "Flags every command shares").
void add_common_options(CLI::App& command, CommonOptions& options);

// Checks a tolerance as it is parsed: a finite number >= 0 (--tol, --step-tol).
CLI::Validator finite_non_negative();

// Whether the user gave `flag` (e.g. "--out") on the command line.
bool given(const CommonOptions& options, std::string_view flag);
bool given(const CLI::App& command, std::string_view flag);

// Which shared flags a sub-command honours: the one table behind docs/cli.md's "Which shared flags
// apply where". `name` is how the command is written ("solve linear", "bench jansen", "lab").
struct CommonFlagUse {
  std::string_view name;
  bool json, csv, trace, step, tol, max_iter, out;
};
const std::vector<CommonFlagUse>& common_flag_table();

// Checks the shared flags given to command `name` against the table: each one it does not honour
// is bad input (std::invalid_argument naming where the flag applies). Returns the options to run
// with: --step turns --trace on.
CommonOptions checked_common_options(const CommonOptions& options, std::string_view name);

// "--flag applies only to X" as bad input, when `applies` is false and the flag was given.
void require_applies(bool given, bool applies, std::string_view flag, std::string_view where);

// Exit codes of docs/cli.md: 0 the method succeeded, 1 it ran but did not succeed (or was stopped
// with q at a --step pause), 2 bad input.
constexpr int exit_success = 0;
constexpr int exit_method_failed = 1;
constexpr int exit_bad_input = 2;
int exit_code_for(Status status);

// Thrown at a --step pause when the user types q: the command reports what ran and exits 1.
struct StoppedByUser : std::runtime_error {
  StoppedByUser() : std::runtime_error("stopped by the user (q at a --step pause)") {}
};
// The status word a stopped command prints.
constexpr std::string_view stopped_status = "stopped_by_user";

// With --step and stdin a terminal: waits for Enter, or throws StoppedByUser on q + Enter (or at
// the end of input). Without a terminal it never waits (scripts and CI never block): the first
// call prints one note on stderr, the others nothing.
void pause_if_stepping(bool step);
// Seconds spent waiting at pauses so far, for printed times that leave them out.
double paused_seconds();
// After StoppedByUser: prints what ran and returns exit 1. JSON: `partial` with "status":
// "stopped_by_user", "steps_done" and the "trace" so far; text and CSV: a status line on stdout
// (the trace went to stderr as it ran).
int report_stopped(const CommonOptions& options, nlohmann::ordered_json partial, const nlohmann::ordered_json& trace);

// A number for JSON output, or null when it is NaN or infinite (JSON has no such numbers).
nlohmann::ordered_json number_or_null(double value);

// Creates the output folder (and parents) and tries making a file in it; throws
// std::invalid_argument naming it on failure (so a read-only folder is refused before any work).
void ensure_directory(const std::string& path);

// Writes a file whole or not at all: to a unique temporary in the same folder, then renamed into
// place. On any failure the temporary is removed and std::invalid_argument names the file.
void write_file_atomically(const std::string& path, const std::string& contents);

// A file given on the command line that the command writes: relative paths go inside --out when
// --out was given (otherwise they are taken as they are).
std::string output_path(const CommonOptions& options, const std::string& path);

// Checks, before any work, every file a command will write (`flag` names who asked for it):
// not empty, not an existing folder, in a folder that accepts files (the nearest existing one is
// tried), not the same file as an input, not twice among the outputs. Throws
// std::invalid_argument naming the first conflict.
struct PlannedFile {
  std::string path;
  std::string flag;
};
void check_outputs(const std::vector<PlannedFile>& outputs, const std::vector<std::string>& inputs);

}  // namespace numlab::cli
