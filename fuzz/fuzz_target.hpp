#pragma once
// What every numlab fuzzer shares: the input as text, and the rule that a parser either returns a
// result that keeps its promises or throws std::invalid_argument (bad input, the normal answer).
// Anything else -- another exception, a broken promise, a crash, a sanitizer report -- is a finding.

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string_view>

namespace numlab::fuzz {

inline std::string_view as_text(const std::uint8_t* data, std::size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

// A promise the parser's result broke: say which, then stop as a crash does.
inline void require(bool promise, const char* what) {
  if (promise) return;
  std::fprintf(stderr, "numlab fuzz finding: %s\n", what);
  std::abort();
}

// Runs `parse` on one input; std::invalid_argument is a refusal, and refusals are fine.
template <typename Parse>
int run_parser(Parse parse) {
  try {
    parse();
  } catch (const std::invalid_argument&) {
  }
  return 0;
}

}  // namespace numlab::fuzz
