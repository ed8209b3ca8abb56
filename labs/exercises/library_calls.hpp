#pragma once
// Calls to forbidden library functions that numlab noticed in the student's program
// (docs/exercises.md, "Library calls"): which languages were watched, and each function's count.

#include <map>
#include <set>
#include <string>

namespace numlab::exercises {

struct LibraryCalls {
  std::set<std::string> watched;            // the languages whose watch was loaded: "python", "octave"
  std::map<std::string, long long> counts;  // "numpy.linalg.solve" -> calls from the student's code

  void add(const LibraryCalls& other) {
    watched.insert(other.watched.begin(), other.watched.end());
    for (const auto& [name, count] : other.counts) counts[name] += count;
  }
};

}  // namespace numlab::exercises
