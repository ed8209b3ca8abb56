#pragma once
// `numlab exercise grade NAME --submissions DIR --out OUT [--jobs N] [--timeout S]` (docs/exercises.md,
// "Grading a class"): every sub-folder of DIR checked as `exercise check` checks it, each student's
// report.html and results.json in OUT/STUDENT/, and OUT/gradebook.csv. Added to the `exercise`
// sub-command that ExerciseCommand made.

#include <CLI/CLI.hpp>
#include <string>

namespace numlab::cli {

class ExerciseGradeCommand {
 public:
  // `exercise` is app.get_subcommand("exercise").
  explicit ExerciseGradeCommand(CLI::App& exercise);
  bool selected() const { return command_->parsed(); }
  int run() const;

 private:
  int grade_class() const;
  int grade_one() const;  // --worker FOLDER: one submission, in this process

  CLI::App* command_;
  std::string name_;
  std::string submissions_;
  std::string out_dir_;
  int jobs_ = 0;  // 0: the number of cores
  double timeout_seconds_ = 10.0;
  double build_seconds_ = 300.0;
  std::string worker_folder_;  // the hidden --worker mode
  std::string worker_student_;
  std::string model_;  // --model FILE.toml|NAME (the linkage exercise)
  std::string variant_;           // --variant ID: every student gets this variant (variant.hpp)
  CLI::Option* variant_option_ = nullptr;
  bool variant_from_folder_ = false;  // --variant-from-folder: each student's folder name is the ID
};

}  // namespace numlab::cli
