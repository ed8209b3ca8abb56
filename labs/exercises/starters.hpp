#pragma once
// The starters of `numlab exercise init` (docs/exercises.md): TASK.md and a program that already
// speaks the protocol, in Python (numpy), C++ (a CMake project using find_package(numlab)) or
// Octave, with the method left as the exercise's stub. As generated, each runs and fails every
// check honestly with "not implemented".

#include <string>
#include <vector>

#include "exercises/exercise.hpp"

namespace numlab::exercises {

enum class Language { python, cpp, octave };

// "python", "cpp" or "octave"; throws std::invalid_argument
// "exercise init: --lang must be python, cpp or octave, not 'X'" otherwise.
Language parse_language(const std::string& name);

struct StarterFile {
  std::string path;  // relative to the starter's folder
  std::string contents;
  bool executable = false;
};

// The command that checks the starter, run in its folder, e.g.
// "numlab exercise check gepp -- python3 solution.py".
std::string check_command(const Exercise& exercise, Language language);

// TASK.md (the task and "How to check") and the program's files. With a variant, TASK.md gets a
// section "Your variant" (its ID) and every check command in the files says `--variant ID`.
std::vector<StarterFile> starter_files(const Exercise& exercise, Language language, const Variant& variant = Variant());

// Writes the files into `folder` (created if needed), executable ones with their x bits set.
// Throws std::runtime_error naming the file that cannot be written.
void write_starter_files(const std::string& folder, const std::vector<StarterFile>& files);

}  // namespace numlab::exercises
