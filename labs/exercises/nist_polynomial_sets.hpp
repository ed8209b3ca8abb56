#pragma once
// NIST StRD polynomial sets with certified coefficients, embedded in the checker: Norris (degree 1),
// Pontius (2), Wampler1, Wampler4, Wampler5 (5; exact, noisy, very noisy).

#include <vector>

#include "numlab/fitting/data_set.hpp"

namespace numlab::exercises {

std::vector<fitting::DataSet> nist_polynomial_sets();

}  // namespace numlab::exercises
