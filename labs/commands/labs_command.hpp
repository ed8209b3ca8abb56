#pragma once
// `numlab labs` (the list) and `numlab lab NAME [--step] [--out DIR]`.

#include <CLI/CLI.hpp>
#include <string>

#include "commands/common_options.hpp"

namespace numlab::cli {

class LabsCommand {
 public:
  explicit LabsCommand(CLI::App& app);
  bool list_selected() const { return list_->parsed(); }
  bool lab_selected() const { return lab_->parsed(); }
  int list() const;
  int run() const;

 private:
  CLI::App* list_;
  CLI::App* lab_;
  CommonOptions common_;
  std::string name_;
};

// Runs one lab by name, writing to stdout; with `step`, pauses between steps at a terminal.
int run_lab(const std::string& name, bool step, const std::string& out_dir);

}  // namespace numlab::cli
