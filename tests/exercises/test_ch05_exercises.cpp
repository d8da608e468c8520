// Grading tests of chapter 05's exercises. Each test case is named after its exercise, calls the
// exercise's own function first (so that in a student copy it fails through its own stub), and
// checks it against exact values; small-step also by the symmetry the Metropolis acceptance
// relies on. Deterministic: no statistical test in this file.
#include "freezeray/ch05/metropolis.hpp"

#include "reference_blocks.hpp"
#include "statistics.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace freezeray::ch05;

TEST_CASE("ch05/acceptance-probability", "[exercise]") {
    // Metropolis et al. 1953 for a symmetric proposal: a = min(1, f(proposed) / f(current)).
    REQUIRE(acceptance_probability(4.0f, 1.0f) == Approx(0.25));
    CHECK(acceptance_probability(1.0f, 4.0f) == 1.0f);   // uphill: always
    CHECK(acceptance_probability(2.0f, 2.0f) == 1.0f);
    CHECK(acceptance_probability(3.0f, 0.0f) == 0.0f);   // a proposal that carries nothing: never
    CHECK(acceptance_probability(0.0f, 0.0f) == 1.0f);   // a chain without light accepts anything
    CHECK(acceptance_probability(0.0f, 5.0f) == 1.0f);
    CHECK(acceptance_probability(1e-30f, 1e30f) == 1.0f);
    CHECK(acceptance_probability(1e30f, 1e-30f) >= 0.0f);
}

TEST_CASE("ch05/small-step", "[exercise]") {
    // value + normal sigma sqrt(steps), wrapped into [0, 1) (Kelemen et al. 2002).
    REQUIRE(small_step(0.5f, 1.0f, 0.1f, 1) == Approx(0.6f));
    CHECK(small_step(0.5f, -2.0f, 0.1f, 1) == Approx(0.3f));
    CHECK(small_step(0.5f, 1.0f, 0.1f, 9) == Approx(0.8f));       // 9 steps: 3 sigma
    CHECK(small_step(0.9f, 1.0f, 0.25f, 1) == Approx(0.15f));     // wraps past 1
    CHECK(small_step(0.1f, -1.0f, 0.25f, 1) == Approx(0.85f));    // wraps past 0
    CHECK(small_step(0.25f, 3.0f, 1.0f, 1) == Approx(0.25f).margin(1e-6));  // a whole turn and back
    // Always in [0, 1): even a step that lands a hair below 0.
    for (const float normal : {-1e-9f, -1e-7f, -0.5f, 0.5f, 1e-7f}) {
        const float x = small_step(0.0f, normal, 1.0f, 1);
        INFO("normal " << normal << " gives " << x);
        CHECK(x >= 0.0f);
        CHECK(x < 1.0f);
    }
    // Symmetric (what lets the acceptance be min(1, f(y) / f(x))): the step from x to y by +n
    // comes back from y to x by -n.
    for (const float x : {0.05f, 0.3f, 0.77f, 0.99f}) {
        const float y = small_step(x, 1.3f, 0.2f, 2);
        CHECK(small_step(y, -1.3f, 0.2f, 2) == Approx(x).margin(1e-5));
    }
}

TEST_CASE("ch05/metropolis-light-transport", "[exercise]") {
    // The assignment (tests/grading/assignments.json): this chapter's exercises together render the
    // Cornell box with mlt as the solution does. 8 independent renders (each its own chains and
    // bootstrap) of 16 samples per pixel; each block of pixels, and the whole image, against the
    // solution's reference (make_references.py --blocks, other seeds, 8 to 32 times the samples),
    // false-failure rate exercise_test_alpha for the whole comparison (reference_blocks.hpp).
    const freezeray::testing::ReferenceComparison comparison = freezeray::testing::compare_with_reference(
        "ch05/metropolis-light-transport", 8, 16, 1, freezeray::stats::exercise_test_alpha);
    INFO(comparison.message);
    INFO(comparison.evidence);
    CHECK(comparison.passed);
}
