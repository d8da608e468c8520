// 0.32 fixed-point fractions, the form in which the chapter's sequences are computed.
#pragma once

#include <cstdint>

namespace freezeray::ch09 {

// x / 2^32 in [0, 1): the top 24 bits, so the float is exact and never rounds up to 1.
inline float fraction_to_float(std::uint32_t x) { return static_cast<float>(x >> 8) * 0x1p-24f; }

}  // namespace freezeray::ch09
