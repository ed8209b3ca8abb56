// NIST StRD linear-regression sets for the polyfit exercise, embedded at build time from the same
// files as fitting/data/nist/*.dat (labs/exercises/CMakeLists.txt writes them into
// nist_polynomial_sets_data.inc), so the checker works wherever numlab is installed. Read with
// numlab's own NIST parser.

#include "exercises/nist_polynomial_sets.hpp"

#include "numlab/fitting/data_set.hpp"

namespace numlab::exercises {

namespace {

struct EmbeddedSet {
  const char* name;
  const char* text;  // the .dat file, verbatim
};

constexpr EmbeddedSet embedded_sets[] = {
#include "exercises/nist_polynomial_sets_data.inc"
};

}  // namespace

std::vector<fitting::DataSet> nist_polynomial_sets() {
  std::vector<fitting::DataSet> sets;
  for (const EmbeddedSet& set : embedded_sets) sets.push_back(fitting::parse_nist_data(set.text, set.name));
  return sets;
}

}  // namespace numlab::exercises
