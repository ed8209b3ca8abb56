#pragma once
// One row of cases.tsv: a numlab command line and what it must and must not do.
// The format of the table is described at the top of cases.tsv and in docs/robustness.md.

#include <string>
#include <vector>

namespace numlab::robustness {

struct Case {
  std::string id;                     // unique name; the ctest test is "robustness: ID"
  std::vector<int> exit_codes;        // the allowed exit codes ("0", "1", "2", or e.g. "0|2")
  std::vector<std::string> arguments; // after the program name, decoded (see decode_word)
  std::vector<std::string> writes;    // globs of the files the case may create, relative to its sandbox
  std::vector<std::string> checks;    // extra checks: json, status=S, out~T, out!~T, err~T, err!~T, short, made=PATH, mem=MB
  double seconds = 0;                 // time limit in the release build (multiplied by the time scale)
  std::string note;                   // why the row is there
};

// Reads every row of the table, decoding its argument words; throws std::runtime_error naming the
// line on a malformed row or a repeated id.
std::vector<Case> read_cases(const std::string& path, const std::string& nist_dir);

// One argument word of the table: \xNN is that byte, \s a space, \\ a backslash, '' the empty
// string, {LONG} 100 000 letters, {NIST} the folder of the NIST data sets.
std::string decode_word(const std::string& word, const std::string& nist_dir);

}  // namespace numlab::robustness
