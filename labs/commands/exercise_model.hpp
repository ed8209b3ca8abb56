#pragma once
// The exercise a command line names (docs/exercises.md, "Any linkage as an exercise"): NAME from
// the registry, or, for `linkage`, the exercise made from --model FILE.toml|NAME. Shared by
// `exercise init`, `check` and `grade`.

#include <string>

#include "exercises/exercise.hpp"

namespace numlab::cli {

struct NamedExercise {
  exercises::Exercise exercise;
  std::string model_file;     // linkage: the description file read (a shipped model's path too)
  bool model_shipped = false; // linkage: --model named a shipped model, not a file
};

// Throws std::invalid_argument (one line, exit 2): an unknown exercise, linkage without --model,
// --model with another exercise, a --model that is neither a file nor a shipped model, and the
// description's own FILE:LINE:COLUMN errors (LinkageFileError). `verb` names the command in messages.
// `model_argument` is what the starter's check command passes as --model (empty: --model as given).
NamedExercise exercise_named(const std::string& name, const std::string& model, const std::string& verb,
                             const std::string& model_argument = "");

}  // namespace numlab::cli
