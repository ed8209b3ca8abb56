#pragma once
// `numlab basins SYSTEM [--grid N|NxM] [--u-range A:B] [--v-range A:B] [--axes U,V] [--damped]
// [--threads T] [--chart FILE] [--max-iter N] [--out DIR] [--format text|json|csv]` (docs/basins.md):
// Newton from every point of a grid of starting guesses, each coloured by the assembly mode it reaches.

#include <CLI/CLI.hpp>
#include <string>

#include "commands/common_options.hpp"

namespace numlab::cli {

class BasinsCommand {
 public:
  explicit BasinsCommand(CLI::App& app);
  bool selected() const { return command_->parsed(); }
  int run() const;

 private:
  CLI::App* command_;
  CommonOptions common_;
  std::string system_;
  std::string grid_ = "400";
  std::string u_range_, v_range_, axes_, chart_;
  bool damped_ = false;
  int threads_ = 0;  // 0: not given (hardware_concurrency)
};

// "N" or "NxM" (columns x rows), each 2 to basins::max_grid_side; throws std::invalid_argument.
std::pair<int, int> parse_grid(const std::string& text);
// "A:B", two finite numbers with A < B; throws std::invalid_argument naming `option`.
std::pair<double, double> parse_slice_range(const std::string& text, const std::string& option);

}  // namespace numlab::cli
