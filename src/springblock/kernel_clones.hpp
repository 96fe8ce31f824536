#pragma once
// SB_KERNEL_CLONES marks a hot vector kernel to be compiled twice on x86-64, for the baseline
// (SSE2, 2 doubles per vector) and for AVX2 (4), with the loader picking the clone the CPU
// runs (GCC target_clones). Helpers a kernel calls must be forced inline (SB_INLINE) so that they
// are compiled into each clone: an out-of-line SSE2 helper called from AVX2 code measured at
// half speed. The library is built without floating-point contraction (src/CMakeLists.txt), so
// no clone fuses a*b+c and both round alike: results are bit-identical whichever runs.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define SB_KERNEL_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define SB_KERNEL_CLONES
#endif
#define SB_INLINE [[gnu::always_inline]] inline
