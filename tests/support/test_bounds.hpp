// The box spanned by two corners, for tests that build cells and scene bounds by hand.
#pragma once

#include "freezeray/math.hpp"

namespace freezeray::testing {

inline Bounds3 box(const Vec3& min, const Vec3& max) {
    Bounds3 b;
    b.expand(min);
    b.expand(max);
    return b;
}

}  // namespace freezeray::testing
