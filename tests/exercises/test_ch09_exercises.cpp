// Grading tests of chapter 09's exercises. Each test case is named after its exercise, calls the
// exercise's own function first (so that in a student copy it fails through its own stub), and
// checks it against exact values: the radical inverse against digits written out by hand, the
// Sobol matrices against direction numbers computed here from Bratley and Fox's integer form of
// the recurrence (ACM TOMS 14, 1988, "Algorithm 659"), which the solution does not use.
// Deterministic: no statistical test in this file.
#include "freezeray/ch09/radical_inverse.hpp"
#include "freezeray/ch09/sobol_matrices.hpp"

#include <catch2/catch.hpp>

#include <cstdint>
#include <vector>

using namespace freezeray::ch09;

TEST_CASE("ch09/radical-inverse", "[exercise]") {
    // Base 2, the van der Corput sequence: 1 = 1b -> 0.1b, 6 = 110b -> 0.011b.
    REQUIRE(radical_inverse(2, 0) == 0.0);
    CHECK(radical_inverse(2, 1) == 0.5);
    CHECK(radical_inverse(2, 2) == 0.25);
    CHECK(radical_inverse(2, 3) == 0.75);
    CHECK(radical_inverse(2, 6) == 0.375);
    CHECK(radical_inverse(2, 13) == Approx(11.0 / 16.0).margin(1e-15));  // 1101b -> 0.1011b
    // Base 3: 5 = 12 (base 3) -> 0.21 = 2/3 + 1/9; 9 = 100 -> 0.001 = 1/27.
    CHECK(radical_inverse(3, 1) == Approx(1.0 / 3.0).margin(1e-15));
    CHECK(radical_inverse(3, 5) == Approx(2.0 / 3.0 + 1.0 / 9.0).margin(1e-15));
    CHECK(radical_inverse(3, 9) == Approx(1.0 / 27.0).margin(1e-15));
    // Base 5, 4 digits: 194 = 1234 (base 5) -> 0.4321.
    CHECK(radical_inverse(5, 194) == Approx(4.0 / 5 + 3.0 / 25 + 2.0 / 125 + 1.0 / 625).margin(1e-15));
    // A large index: 2^40 + 1 in base 2 -> 2^-1 + 2^-41.
    CHECK(radical_inverse(2, (std::uint64_t{1} << 40) + 1) == 0.5 + 0x1p-41);
    // The first b^2 points in base b fill the b^2 intervals [j / b^2, (j + 1) / b^2) once each.
    for (std::uint32_t base : {2u, 3u, 7u}) {
        std::vector<int> count(base * base, 0);
        for (std::uint64_t i = 0; i < base * base; ++i) {
            const double x = radical_inverse(base, i);
            REQUIRE(x >= 0.0);
            REQUIRE(x < 1.0);
            ++count[static_cast<std::size_t>(x * base * base + 1e-9)];
        }
        for (int c : count) CHECK(c == 1);
    }
}

namespace {

// m_1 ... m_count of a dimension by Bratley and Fox's recurrence on the odd integers m_k:
// m_k = 2 a_1 m_(k-1) XOR 2^2 a_2 m_(k-2) XOR ... XOR 2^(s-1) a_(s-1) m_(k-s+1) XOR 2^s m_(k-s) XOR m_(k-s).
std::vector<std::uint64_t> bratley_fox_m(const DirectionNumbers& d, int count) {
    const int s = d.degree;
    std::vector<std::uint64_t> m(d.initial.begin(), d.initial.begin() + s);
    for (int k = s; k < count; ++k) {
        std::uint64_t next = (m[k - s] << s) ^ m[k - s];
        for (int j = 1; j < s; ++j) {
            const std::uint64_t a_j = (d.coefficients >> (s - 1 - j)) & 1u;
            if (a_j) next ^= m[k - j] << j;
        }
        m.push_back(next);
    }
    return m;
}

}  // namespace

TEST_CASE("ch09/sobol-direction-numbers", "[exercise]") {
    // Dimension 1 (the polynomial x + 1, m_1 = 1): m_k = 3 m_(k-1) in carry-less arithmetic.
    const GeneratorMatrix v1 = sobol_generator_matrix(1);
    const std::uint64_t m1[] = {1, 3, 5, 15, 17, 51, 85, 255};
    for (int k = 0; k < 8; ++k) {
        INFO("dimension 1, column " << k);
        REQUIRE(v1[k] == static_cast<std::uint32_t>(m1[k] << (31 - k)));
    }
    // Dimension 2 (x^2 + x + 1, m = 1, 3): 1, 3, 3, 9, 29, as Bratley and Fox list it.
    const GeneratorMatrix v2 = sobol_generator_matrix(2);
    const std::uint64_t m2[] = {1, 3, 3, 9, 29};
    for (int k = 0; k < 5; ++k) {
        INFO("dimension 2, column " << k);
        CHECK(v2[k] == static_cast<std::uint32_t>(m2[k] << (31 - k)));
    }
    // Every dimension, all 32 columns, against the integer recurrence.
    for (int d = 1; d < SobolDimensions; ++d) {
        const GeneratorMatrix v = sobol_generator_matrix(d);
        const std::vector<std::uint64_t> m = bratley_fox_m(direction_numbers(d), 32);
        for (int k = 0; k < 32; ++k) {
            INFO("dimension " << d << ", column " << k << " (m_" << k + 1 << " = " << m[k] << ")");
            CHECK(v[k] == static_cast<std::uint32_t>(m[k] << (31 - k)));
        }
    }
    // The first points of dimension 1: 0, 1/2, 3/4, 1/4, 5/8, 1/8, 3/8, 7/8.
    const double points[] = {0, 0.5, 0.75, 0.25, 0.625, 0.125, 0.375, 0.875};
    for (std::uint32_t i = 0; i < 8; ++i) CHECK(sobol_sample(i, 1) == static_cast<float>(points[i]));
}
