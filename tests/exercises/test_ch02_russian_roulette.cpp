// Grading test of chapter 02's Russian roulette exercise.
#include "freezeray/ch02/path_tracer.hpp"

#include <catch2/catch.hpp>

using namespace freezeray;

TEST_CASE("ch02/russian-roulette", "[exercise]") {
    // The continuation probability is the throughput's largest component, capped at 0.95 so
    // that even bright paths end eventually (the path tracer divides survivors by it).
    CHECK(ch02::russian_roulette_continue_probability(Spectrum(0.5f, 0.2f, 0.1f)) == Approx(0.5f));
    CHECK(ch02::russian_roulette_continue_probability(Spectrum(0.1f, 0.3f, 0.05f)) == Approx(0.3f));
    CHECK(ch02::russian_roulette_continue_probability(Spectrum(2.0f, 0.1f, 0.1f)) == Approx(0.95f));
    CHECK(ch02::russian_roulette_continue_probability(Spectrum(0.95f)) == Approx(0.95f));
    CHECK(ch02::russian_roulette_continue_probability(Spectrum(0.0f)) == 0.0f);
}
