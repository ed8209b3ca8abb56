#pragma once
// NUMLAB_FORCE_INLINE: for the few small functions on a fast path that GCC would otherwise call
// out of line once their callees are inlined into them (docs/performance.md says where and why).
// The textbook paths never use it.

#if defined(__GNUC__) || defined(__clang__)
#define NUMLAB_FORCE_INLINE [[gnu::always_inline]] inline
#else
#define NUMLAB_FORCE_INLINE inline
#endif
