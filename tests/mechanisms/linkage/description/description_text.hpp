#pragma once
// Description text for the reader's tests (docs/linkage-files.md), written line by line so that a
// test names the line and column a refusal must give.

#include <initializer_list>
#include <string>

namespace numlab::mechanisms::testing {

// Lines joined with '\n': the k-th string is line k + 1 of the file.
inline std::string lines(std::initializer_list<std::string> items) {
  std::string text;
  for (const std::string& item : items) text += item + "\n";
  return text;
}

}  // namespace numlab::mechanisms::testing
