// Four floats at once: the importance of the four children of a light-tree node is computed in
// the lanes of one vector (book chapter 10, "Four clusters at once"; chapter 07 introduces lanes
// and masks). Written with GCC's vector extensions, so that the formulas read as with floats:
// +, -, *, / and comparisons act lane by lane, and a float on one side stands for four copies of
// it. On x86-64 each operation is one SSE instruction; elsewhere the compiler does it lane by lane,
// with the same results (every operation here is correctly rounded either way).
#pragma once

#include <cstdint>

#if defined(__SSE2__)
#include <emmintrin.h>
#else
#include <cmath>
#endif

namespace freezeray::ch10 {

inline constexpr int LaneCount = 4;

// Marks a function to be compiled twice on x86-64, for processors with AVX2 and for any other,
// the program choosing one when it starts (GCC's and Clang's function multiversioning). The
// AVX2 version writes the same four-lane operations with three-operand instructions, which spare
// the register copies SSE's two-operand ones need. Its results are the same to the bit: every
// operation here is correctly rounded, and no multiply and add are fused into one (the project
// compiles with -ffp-contract=off).
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define FREEZERAY_ALSO_FOR_AVX2 __attribute__((target_clones("avx2", "default")))
#else
#define FREEZERAY_ALSO_FOR_AVX2
#endif

using Lanes = float __attribute__((vector_size(16)));
// A comparison's answer per lane: all bits set (-1) where it holds, 0 where it does not.
using LaneMask = std::int32_t __attribute__((vector_size(16)));

inline Lanes splat(float x) { return Lanes{x, x, x, x}; }

// mask ? if_true : if_false, lane by lane.
inline Lanes select(LaneMask mask, Lanes if_true, Lanes if_false) { return mask ? if_true : if_false; }

// As std::max and std::min, lane by lane: a NaN in `a` comes through.
inline Lanes max(Lanes a, Lanes b) { return select(a < b, b, a); }
inline Lanes min(Lanes a, Lanes b) { return select(b < a, b, a); }

inline Lanes sqrt(Lanes x) {
#if defined(__SSE2__)
    return _mm_sqrt_ps(x);
#else
    for (int i = 0; i < LaneCount; ++i) x[i] = std::sqrt(x[i]);
    return x;
#endif
}

}  // namespace freezeray::ch10
