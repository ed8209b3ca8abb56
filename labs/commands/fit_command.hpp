#pragma once
// `numlab fit --data FILE --degree D --method M [--linear L] [--chart FILE]` (docs/cli.md), and
// `--foot-path upper|lower` to fit an arc of the Jansen foot's path instead of a file.

#include <CLI/CLI.hpp>
#include <optional>
#include <string>

#include "commands/common_options.hpp"

namespace numlab::cli {

class FitCommand {
 public:
  explicit FitCommand(CLI::App& app);
  bool selected() const { return command_->parsed(); }
  int run() const;

 private:
  CLI::App* command_;
  CommonOptions common_;
  std::string data_file_;
  std::string foot_path_;
  int degree_ = 0;
  std::string method_ = "normal";
  std::string linear_ = "gepp";
  std::string chart_;
};

}  // namespace numlab::cli
