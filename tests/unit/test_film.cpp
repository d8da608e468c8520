// The film's running mean and variance.
#include "freezeray/film.hpp"
#include "freezeray/random.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <vector>

using namespace freezeray;

TEST_CASE("the film's mean and variance of the mean match the two-pass formulas", "[unit][film]") {
    Film film(2, 1);
    PCG32 random(1, 2);
    std::vector<double> values;
    for (int i = 0; i < 1000; ++i) {
        const float v = 5.0f + random.next_float();  // an offset that would hurt a naive sum of squares
        values.push_back(v);
        film.add_sample(0, 0, Spectrum(v, 2 * v, 0));
    }
    double mean = 0;
    for (double v : values) mean += v;
    mean /= values.size();
    double variance = 0;
    for (double v : values) variance += (v - mean) * (v - mean);
    variance /= (values.size() - 1);

    CHECK(film.mean().at(0, 0).r == Approx(mean).epsilon(1e-6));
    CHECK(film.mean().at(0, 0).g == Approx(2 * mean).epsilon(1e-6));
    CHECK(film.variance_of_mean().at(0, 0).r == Approx(variance / 1000).epsilon(1e-4));
    CHECK(film.variance_of_mean().at(0, 0).g == Approx(4 * variance / 1000).epsilon(1e-4));
    CHECK(film.sample_count(0, 0) == 1000u);
    CHECK(film.sample_count(1, 0) == 0u);
}

TEST_CASE("invalid samples are counted and enter the mean as zero", "[unit][film]") {
    Film film(1, 1);
    film.add_sample(0, 0, Spectrum(1.0f));
    film.add_sample(0, 0, Spectrum(std::numeric_limits<float>::quiet_NaN(), 0, 0));
    film.add_sample(0, 0, Spectrum(std::numeric_limits<float>::infinity()));
    film.add_sample(0, 0, Spectrum(-1.0f, 1, 1));
    CHECK(film.invalid_sample_count() == 3u);
    CHECK(film.mean().at(0, 0).r == Approx(0.25f));
    CHECK(std::isfinite(film.variance_of_mean().at(0, 0).r));
}

TEST_CASE("a film restored from its images has the same mean, variance and count", "[unit][film]") {
    Film film(3, 2);
    PCG32 random(4, 4);
    for (int s = 0; s < 16; ++s)
        for (int y = 0; y < 2; ++y)
            for (int x = 0; x < 3; ++x) film.add_sample(x, y, Spectrum(random.next_float()));
    const Film restored = Film::from_images(film.mean(), film.variance_of_mean(), 16);
    CHECK(restored.sample_count(2, 1) == 16u);
    CHECK(restored.mean().at(2, 1).r == film.mean().at(2, 1).r);
    CHECK(restored.variance_of_mean().at(2, 1).r == Approx(film.variance_of_mean().at(2, 1).r).epsilon(1e-5));
    CHECK(restored.estimated_relative_mse() == Approx(film.estimated_relative_mse()).epsilon(1e-5));
}
