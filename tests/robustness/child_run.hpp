#pragma once
// Runs a program in a folder with a time limit, as a user at a script would: stdin from
// /dev/null, stdout and stderr captured to files. A program still running at the limit is killed
// with its whole process group (gnuplot included).

#include <string>
#include <vector>

namespace numlab::robustness {

struct ChildResult {
  bool timed_out = false;
  int exit_code = -1;  // when it exited
  int signal = 0;      // when a signal ended it
  double seconds = 0;  // wall-clock time
  double peak_mb = 0;  // its largest resident set size, in MB
};

// `memory_limit_mb` > 0 caps the child's address space (not usable under AddressSanitizer, which
// reserves terabytes of address space; there ASAN_OPTIONS limits the heap instead).
ChildResult run_child(const std::string& program, const std::vector<std::string>& arguments, const std::string& folder,
                      const std::string& stdout_file, const std::string& stderr_file, double time_limit,
                      long memory_limit_mb);

}  // namespace numlab::robustness
