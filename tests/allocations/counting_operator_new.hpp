#pragma once
// A replaced global operator new that counts its calls while `counting_operator_new` is true. Its
// definitions are not inline: include this header in exactly one file of a test executable.
// AddressSanitizer owns operator new (some allocations bind to its entry point whatever a program
// defines), so under ASan nothing is replaced and counts_operator_new is false: such a test then
// checks only the counts it can make.

#include <atomic>
#include <cstddef>
#include <cstdlib>
#include <new>

namespace numlab::testing {
inline std::atomic<long> operator_new_calls{0};
inline std::atomic<bool> counting_operator_new{false};
}  // namespace numlab::testing

#if defined(__SANITIZE_ADDRESS__)
inline constexpr bool counts_operator_new = false;
#else
inline constexpr bool counts_operator_new = true;
void* operator new(std::size_t size) {
  if (numlab::testing::counting_operator_new) ++numlab::testing::operator_new_calls;
  if (void* memory = std::malloc(size == 0 ? 1 : size)) return memory;
  throw std::bad_alloc();
}
void* operator new[](std::size_t size) { return operator new(size); }
void operator delete(void* memory) noexcept { std::free(memory); }
void operator delete(void* memory, std::size_t) noexcept { std::free(memory); }
void operator delete[](void* memory) noexcept { std::free(memory); }
void operator delete[](void* memory, std::size_t) noexcept { std::free(memory); }
#endif
