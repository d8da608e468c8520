// Scale (scenes/hard/scale-1e-4, scale-1e4, far-and-tiny): light transport does not know the
// unit of length, so the Cornell box scaled by 1e-4 or 1e4 renders the Cornell box's image, and a
// tiny object inside huge geometry renders as if it were alone. What breaks this is a ray offset
// or epsilon that does not scale with the geometry (common/core/src/ray.cpp, make_hit in
// common/core/src/accelerator.cpp use pbrt's error bounds, which do).
#include "stability_support.hpp"

#include "test_scenes.hpp"

#include "freezeray/random.hpp"
#include "freezeray/ch01/warps.hpp"

#include <catch2/catch.hpp>

using namespace freezeray;
using namespace freezeray::ch01;
using namespace freezeray::stability;

namespace {

// Spawns rays from surface points in every direction, on both sides (reflection and
// transmission), and counts those that hit the triangle they left: a flat triangle can never be
// hit again by a ray leaving it, so every such hit is a self-intersection. The points are where
// camera rays land, and where rays spawned from those land (second bounces), 4 x 4 per pixel.
struct SelfIntersections {
    std::size_t spawned = 0;
    std::size_t self_hits = 0;
};

SelfIntersections count_self_intersections(const Scene& scene) {
    SelfIntersections counts;
    PCG32 random(77, 3);
    const Camera& camera = *scene.camera;
    auto spawn_from = [&](const Hit& hit, const Vec3& direction) -> std::optional<Hit> {
        ++counts.spawned;
        const std::optional<Hit> next = scene.intersect(hit.spawn_ray(direction));
        if (next && next->mesh == hit.mesh && next->triangle == hit.triangle) ++counts.self_hits;
        return next;
    };
    for (int y = 0; y < camera.height(); ++y) {
        for (int x = 0; x < camera.width(); ++x) {
            for (int s = 0; s < 16; ++s) {
                const Vec2 film(x + (s % 4 + random.next_float()) / 4.0f, y + (s / 4 + random.next_float()) / 4.0f);
                const std::optional<Hit> first = scene.intersect(camera.generate_ray(film));
                if (!first) continue;
                const Frame frame(first->geometric_normal);
                // Nearly tangent directions are the hardest: sample cos theta down to 1e-4.
                for (const float side : {1.0f, -1.0f}) {
                    Vec3 local = sample_uniform_hemisphere(Vec2(random.next_float(), random.next_float()));
                    if (s % 2 == 0) local.z = std::max(local.z * 1e-3f, 1e-4f);
                    local = glm::normalize(local);
                    local.z *= side;
                    const std::optional<Hit> second = spawn_from(*first, frame.to_world(local));
                    if (!second) continue;
                    const Frame second_frame(second->geometric_normal);
                    const Vec3 bounce = sample_uniform_hemisphere(Vec2(random.next_float(), random.next_float()));
                    spawn_from(*second, second_frame.to_world(s % 3 == 0 ? -bounce : bounce));
                }
            }
        }
    }
    return counts;
}

}  // namespace

TEST_CASE("rays spawned from the Cornell box at scales 1e-4, 1 and 1e4 never hit their own triangle",
          "[stability][scale]") {
    for (const std::string& file : {std::string("scale-1e-4/scene.json"), std::string("scale-1e4/scene.json"),
                                    std::string("../cornell-box/scene.json"), std::string("far-and-tiny/scene.json")}) {
        const Scene scene = load(file, 24);
        const SelfIntersections counts = count_self_intersections(scene);
        INFO(file << ": " << counts.self_hits << " of " << counts.spawned << " spawned rays hit their own triangle");
        CHECK(counts.spawned > 10000u);
        CHECK(counts.self_hits == 0u);
    }
}

