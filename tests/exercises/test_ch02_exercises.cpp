// Grading tests of chapter 02's exercises. Each test case is named after its exercise, calls the
// exercise's own function first (so that in a student copy it fails through its own stub), and
// checks it against exact values or its density (chi-square, false-failure rate
// exercise_test_alpha each).
#include "freezeray/ch02/cosine_lambertian.hpp"
#include "freezeray/ch02/fresnel.hpp"
#include "freezeray/ch02/microfacet.hpp"

#include "chi_square.hpp"
#include "evidence.hpp"
#include "reference_blocks.hpp"
#include "statistics.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace freezeray;
using namespace freezeray::ch02;

namespace {

constexpr double pi = 3.14159265358979323846;

// On failure the chi-square table is written as images (observed, expected, deviation per cell),
// and the folder named.
void check_passes(const stats::ChiSquareResult& result) {
    INFO(result.message);
    const std::string evidence =
        result.passed ? ""
                      : "evidence: " + stats::write_evidence(Catch::getResultCapture().getCurrentTestName(), result);
    INFO(evidence);
    CHECK(result.passed);
}

}  // namespace

TEST_CASE("ch02/cosine-hemisphere", "[exercise]") {
    // Every direction is a unit vector on the upper hemisphere, and their distribution over the
    // whole sphere matches the density cos(theta) / pi on z >= 0.
    PCG32 random(12, 1);
    for (int i = 0; i < 10000; ++i) {
        const Vec3 w = sample_cosine_hemisphere(Vec2(random.next_float(), random.next_float()));
        REQUIRE(glm::length(w) == Approx(1.0f).margin(1e-5));
        REQUIRE(w.z >= 0.0f);
    }
    stats::ChiSquareOptions options;
    options.alpha = stats::exercise_test_alpha;
    check_passes(stats::chi_square_test(
        stats::Domain::sphere(),
        [](PCG32& r) -> std::optional<Vec3> { return sample_cosine_hemisphere(Vec2(r.next_float(), r.next_float())); },
        [](const Vec3& w) { return w.z >= 0.0f ? w.z / pi : 0.0; }, options));
}

TEST_CASE("ch02/dielectric-fresnel", "[exercise]") {
    // Normal incidence on glass: ((1.5 - 1) / (1.5 + 1))^2 = 0.04, from either side.
    REQUIRE(fresnel_dielectric(1.0f, 1.5f) == Approx(0.04).margin(1e-6));
    CHECK(fresnel_dielectric(-1.0f, 1.5f) == Approx(0.04).margin(1e-6));
    // Oblique incidence against Fresnel's sine and tangent laws, computed here in double:
    // R = (sin^2(i - t) / sin^2(i + t) + tan^2(i - t) / tan^2(i + t)) / 2.
    for (double eta : {1.33, 1.5, 2.4}) {
        for (double degrees : {20.0, 45.0, 70.0, 85.0}) {
            const double i = degrees * pi / 180.0;
            const double t = std::asin(std::sin(i) / eta);
            const double rs = std::sin(i - t) / std::sin(i + t);
            const double rp = std::tan(i - t) / std::tan(i + t);
            const double expected = 0.5 * (rs * rs + rp * rp);
            INFO("eta " << eta << ", " << degrees << " degrees from outside");
            CHECK(fresnel_dielectric(static_cast<float>(std::cos(i)), static_cast<float>(eta)) ==
                  Approx(expected).epsilon(1e-4));
            // The same interface from inside, along the refracted direction: the same reflectance.
            INFO("and from inside at " << t * 180.0 / pi << " degrees");
            CHECK(fresnel_dielectric(-static_cast<float>(std::cos(t)), static_cast<float>(eta)) ==
                  Approx(expected).epsilon(1e-3));
        }
    }
    // Total internal reflection from inside beyond the critical angle (41.8 degrees for 1.5).
    CHECK(fresnel_dielectric(-0.5f, 1.5f) == 1.0f);
    CHECK(fresnel_dielectric(0.5f, 1.0f / 1.5f) == 1.0f);
    // Index-matched: nothing is reflected.
    CHECK(fresnel_dielectric(0.3f, 1.0f) == Approx(0.0).margin(1e-7));
}

TEST_CASE("ch02/ggx-visible-normals", "[exercise]") {
    // The sampled normals are unit vectors on the upper hemisphere, distributed as the normals
    // visible from w, D(w, wm) = G1(w) |w.wm| D(wm) / |cos theta(w)|: isotropic, anisotropic,
    // grazing, and from below the surface.
    struct Case {
        TrowbridgeReitz distribution;
        Vec3 w;
    };
    const Case cases[] = {
        {TrowbridgeReitz(0.3f, 0.3f), glm::normalize(Vec3(0.5f, 0.2f, 0.8f))},
        {TrowbridgeReitz(0.2f, 0.7f), glm::normalize(Vec3(-0.6f, 0.3f, 0.2f))},
        {TrowbridgeReitz(0.5f, 0.5f), glm::normalize(Vec3(0.4f, -0.1f, -0.7f))},
    };
    for (const Case& c : cases) {
        PCG32 random(13, 1);
        for (int i = 0; i < 10000; ++i) {
            const Vec3 wm = c.distribution.sample_visible_normal(c.w, Vec2(random.next_float(), random.next_float()));
            REQUIRE(glm::length(wm) == Approx(1.0f).margin(1e-5));
            REQUIRE(wm.z > 0.0f);
        }
        stats::ChiSquareOptions options;
        options.alpha = stats::exercise_test_alpha;
        options.sample_count = 300'000;
        check_passes(stats::chi_square_test(
            stats::Domain::sphere(),
            [&](PCG32& r) -> std::optional<Vec3> {
                return c.distribution.sample_visible_normal(c.w, Vec2(r.next_float(), r.next_float()));
            },
            [&](const Vec3& wm) { return static_cast<double>(c.distribution.pdf(c.w, wm)); }, options));
    }
}

TEST_CASE("ch02/importance-sampled-path-tracer", "[exercise]") {
    // The assignment (tests/grading/assignments.json): this chapter's exercises together render the
    // material spheres (rough plastic, rough glass, rough gold, a mirror) with pt-is as the solution
    // does. 8 independent renders of 64 samples per pixel; each block of pixels, and the whole image,
    // against the solution's reference (make_references.py --blocks, other seeds, 8 to 32 times the
    // samples), false-failure rate exercise_test_alpha for the whole comparison
    // (reference_blocks.hpp).
    const testing::ReferenceComparison comparison =
        testing::compare_with_reference("ch02/importance-sampled-path-tracer", 8, 64, 1, stats::exercise_test_alpha);
    INFO(comparison.message);
    INFO(comparison.evidence);
    CHECK(comparison.passed);
}
