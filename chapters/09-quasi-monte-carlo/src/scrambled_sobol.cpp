// One coordinate of an Owen-scrambled Sobol point (book chapter 09).
#include "freezeray/ch09/scrambled_sobol.hpp"

namespace freezeray::ch09 {

static_assert(MaxJointCoordinates <= SobolDimensions, "every coordinate of a joint set needs a Sobol dimension");

const SobolNibbleTables* joint_coordinate_tables() {
    static const std::array<SobolNibbleTables, MaxJointCoordinates> tables = [] {
        std::array<SobolNibbleTables, MaxJointCoordinates> t{};
        for (std::size_t c = 0; c < MaxJointCoordinates; ++c) t[c] = reversed_sobol_tables()[JointCoordinateDimension[c]];
        return t;
    }();
    return tables.data();
}

}  // namespace freezeray::ch09