TEST_CASE("the Cornell box scaled by 1e-4 and by 1e4 renders the Cornell box's image", "[stability][scale]") {
    // Welch's test per 8x8 block between the scaled box and the original (independent seeds),
    // at 32x32 and 256 samples per pixel, for each integrator: 8 two-sample tests.
    std::uint64_t seed = 50;
    for (const std::string& integrator : all_integrators()) {
        testing::TestRender original_request;
        original_request.scene = testing::scene_path("cornell-box/scene.json");
        original_request.integrator = integrator;
        original_request.width = original_request.height = 32;
        original_request.samples_per_pixel = 256;
        original_request.seed = seed++;
        original_request.threads = 1;
        const RenderResult original = testing::render(original_request);
        check_valid(original, "cornell-box with " + integrator);
        for (const std::string& file : {std::string("scale-1e-4/scene.json"), std::string("scale-1e4/scene.json")}) {
            HardRender request;
            request.scene = file;
            request.integrator = integrator;
            request.size = 32;
            request.samples_per_pixel = 256;
            request.seed = seed++;
            const RenderResult scaled = render(request);
            check_valid(scaled, file + " with " + integrator);
            const EnergyTestResult test = agreement_test(scaled, original, 0.0, 8, stability_test_alpha);
            INFO(file << " with " << integrator);
            if (!test.passed)
                FAIL(test.message << "\nevidence: "
                                  << write_evidence("scale " + file + " " + integrator, test.message,
                                                    {{"scaled", &scaled}, {"original", &original}}));
            SUCCEED(test.message);
        }
    }
}

TEST_CASE("a tiny cube inside geometry 1e8 times larger renders as if alone", "[stability][scale]") {
    // Convex, white (albedo 0.5), under uniform radiance 1: every pt-is sample on the cube is 0.5
    // and on the enclosure 1, exactly. pt-naive's, pt-nee's and pt-mis's samples vary; their cube
    // pixels are tested against 0.5 with the one-sample test.
    const Scene scene = load("far-and-tiny/scene.json");
    const std::vector<int> coverage = pixel_coverage(scene);
    const std::vector<std::size_t> cube = pixels_where(coverage, 1);
    const std::vector<std::size_t> enclosure = pixels_where(coverage, 0);
    REQUIRE(cube.size() > 200u);
    REQUIRE(enclosure.size() > 200u);
    for (const std::string& integrator : all_integrators()) {
        HardRender request;
        request.scene = "far-and-tiny/scene.json";
        request.integrator = integrator;
        request.samples_per_pixel = 64;
        request.seed = 60;
        const RenderResult result = render(request);
        check_valid(result, "far-and-tiny with " + integrator);
        std::size_t wrong_enclosure = 0, wrong_cube = 0;
        for (const std::size_t i : enclosure) wrong_enclosure += result.image[i] == Spectrum(1.0f) ? 0 : 1;
        CHECK(wrong_enclosure == 0u);
        if (integrator == "pt-is") {
            for (const std::size_t i : cube)
                wrong_cube += glm::all(glm::lessThan(glm::abs(result.image[i] - Spectrum(0.5f)), Spectrum(1e-5f))) ? 0 : 1;
            INFO(wrong_cube << " of " << cube.size() << " cube pixels are not 0.5");
            CHECK(wrong_cube == 0u);
        } else {
            // Only the cube's pixels: the enclosure's are exactly 1 (checked above).
            RenderResult cube_only = result;
            for (std::size_t i = 0; i < coverage.size(); ++i)
                if (coverage[i] != 1) {
                    cube_only.image[i] = Spectrum(0.5f);
                    cube_only.variance[i] = Spectrum(0.0f);
                }
            const EnergyTestResult test = energy_test(cube_only, 0.5, Expectation::Equal, 16,
                                                      {{"cube pixels", cube}}, one_sample_stability_alpha);
            if (!test.passed)
                FAIL(test.message << "\nevidence: "
                                  << write_evidence("far-and-tiny " + integrator, test.message, {{integrator, &result}}));
            SUCCEED(test.message);
        }
    }
}
