#pragma once
// The task statements of the exercises (the TASK.md of `exercise init`, the text of `exercise show`).
// Each is a Markdown file, tasks/NAME.md, embedded in the program at build time by CMakeLists.txt
// (generated/exercises/task_texts.inc in the build tree): edit the .md file, not C++.

#include <string>

namespace numlab::exercises {

// The task of the exercise called `name`: tasks/NAME.md as it was at build time, each line
// "<!-- include: shared/PART.md -->" replaced by that file. Throws std::logic_error when the build
// embedded no tasks/NAME.md.
const std::string& task_text(const std::string& name);

}  // namespace numlab::exercises
