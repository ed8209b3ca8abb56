#pragma once
// `numlab bench grade`: a class of Python GEPP submissions (copies of the reference solution,
// tests/exercises/references/python/gepp.py, embedded at build time, and every tenth one a mutant:
// no pivoting, or the rows of A swapped without b) graded by `numlab exercise grade`, run as a
// process of its own; the wall time, the time per submission and whether the verdicts are right.
// Issue 29's goal: 300 submissions in under 60 s on a 2-core machine.

#include "bench/bench_options.hpp"

namespace numlab::cli {

// 300 submissions (30 with `quick`); exit 0 when every verdict is the expected one.
int run_grade_bench(const BenchOptions& common, bool quick);

}  // namespace numlab::cli
