// One coordinate of an Owen-scrambled Sobol point, as the chapter's samplers draw it (book
// chapter 09; Burley, "Practical Hash-based Owen Scrambling", JCGT 9(4), 2020).
#pragma once

#include "freezeray/ch09/fixed_point.hpp"
#include "freezeray/ch09/joint_sets.hpp"
#include "freezeray/ch09/owen_scrambling.hpp"
#include "freezeray/ch09/radical_inverse.hpp"
#include "freezeray/ch09/sobol_matrices.hpp"
#include "freezeray/math.hpp"
#include "freezeray/sampler.hpp"

#include <array>
#include <cstdint>

namespace freezeray::ch09 {

// The Sobol dimension that coordinate c of a joint set's point takes (sampler.hpp numbers a set's
// coordinates by importance, a pair as c and c + 1). Sets of up to three coordinates take
// dimensions 0, 1, 2, whose first pair is a (0, 2)-sequence. The path set's pairs beyond its
// second take the pairs of the remaining dimensions that are the best nets together, (4, 6),
// (5, 7) and (9, 14): each a (2, m, 2)-net for every m <= 12, where (4, 5), (7, 8) and (9, 10)
// have t of 3, 3 and 4 (book chapter 09, "Drawing jointly").
constexpr std::array<int, MaxJointCoordinates> JointCoordinateDimension = {0, 1, 2, 3, 4, 6, 8, 5, 7, 9, 14, 10, 11, 12, 13};

// The reversed tables (reversed_sobol_tables) of each coordinate's dimension, in coordinate order.
const SobolNibbleTables* joint_coordinate_tables();

// Coordinate `c` of the Sobol point whose index, its bits reversed, is `reversed_index`,
// Owen-scrambled by `seed`, as a 0.32 fraction: nested_uniform_scramble(sobol_sample_bits(i, d),
// seed) for i = reverse_bits(reversed_index) and d = JointCoordinateDimension[c]. The scramble
// reverses the point, permutes it and reverses it back; the reversed point is the reversed matrix
// (`coordinate_tables`, from joint_coordinate_tables()) times the reversed index, so one reversal
// is left of three.
inline std::uint32_t scrambled_sobol_coordinate(const SobolNibbleTables* coordinate_tables, std::uint32_t reversed_index,
                                                std::uint32_t c, std::uint32_t seed) {
    // Sobol dimension 0 is the index reversed (the van der Corput sequence), so its reversed
    // point is the index: no table.
    static_assert(JointCoordinateDimension[0] == 0);
    const std::uint32_t reversed_point =
        c == 0 ? reverse_bits(reversed_index) : multiply_by_nibbles(coordinate_tables[c], reversed_index);
    return reverse_bits(laine_karras_permutation(reversed_point, seed));
}

// Coordinates c and c + 1 of that point in [0, 1), each its own scramble of `seed` (Burley's
// hash_combine): a sampler's 2D draw.
inline Vec2 scrambled_sobol_pair(const SobolNibbleTables* coordinate_tables, std::uint32_t reversed_index, std::uint32_t c,
                                 std::uint32_t seed) {
    return Vec2(fraction_to_float(scrambled_sobol_coordinate(coordinate_tables, reversed_index, c, hash_combine(seed, 0))),
                fraction_to_float(scrambled_sobol_coordinate(coordinate_tables, reversed_index, c + 1, hash_combine(seed, 1))));
}

}  // namespace freezeray::ch09
