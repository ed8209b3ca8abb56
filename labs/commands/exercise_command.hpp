#pragma once
// `numlab exercise list|show|init|check|replay` (docs/exercises.md): a student's own solver, run as a
// sandboxed child process, checked against GSL, Eigen, numlab's steppers and the closed forms.

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "commands/common_options.hpp"
#include "exercises/variant.hpp"

namespace numlab::cli {

class ExerciseCommand {
 public:
  explicit ExerciseCommand(CLI::App& app);
  bool selected() const { return command_->parsed(); }
  int run() const;

 private:
  int list() const;
  int show() const;
  int init() const;
  int check() const;
  int replay() const;
  // --variant ID as given (std::invalid_argument for an empty ID or one with control characters),
  // or no variant.
  exercises::Variant variant() const;

  CLI::App* command_;
  CLI::App* list_;
  CLI::App* show_;
  CLI::App* init_;
  CLI::App* check_;
  CLI::App* replay_;
  std::string name_;
  std::string folder_;
  std::string language_ = "python";
  double timeout_seconds_ = 10.0;
  std::vector<std::string> program_;
  std::string replay_file_;
  std::string model_;          // init/check --model FILE.toml|NAME (the linkage exercise)
  std::string variant_;        // init/check --variant ID (variant.hpp)
  std::vector<CLI::Option*> variant_options_;  // --variant of init and check: given or not
  bool json_ = false;          // check --format json
  std::string out_dir_;        // check --out DIR ("" when not given)
};

}  // namespace numlab::cli
