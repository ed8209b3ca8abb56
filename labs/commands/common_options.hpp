#pragma once
// What every `numlab` sub-command shares: the common flags and where each applies, and what a
// command stopped at a --step pause prints. (Output formats, exit codes and file writing, which the
// lessons and benchmarks use too, are in output/.)

#include <nlohmann/json.hpp>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "numlab/status.hpp"
#include "output/exit_codes.hpp"
#include "output/files.hpp"
#include "output/format.hpp"

// CLI11 is only named here (a sub-command and a validator): the files that build commands include
// <CLI/CLI.hpp> themselves, so the ~30 files that only print and compute do not compile it.
namespace CLI {
class App;
class Validator;
}  // namespace CLI

namespace numlab::cli {

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

// The status word a command stopped with q at a --step pause prints.
constexpr std::string_view stopped_status = "stopped_by_user";

// After q at a --step pause: prints what ran and returns exit 1. JSON: `partial` with "status":
// "stopped_by_user", "steps_done" and the "trace" so far; text and CSV: a status line on stdout
// (the trace went to stderr as it ran).
int report_stopped(const CommonOptions& options, nlohmann::ordered_json partial, const nlohmann::ordered_json& trace);

// A file given on the command line that the command writes: relative paths go inside --out when
// --out was given (otherwise they are taken as they are).
std::string output_path(const CommonOptions& options, const std::string& path);

}  // namespace numlab::cli
