// The Sobol sequence's generator matrices (book chapter 09).
#include "freezeray/ch09/sobol_matrices.hpp"

#include "freezeray/error.hpp"
#include "freezeray/ch09/fixed_point.hpp"
#include "freezeray/ch09/radical_inverse.hpp"

#include <stdexcept>
#include <string>
#include <vector>

namespace freezeray::ch09 {

namespace {

// Joe and Kuo's new-joe-kuo-6.21201, dimensions 2 to 16 (their numbering starts at 1 with the
// van der Corput dimension, ours at 0).
const DirectionNumbers table[SobolDimensions - 1] = {
    {1, 0, {1}},
    {2, 1, {1, 3}},
    {3, 1, {1, 3, 1}},
    {3, 2, {1, 1, 1}},
    {4, 1, {1, 1, 3, 3}},
    {4, 4, {1, 3, 5, 13}},
    {5, 2, {1, 1, 5, 5, 17}},
    {5, 4, {1, 1, 5, 5, 5}},
    {5, 7, {1, 1, 7, 11, 19}},
    {5, 11, {1, 1, 5, 1, 1}},
    {5, 13, {1, 1, 1, 3, 11}},
    {5, 14, {1, 3, 5, 5, 31}},
    {6, 1, {1, 3, 3, 9, 7, 49}},
    {6, 13, {1, 1, 1, 15, 21, 21}},
    {6, 16, {1, 3, 1, 13, 27, 49}},
};

void check_dimension(int dimension) {
    if (dimension < 0 || dimension >= SobolDimensions)
        throw std::out_of_range("Sobol dimension " + std::to_string(dimension) + " (this table has 0 to " +
                                std::to_string(SobolDimensions - 1) + ")");
}

}  // namespace

const DirectionNumbers& direction_numbers(int dimension) {
    if (dimension < 1) throw std::out_of_range("Sobol dimension 0 has no direction numbers (its matrix is the identity)");
    check_dimension(dimension);
    return table[dimension - 1];
}

// BOOK(sobol-matrix)
GeneratorMatrix sobol_generator_matrix(int dimension) {
    check_dimension(dimension);
    GeneratorMatrix v{};
    if (dimension == 0) {
        // The identity: index bit k becomes fraction bit k + 1, the van der Corput sequence.
        for (int k = 0; k < 32; ++k) v[k] = 1u << (31 - k);
        return v;
    }
    const DirectionNumbers& d = direction_numbers(dimension);
    // EXERCISE(ch09/sobol-direction-numbers): fill the 32 columns of the generator matrix from the initial direction numbers and the recurrence of book chapter 09, "Nets and the Sobol sequence"
    const int s = d.degree;
    for (int k = 0; k < s; ++k) v[k] = d.initial[k] << (31 - k);
    for (int k = s; k < 32; ++k) {
        // m_k / 2^k: the term 2^s m_(k-s) / 2^k is v[k-s] itself, m_(k-s) / 2^k is v[k-s] >> s.
        v[k] = v[k - s] ^ (v[k - s] >> s);
        for (int j = 1; j < s; ++j)
            if ((d.coefficients >> (s - 1 - j)) & 1u) v[k] ^= v[k - j];
    }
    // END EXERCISE
    return v;
}
// END BOOK

namespace {

// Every dimension's tables of the XORs of `Bits` columns at a time, of the matrix's columns as
// `column` gives them.
template <int Bits, typename Column>
std::vector<std::array<std::array<std::uint32_t, 1u << Bits>, 32 / Bits>> chunk_tables(Column column) {
    std::vector<std::array<std::array<std::uint32_t, 1u << Bits>, 32 / Bits>> t(SobolDimensions);
    for (int d = 0; d < SobolDimensions; ++d) {
        const GeneratorMatrix v = sobol_generator_matrix(d);
        for (int chunk = 0; chunk < 32 / Bits; ++chunk)
            for (std::uint32_t value = 0; value < (1u << Bits); ++value) {
                std::uint32_t x = 0;
                for (int bit = 0; bit < Bits; ++bit)
                    if (value & (1u << bit)) x ^= column(v, Bits * chunk + bit);
                t[static_cast<std::size_t>(d)][static_cast<std::size_t>(chunk)][value] = x;
            }
    }
    return t;
}

}  // namespace

std::uint32_t sobol_sample_bits(std::uint32_t index, int dimension) {
    // The product of the matrix and the index, a byte of the index at a time: for each of the
    // four bytes, the XOR of the columns of its set bits, for all 256 byte values, is tabulated
    // once (4 KB per dimension); the loop over 32 index bits would cost more.
    static const auto tables = chunk_tables<8>([](const GeneratorMatrix& v, int k) { return v[static_cast<std::size_t>(k)]; });
    check_dimension(dimension);
    const auto& t = tables[static_cast<std::size_t>(dimension)];
    return t[0][index & 0xffu] ^ t[1][(index >> 8) & 0xffu] ^ t[2][(index >> 16) & 0xffu] ^ t[3][index >> 24];
}

const SobolNibbleTables* reversed_sobol_tables() {
    // Bit k of the reversed index is bit 31 - k of the index, whose column, reversed, it adds.
    static const auto tables =
        chunk_tables<4>([](const GeneratorMatrix& v, int k) { return reverse_bits(v[static_cast<std::size_t>(31 - k)]); });
    return tables.data();
}

float sobol_sample(std::uint32_t index, int dimension) { return fraction_to_float(sobol_sample_bits(index, dimension)); }

}  // namespace freezeray::ch09
