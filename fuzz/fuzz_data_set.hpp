#pragma once
// The promise a data set parser keeps on success (CSV and NIST alike): x and y of one length, at
// least one row, every value finite; certified values, when present, one sd per parameter.

#include "fuzz_target.hpp"
#include "numlab/fitting/data_set.hpp"

namespace numlab::fuzz {

inline void check_data_set(const fitting::DataSet& data) {
  require(data.x.size() > 0 && data.x.size() == data.y.size(), "x and y differ in length or are empty");
  require(data.x.allFinite() && data.y.allFinite(), "a non-finite value was returned");
  if (data.certified) {
    require(data.certified->parameters.size() == data.certified->standard_deviations.size(),
            "certified parameters and their sds differ in number");
  }
}

}  // namespace numlab::fuzz
