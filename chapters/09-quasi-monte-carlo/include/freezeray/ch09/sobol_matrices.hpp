// The Sobol sequence's generator matrices, from Joe and Kuo's direction numbers (book chapter 09;
// Sobol 1967; Joe and Kuo, "Constructing Sobol sequences with better two-dimensional
// projections", SIAM J. Sci. Comput. 30, 2008, the file new-joe-kuo-6.21201).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

namespace freezeray::ch09 {

// Dimensions with direction numbers here: the first (the van der Corput sequence) and Joe and
// Kuo's next 15.
constexpr int SobolDimensions = 16;

// One dimension's primitive polynomial and initial direction numbers, as Joe and Kuo list them:
// degree s, the coefficients a_1 ... a_(s-1) as the bits of a (a_1 the highest), and m_1 ... m_s
// (odd, m_k < 2^k).
struct DirectionNumbers {
    int degree;
    std::uint32_t coefficients;
    std::array<std::uint32_t, 8> initial;  // m_1 ... m_s
};
// Dimension d (1 <= d < SobolDimensions; dimension 0 has none: its matrix is the identity).
const DirectionNumbers& direction_numbers(int dimension);

// A generator matrix as its 32 columns: column k is v_(k+1) = m_(k+1) / 2^(k+1) as a 0.32
// fixed-point fraction, which index bit k adds (XOR) to the point.
using GeneratorMatrix = std::array<std::uint32_t, 32>;

// The matrix of `dimension` (0 <= dimension < SobolDimensions): m_k beyond the initial ones from
// the recurrence m_k = 2 a_1 m_(k-1) ^ 4 a_2 m_(k-2) ^ ... ^ 2^s m_(k-s) ^ m_(k-s).
GeneratorMatrix sobol_generator_matrix(int dimension);

// Point `index` of the sequence in `dimension` as a 0.32 fixed-point fraction: the XOR of the
// columns of the set bits of index (Antonov and Saleev 1979 give the same points in Gray-code order).
std::uint32_t sobol_sample_bits(std::uint32_t index, int dimension);

// The same in [0, 1).
float sobol_sample(std::uint32_t index, int dimension);

// The product of a generator matrix and an index, four bits of the index at a time: for each of
// the eight nibbles, the XOR of the columns of its set bits, for all 16 values. 512 bytes a
// dimension, so that the fifteen a sampler draws from stay in the first-level data cache
// (book chapter 09, "Drawing jointly": tables of bytes, 4 KB a dimension, missed it).
using SobolNibbleTables = std::array<std::array<std::uint32_t, 16>, 8>;
inline std::uint32_t multiply_by_nibbles(const SobolNibbleTables& t, std::uint32_t index) {
    std::uint32_t x = 0;
    for (std::size_t k = 0; k < 8; ++k) x ^= t[k][(index >> (4 * k)) & 0xfu];
    return x;
}

// The tables of every dimension's matrix in reversed bit order: the matrix C with its rows and
// columns reversed, R C R, where R reverses 32 bits. It maps the reversed index to the reversed
// point, reverse_bits(sobol_sample_bits(i, d)) = multiply_by_nibbles(t[d], reverse_bits(i)). Owen
// scrambling works on reversed fractions (owen_scrambling.hpp), so a sampler that shuffles and
// scrambles can stay in reversed order from the index to the scramble.
const SobolNibbleTables* reversed_sobol_tables();  // SobolDimensions tables

}  // namespace freezeray::ch09
