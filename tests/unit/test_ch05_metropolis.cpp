// Chapter 05: the Metropolis-Hastings machinery in primary sample space on its own. A rejected
// proposal restores the exact previous state (deterministic), and chains driven by
// PrimarySamples and acceptance_probability sample a known 1-D and 2-D target density
// (chi-square, 2 tests at chi_square_test_alpha = unit_test_alpha = 1e-6, counted in the unit
// label's allowance: tests/STATISTICS.md).
#include "freezeray/ch05/metropolis.hpp"
#include "freezeray/ch05/primary_samples.hpp"

#include "chi_square.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

using namespace freezeray;
using namespace freezeray::ch05;

TEST_CASE("a rejected proposal restores every primary sample exactly, and an accepted one keeps it",
          "[unit][ch05]") {
    PrimarySamples samples(PCG32(7, 3), 0.05f, 0.3f, 3);
    auto read = [&](int stream, int count) {
        samples.start_stream(stream);
        std::vector<float> values;
        for (int i = 0; i < count; ++i) values.push_back(samples.next_float());
        return values;
    };
    // The first state reads 4 numbers of stream 0 and 6 of stream 1.
    const std::vector<float> first0 = read(0, 4), first1 = read(1, 6);
    int proposals_that_changed_something = 0, large = 0;
    for (int iteration = 0; iteration < 200; ++iteration) {
        const std::vector<PrimarySample> before = samples.samples();
        const std::uint64_t iteration_before = samples.iteration();
        samples.start_iteration();
        // A proposal reads more than the state did (a longer path): 7 of stream 0, 6 of stream 2.
        const std::vector<float> proposal0 = read(0, 7);
        read(2, 6);
        if (samples.large_step()) ++large;
        bool changed = false;
        for (int i = 0; i < 4; ++i) changed = changed || proposal0[static_cast<std::size_t>(i)] != first0[static_cast<std::size_t>(i)];
        proposals_that_changed_something += changed ? 1 : 0;
        samples.reject();
        REQUIRE(samples.iteration() == iteration_before);
        // Every number the state had is back, bit for bit, with its iteration.
        const std::vector<PrimarySample>& after = samples.samples();
        for (std::size_t i = 0; i < before.size(); ++i) {
            INFO("iteration " << iteration << ", primary sample " << i);
            REQUIRE(after[i].value == before[i].value);
            REQUIRE(after[i].last_modified == before[i].last_modified);
        }
        // Reading the state again gives the state (no mutation outside an iteration).
        CHECK(read(0, 4) == first0);
        CHECK(read(1, 6) == first1);
    }
    CHECK(proposals_that_changed_something == 200);  // every proposal moved the state's numbers
    CHECK(large > 20);
    CHECK(large < 100);  // 0.3 of 200 = 60 expected

    // An accepted proposal is the new state.
    samples.start_iteration();
    const std::vector<float> proposal = read(0, 4);
    samples.accept();
    CHECK(read(0, 4) == proposal);
    CHECK(proposal != first0);
}

TEST_CASE("acceptance_probability and small_step: exact values", "[unit][ch05]") {
    CHECK(acceptance_probability(2.0f, 1.0f) == 0.5f);
    CHECK(acceptance_probability(1.0f, 3.0f) == 1.0f);
    CHECK(acceptance_probability(0.0f, 0.0f) == 1.0f);
    CHECK(acceptance_probability(1.0f, 0.0f) == 0.0f);
    CHECK(small_step(0.5f, 1.0f, 0.1f, 4) == Approx(0.7f));
    CHECK(small_step(0.95f, 1.0f, 0.1f, 1) == Approx(0.05f).margin(1e-6));
    CHECK(small_step(0.05f, -1.0f, 0.1f, 1) == Approx(0.95f).margin(1e-6));
    const float wrapped = small_step(0.0f, -1e-9f, 1.0f, 1);  // wraps to just below 1, never 1
    CHECK(wrapped < 1.0f);
    CHECK(wrapped >= 0.0f);
}

namespace {

// The last state of a Metropolis chain of `steps` proposals on the target f over [0, 1)^dimensions,
// started from a uniform point: after 128 steps with large steps of probability 0.3 it is
// distributed as f / integral up to a total variation of (1 - 0.3 / (max f / mean f))^128, below
// 1e-7 for the targets here (an independence sampler's geometric convergence), far below what
// 2e5 samples can see.
template <typename Target>
Vec3 chain_end(PCG32& random, int dimensions, const Target& f, int steps) {
    PrimarySamples samples(PCG32(random.next_uint(), random.next_uint()), 0.05f, 0.3f, 1);
    PCG32 acceptance(random.next_uint(), random.next_uint());
    auto read = [&] {
        samples.start_stream(0);
        Vec3 point(0.0f);
        for (int d = 0; d < dimensions; ++d) point[d] = samples.next_float();
        return point;
    };
    Vec3 current = read();
    float current_value = f(current);
    for (int step = 0; step < steps; ++step) {
        samples.start_iteration();
        const Vec3 proposed = read();
        const float proposed_value = f(proposed);
        if (acceptance.next_float() < acceptance_probability(current_value, proposed_value)) {
            samples.accept();
            current = proposed;
            current_value = proposed_value;
        } else {
            samples.reject();
        }
    }
    return current;
}

}  // namespace

TEST_CASE("Metropolis chains in primary sample space sample a known 1-D density (chi-square)", "[unit][ch05]") {
    // f(x) = 0.5 + 3 x^2 on [0, 1): integral 1.5, max / mean 2.33.
    const auto f = [](const Vec3& p) { return 0.5f + 3.0f * p.x * p.x; };
    stats::ChiSquareOptions options;
    options.sample_count = 200000;
    options.resolution = 40;
    options.seed = 501;
    const stats::ChiSquareResult result = stats::chi_square_test(
        stats::Domain::interval(0.0, 1.0), [&](PCG32& random) -> std::optional<Vec3> { return chain_end(random, 1, f, 128); },
        [](const Vec3& p) { return (0.5 + 3.0 * p.x * p.x) / 1.5; }, options);
    INFO(result.message);
    CHECK(result.passed);
}

TEST_CASE("Metropolis chains in primary sample space sample a known 2-D density (chi-square)", "[unit][ch05]") {
    // f(x, y) = (1 + 0.8 sin(2 pi x)) (y + 0.2) on [0, 1)^2: integral 0.7, max / mean 3.1; the
    // sine wraps around x = 0, where small steps cross the edge.
    const auto f = [](const Vec3& p) { return (1.0f + 0.8f * std::sin(2.0f * 3.14159265f * p.x)) * (p.y + 0.2f); };
    stats::ChiSquareOptions options;
    options.sample_count = 200000;
    options.resolution = 12;
    options.seed = 502;
    const stats::ChiSquareResult result = stats::chi_square_test(
        stats::Domain::unit_square(), [&](PCG32& random) -> std::optional<Vec3> { return chain_end(random, 2, f, 128); },
        [](const Vec3& p) { return (1.0 + 0.8 * std::sin(2.0 * 3.14159265358979 * p.x)) * (p.y + 0.2) / 0.7; }, options);
    INFO(result.message);
    CHECK(result.passed);
}
