#pragma once
// Description text for the reader's tests (docs/linkage-files.md), written line by line so that a
// test names the line and column a refusal must give, and the check of that refusal.

#include <catch2/catch.hpp>

#include <initializer_list>
#include <string>

#include "numlab/mechanisms/linkage/linkage_description.hpp"

namespace numlab::mechanisms::testing {

// Lines joined with '\n': the k-th string is line k + 1 of the file.
inline std::string lines(std::initializer_list<std::string> items) {
  std::string text;
  for (const std::string& item : items) text += item + "\n";
  return text;
}

// The reader's error for `text` read as "t.toml"; the test fails where the reader accepts it.
inline LinkageFileError error_of(const std::string& text) {
  try {
    (void)parse_linkage_description(text, "t.toml");
  } catch (const LinkageFileError& error) {
    return error;
  }
  FAIL("the reader accepted:\n" << text);
  throw;  // not reached
}

// The text is refused at line:column with exactly this problem, and what() is "t.toml:LINE:COLUMN: problem".
inline void check_refused(const std::string& text, int line, int column, const std::string& problem) {
  INFO(text);
  const LinkageFileError error = error_of(text);
  CHECK(error.problem() == problem);
  CHECK(error.place().line == line);
  CHECK(error.place().column == column);
  CHECK(std::string(error.what()) == "t.toml:" + std::to_string(line) + ":" + std::to_string(column) + ": " + problem);
}

}  // namespace numlab::mechanisms::testing
