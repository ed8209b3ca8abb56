#pragma once
// Force-included (compiler flag -include) into every file of test_allocations, before Eigen:
// with EIGEN_RUNTIME_NO_MALLOC, each Eigen heap allocation asserts is_malloc_allowed(); this
// eigen_assert counts the refusals instead of aborting, so a test can report them.

#include <atomic>
#include <cstring>

inline std::atomic<long> refused_eigen_allocations{0};

inline void numlab_eigen_assert(bool ok, const char* condition) {
  if (!ok && std::strstr(condition, "heap allocation is forbidden") != nullptr) ++refused_eigen_allocations;
}

#define EIGEN_RUNTIME_NO_MALLOC
#define eigen_assert(x) numlab_eigen_assert(static_cast<bool>(x), #x)
