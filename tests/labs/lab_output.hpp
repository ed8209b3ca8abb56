#pragma once
// A lab run as a student runs it, and what the tests read from it: the printed text with its line
// wrapping undone (so that a sentence can be found whole), and the tables the lab saved as CSV.

#include <map>
#include <string>
#include <vector>

namespace numlab::test {

using CsvRows = std::vector<std::vector<std::string>>;  // the header row first

struct LabOutput {
  int exit_code;
  std::string text;    // stdout, every run of white space made one space
  std::string folder;  // FOLDER/lab-NAME, where the tables are
  // The table saved as FOLDER/lab-NAME/FILE (e.g. "step4-hilbert.csv").
  CsvRows table(const std::string& file) const;
};

// Runs `numlab lab NAME --out TMP`; without a name, runs `numlab` with no arguments in TMP.
LabOutput run_lab(const std::string& name);

// A cell as a number: its leading number ("0.000196 s" -> 0.000196); NaN when there is none.
double number(const std::string& cell);

// The column named `header` in `rows`.
std::size_t column(const CsvRows& rows, const std::string& header);

// Words that belong to developers' benchmarks, not to a lesson.
bool has_developer_talk(const std::string& text);

}  // namespace numlab::test
