// Grading tests of chapter 09's exercises. Each test case is named after its exercise, calls the
// exercise's own function first (so that in a student copy it fails through its own stub), and
// checks it against exact values: the radical inverse against digits written out by hand, the
// Sobol matrices against direction numbers computed here from Bratley and Fox's integer form of
// the recurrence (ACM TOMS 14, 1988, "Algorithm 659"), which the solution does not use; the
// Owen hash by the properties its contract states (bits carried upwards only, a bijection of
// every prefix, coins near fair for every pair of bits, seeds that matter) and by the nets that
// scrambled Sobol points still form, dimension 1 computed here from its direction numbers.
// Deterministic: fixed seeds, no statistical test in this file (the coins' frequencies are
// compared with a window wide enough for any reasonable hash, not tested for 1/2).
#include "freezeray/ch09/owen_scrambling.hpp"
#include "freezeray/ch09/radical_inverse.hpp"
#include "freezeray/ch09/sobol_matrices.hpp"
#include "freezeray/random.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdint>
#include <set>
#include <vector>

using namespace freezeray::ch09;
using freezeray::PCG32;

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

namespace {

// Point `index` of Sobol dimension 1 as a 0.32 fraction, from its direction numbers written out
// here: m_k = m_(k-1) XOR 2 m_(k-1) (the polynomial x + 1, m_1 = 1), so v_k = v_(k-1) XOR
// v_(k-1) / 2 in fixed point. Independent of the sobol-direction-numbers exercise.
std::uint32_t sobol_dimension_1(std::uint32_t index) {
    std::uint32_t v = 0x80000000u, x = 0;
    for (int k = 0; k < 32; ++k, v ^= v >> 1)
        if ((index >> k) & 1u) x ^= v;
    return x;
}

// Whether the points (x, y), 2^m of them as 0.32 fractions, form a (0, m, 2)-net: every
// elementary interval of 2^(-a) by 2^(-(m-a)) holds exactly one.
bool is_net(const std::vector<std::uint32_t>& xs, const std::vector<std::uint32_t>& ys, int m) {
    for (int a = 0; a <= m; ++a) {
        std::vector<int> count(std::size_t{1} << m, 0);
        for (std::size_t i = 0; i < xs.size(); ++i) {
            const std::uint64_t cx = a == 0 ? 0 : xs[i] >> (32 - a);
            const std::uint64_t cy = a == m ? 0 : ys[i] >> (32 - (m - a));
            if (++count[static_cast<std::size_t>(cx << (m - a) | cy)] > 1) return false;
        }
    }
    return true;
}

}  // namespace

TEST_CASE("ch09/owen-hash", "[exercise]") {
    // The hash first (its own code before any other): one word under two seeds.
    REQUIRE(laine_karras_permutation(0x12345678u, 0x9abcdef0u) != laine_karras_permutation(0x12345678u, 0x9abcdef1u));
    PCG32 random(909, 9);

    // Bit k depends on bits 0 to k only: words that agree in their low k + 1 bits have images that
    // agree in them.
    for (int trial = 0; trial < 20000; ++trial) {
        const std::uint32_t x = random.next_uint(), seed = random.next_uint();
        const int k = static_cast<int>(random.next_below(32));
        const std::uint32_t low = k == 31 ? ~0u : (2u << k) - 1u;
        const std::uint32_t y = (x & low) | (random.next_uint() & ~low);
        INFO("x = " << x << ", y = " << y << ", seed = " << seed << ": they agree in bits 0 to " << k);
        REQUIRE(((laine_karras_permutation(x, seed) ^ laine_karras_permutation(y, seed)) & low) == 0u);
    }

    // A bijection of the low k bits, for every k up to 16 and several seeds (and so, with the
    // property above, of every word).
    for (const std::uint32_t seed : {0u, 1u, 0x80000000u, 0x5bd1e995u, random.next_uint(), random.next_uint()}) {
        for (int k = 1; k <= 16; ++k) {
            const std::uint32_t size = 1u << k;
            std::vector<bool> seen(size, false);
            std::uint32_t distinct = 0;
            for (std::uint32_t x = 0; x < size; ++x) {
                const std::uint32_t image = laine_karras_permutation(x, seed) & (size - 1);
                distinct += !seen[image];
                seen[image] = true;
            }
            INFO("seed " << seed << ": the " << size << " words below 2^" << k << " have " << distinct
                         << " different low " << k << " bits");
            REQUIRE(distinct == size);
        }
    }

    // Owen's coins: for two words that first differ at bit j, bit k > j of their images differs
    // for about half the seeds. 4000 random pairs and seeds per (j, k): Burley's hash gives 0.32
    // to 0.75 (the standard deviation of a frequency is at most 0.008); an addition of the seed
    // alone gives 2^-(k-j), a product by an odd number 0 or 1 for some pairs of bits.
    for (int j = 0; j < 31; ++j)
        for (int k = j + 1; k < 32; ++k) {
            int differ = 0;
            const int pairs = 4000;
            for (int n = 0; n < pairs; ++n) {
                const std::uint32_t x = random.next_uint(), seed = random.next_uint();
                differ += ((laine_karras_permutation(x, seed) ^ laine_karras_permutation(x ^ (1u << j), seed)) >> k) & 1u;
            }
            const double frequency = static_cast<double>(differ) / pairs;
            INFO("words differing first at bit " << j << ": bit " << k << " of their images differs for " << frequency
                                                 << " of the seeds (a fair coin: 0.5)");
            REQUIRE(frequency > 0.2);
            REQUIRE(frequency < 0.8);
        }

    // Different seeds, different permutations: the images of the 256 words below 2^8 under 200
    // seeds are 200 different lists.
    std::set<std::vector<std::uint32_t>> permutations;
    for (std::uint32_t s = 0; s < 200; ++s) {
        const std::uint32_t seed = random.next_uint();
        std::vector<std::uint32_t> images(256);
        for (std::uint32_t x = 0; x < 256; ++x) images[x] = laine_karras_permutation(x, seed);
        permutations.insert(images);
    }
    CHECK(permutations.size() == 200);

    // Scrambled Sobol points stay nets: the first 2^m points of dimensions 0 and 1, each
    // coordinate scrambled with its own seed, are (0, m, 2)-nets for every m up to 12; and the
    // scramble moves them (not every point where it was).
    for (int trial = 0; trial < 4; ++trial) {
        const std::uint32_t seed_x = random.next_uint(), seed_y = random.next_uint();
        std::vector<std::uint32_t> xs, ys;
        int moved = 0;
        for (int m = 0; m <= 12; ++m) {
            while (xs.size() < (std::size_t{1} << m)) {
                const auto i = static_cast<std::uint32_t>(xs.size());
                xs.push_back(nested_uniform_scramble(reverse_bits(i), seed_x));
                ys.push_back(nested_uniform_scramble(sobol_dimension_1(i), seed_y));
                moved += xs.back() != reverse_bits(i);
            }
            INFO("seeds " << seed_x << ", " << seed_y << ": the first " << xs.size() << " scrambled points");
            REQUIRE(is_net(xs, ys, m));
        }
        CHECK(moved > 4000);
    }
}
