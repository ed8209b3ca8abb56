#pragma once
// Command lines of the student's program: found on PATH, and written back as a shell reads them
// (for the report's "Checked:" line and the replay command).

#include <string>
#include <vector>

namespace numlab::exercises {

// `name` found on PATH (or /usr/local/bin:/usr/bin:/bin when PATH is unset or empty) as an
// executable regular file, as an absolute path; "" when it is not there.
std::string find_on_path(const std::string& name);

// A word as a POSIX shell reads it back: as it is when it holds only safe characters, else quoted.
std::string shell_word(const std::string& word);
// The words, each as shell_word writes it, separated by spaces.
std::string shell_words(const std::vector<std::string>& words);

}  // namespace numlab::exercises
