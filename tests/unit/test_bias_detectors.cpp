// The grading tests' bias detectors (tests/support/bias_detectors.hpp): the furnace's predicted
// answers for each classic mistake, against their closed forms, and the choice of the nearest.
// Deterministic: no statistical test in this file.
#include "bias_detectors.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace freezeray::testing;

TEST_CASE("bias detectors: the furnace's answers for each mistake are Le (1 + q + ... )", "[unit]") {
    const double pi = 3.14159265358979323846;
    const std::vector<Suspect> one_bounce = furnace_suspects(0.5, 0.5, 2);
    REQUIRE(one_bounce.size() == 4u);
    CHECK(one_bounce[0].predicted == Approx(1.0));                              // f / pdf: q = 2 rho = 1
    CHECK(one_bounce[1].predicted == Approx(0.5 * (1.0 + 0.5 / (2.0 * pi))));  // f |cos|
    CHECK(one_bounce[2].predicted == Approx(0.5 * (1.0 + pi)));                // f |cos| / pdf^2
    CHECK(one_bounce[3].predicted == Approx(0.5 * (1.0 + 0.5 / (4.0 * pi * pi))));  // f |cos| pdf
    // 64 segments without the cosine: each bounce weighs exactly 1, so 64 emissions of 0.5.
    CHECK(furnace_suspects(0.5, 0.5, 64)[0].predicted == Approx(32.0));
}

TEST_CASE("bias detectors: the nearest suspect within the tolerance is named, else none", "[unit]") {
    const std::vector<Suspect> suspects{{"a", 1.0}, {"b", 0.54}, {"c", 0.506}};
    CHECK_THAT(likely_mistake(0.99, suspects, 0.025), Catch::StartsWith("likely mistake: a ("));
    CHECK_THAT(likely_mistake(0.545, suspects, 0.025), Catch::StartsWith("likely mistake: b ("));
    CHECK_THAT(likely_mistake(0.51, suspects, 0.025), Catch::StartsWith("likely mistake: c ("));
    CHECK(likely_mistake(0.75, suspects, 0.025).empty());  // the right answer matches no mistake
    CHECK(likely_mistake(std::nan(""), suspects, 0.025).empty());
}
