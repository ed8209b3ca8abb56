#pragma once
// What a case's run must show: the exit code, the shape of its output, and the files it left.
// Each function returns the broken promises, one sentence each (none: the case passed).

#include <map>
#include <string>
#include <vector>

#include "case_table.hpp"
#include "child_run.hpp"

namespace numlab::robustness {

// Exit code, time, stdout and stderr against the row and the contract of docs/cli.md.
std::vector<std::string> judge_run(const Case& row, const ChildResult& run, double time_limit, const std::string& out,
                                   const std::string& err);

// The case folder before and after: prepared files unchanged and still there, new entries only
// where the row allows them, no *.partial anywhere, and after exit 0 each made=PATH of the row there.
std::vector<std::string> judge_files(const Case& row, int exit_code, const std::map<std::string, std::string>& before,
                                     const std::map<std::string, std::string>& after);

}  // namespace numlab::robustness
