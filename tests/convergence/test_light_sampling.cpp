// Chapter 03's light sampling: closed forms (the white furnace under a constant environment, a
// diffuse floor under a point light and under a spot light) and agreement of pt-is, pt-nee and
// pt-mis where all of them apply (the Cornell box, veach-mis) and of pt-nee and pt-mis where
// only light sampling can find the light (point and spot lights).
#include "evidence.hpp"
#include "image_tests.hpp"
#include "statistics.hpp"
#include "test_scenes.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <sstream>

using namespace freezeray;

namespace {

RenderResult render_scene(const std::string& scene, const std::string& integrator, std::uint64_t seed,
                          std::uint64_t spp, int width = 0, int height = 0, int max_depth = 0) {
    testing::TestRender request;
    request.scene = testing::scene_path(scene);
    request.integrator = integrator;
    request.width = width;
    request.height = height;
    request.samples_per_pixel = spp;
    request.seed = seed;
    request.max_depth = max_depth;
    return testing::render(request);
}

// Passes, or fails with the evidence (both renders, their variances, the p-value map) on disk.
void require_agreement(const std::string& name, const stats::ImageTestResult& test, const std::string& a_name,
                       const RenderResult& a, const std::string& b_name, const RenderResult& b) {
    if (!test.passed) {
        const std::string folder = stats::write_evidence(
            name, test,
            {{a_name, a.image}, {a_name + "-variance", a.variance}, {b_name, b.image}, {b_name + "-variance", b.variance}});
        FAIL(name << ": " << test.message << "\nevidence: " << folder);
    }
    SUCCEED(name << ": " << test.message);
}

// Renders a scene with each integrator (independent seeds) and compares every pair with the
// blockwise Welch test at each block size: one statistical test per pair and block size.
void require_pairwise_agreement(const std::string& scene, const std::vector<std::string>& integrators,
                                std::uint64_t first_seed, std::uint64_t spp, int width, int height, int max_depth,
                                const std::vector<int>& block_sizes) {
    std::map<std::string, RenderResult> renders;
    std::uint64_t seed = first_seed;
    for (const std::string& integrator : integrators) {
        renders[integrator] = render_scene(scene, integrator, seed++, spp, width, height, max_depth);
        INFO(scene << " with " << integrator);
        REQUIRE(renders[integrator].invalid_samples == 0u);
    }
    for (std::size_t i = 0; i < integrators.size(); ++i) {
        for (std::size_t j = i + 1; j < integrators.size(); ++j) {
            const RenderResult& a = renders[integrators[i]];
            const RenderResult& b = renders[integrators[j]];
            for (const int block : block_sizes) {
                const stats::ImageTestResult test =
                    stats::blockwise_welch_test(a.image, a.variance, a.samples_per_pixel, b.image, b.variance,
                                                b.samples_per_pixel, block, stats::convergence_test_alpha);
                const std::string name = integrators[j] + "-agrees-with-" + integrators[i] + " " + scene + " blocks " +
                                         std::to_string(block);
                require_agreement(name, test, integrators[i], a, integrators[j], b);
            }
        }
    }
}

}  // namespace

TEST_CASE("a white diffuse sphere under a constant environment of radiance 1 is 1 everywhere with pt-is, pt-nee and "
          "pt-mis (emission counted twice by light and BSDF sampling would give 2)",
          "[convergence][ch03]") {
    // The closed form: albedo 1 and a convex object, so every path escapes with throughput 1 and
    // every pixel, sphere and background, is exactly 1. pt-is's samples are all exactly 1 (zero
    // variance: the test is deterministic and spends no false-failure budget); pt-nee's are
    // 4 cos(theta) for a uniformly sampled direction, pt-mis's a mixture: one one-sample image test
    // each, on 16x16 blocks at 256 spp and alpha / 10 (tests/STATISTICS.md, rule 2).
    //
    // Power: the per-sample standard deviation of pt-nee is 1.3 (4 cos theta over the sphere; pt-mis far less), so
    // a 16x16 block at 256 spp has a standard error below 0.005; a 3 % bias is more than 6
    // standard errors. Counting the environment twice (NEE and BSDF hits both weighted 1) gives 2 on the
    // sphere, forgetting it in NEE gives 0.
    const std::vector<std::pair<std::string, std::uint64_t>> cases = {{"pt-is", 401}, {"pt-nee", 402}, {"pt-mis", 403}};
    for (const auto& [integrator, seed] : cases) {
        const RenderResult result = render_scene("furnace/scene-environment.json", integrator, seed, 256);
        INFO(integrator);
        REQUIRE(result.invalid_samples == 0u);
        const stats::ImageTestResult test = stats::one_sample_image_test(
            result.image, result.variance, result.samples_per_pixel, Spectrum(1.0f), 16, stats::convergence_test_alpha / 10);
        if (!test.passed) {
            const std::string folder = stats::write_evidence("environment-furnace-" + integrator, test,
                                                             {{integrator, result.image}, {"variance", result.variance}});
            FAIL(integrator << ": " << test.message << "\nevidence: " << folder);
        }
        SUCCEED(integrator << ": " << test.message);
    }
}

namespace {

// The closed form of point-light/scene.json and spot.json: a diffuse floor (y = 0, albedo rho)
// lit by one delta light, nothing else. A sample that sees floor point x is exactly
// rho / pi * I(direction) cos(theta) / r^2 (pbrt-v3, section 12.2): the only path is
// camera -> floor -> light, and the light is chosen with probability 1.
struct DeltaLightOnFloor {
    Vec3 position;
    Spectrum intensity;
    Spectrum albedo;
    // Spot lights only: the axis and the cosines of the cone and of the falloff's start.
    std::optional<Vec3> axis;
    float cos_cone = -1.0f, cos_falloff_start = -1.0f;

    Spectrum radiance(const Vec3& x) const {
        const Vec3 to_light = position - x;
        const double r2 = glm::dot(to_light, to_light);
        const double cos_theta = to_light.y / std::sqrt(r2);
        double fraction = 1.0;
        if (axis) {
            const double cos_axis = glm::dot(-to_light / static_cast<float>(std::sqrt(r2)), glm::normalize(*axis));
            if (cos_axis <= cos_cone) fraction = 0.0;
            else if (cos_axis < cos_falloff_start) {
                const double t = (cos_axis - cos_cone) / (cos_falloff_start - cos_cone);
                fraction = t * t * (3.0 - 2.0 * t);  // smoothstep, as in pbrt-v4's SpotLight
            }
        }
        return albedo * static_cast<float>(InvPi * fraction * std::max(cos_theta, 0.0) / r2) * intensity;
    }
};

// Checks every pixel that sees only the floor against the range of the closed form over the
// pixel's footprint: each sample is the closed form at some point of the footprint, so the pixel's
// mean lies between its smallest and largest value there. Deterministic (no false failures); the
// range is taken on a 9x9 grid of the footprint and widened by the largest step between grid
// neighbours (a smooth function moves less than that between them) and by float rounding.
void check_floor_closed_form(const std::string& scene_file, const DeltaLightOnFloor& light,
                             const std::string& integrator, std::uint64_t seed) {
    SceneLoadOptions options;
    const Scene scene = load_scene(testing::scene_path(scene_file), testing::full_registry(), options);
    INFO(scene_file << " with " << integrator);
    CHECK(scene.warnings.empty());  // a scene with "lights" once warned that the key was unknown
    const RenderResult result = render_scene(scene_file, integrator, seed, 16);
    REQUIRE(result.invalid_samples == 0u);
    const int width = scene.camera->width(), height = scene.camera->height();
    constexpr int grid = 9;
    int tested = 0, lit = 0, failed = 0;
    std::ostringstream failures;
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            Spectrum values[grid][grid];
            bool on_floor = true;
            for (int j = 0; j < grid && on_floor; ++j) {
                for (int i = 0; i < grid && on_floor; ++i) {
                    const Ray ray = scene.camera->generate_ray(
                        Vec2(static_cast<float>(x) + static_cast<float>(i) / (grid - 1),
                             static_cast<float>(y) + static_cast<float>(j) / (grid - 1)));
                    const float t = -ray.origin.y / ray.direction.y;
                    const Vec3 p = ray.origin + t * ray.direction;
                    on_floor = t > 0.0f && std::abs(p.x) < 2.0f && std::abs(p.z) < 2.0f;
                    values[j][i] = light.radiance(p);
                }
            }
            if (!on_floor) continue;
            ++tested;
            for (int c = 0; c < 3; ++c) {
                double low = std::numeric_limits<double>::infinity(), high = -low, step = 0.0;
                for (int j = 0; j < grid; ++j) {
                    for (int i = 0; i < grid; ++i) {
                        low = std::min<double>(low, values[j][i][c]);
                        high = std::max<double>(high, values[j][i][c]);
                        if (i > 0) step = std::max<double>(step, std::abs(values[j][i][c] - values[j][i - 1][c]));
                        if (j > 0) step = std::max<double>(step, std::abs(values[j][i][c] - values[j - 1][i][c]));
                    }
                }
                const double slack = step + 1e-5 * high + 1e-9;
                const double mean = result.image.at(x, y)[c];
                if (high > 0.0) lit += c == 0 ? 1 : 0;
                if (mean < low - slack || mean > high + slack) {
                    if (++failed <= 5)
                        failures << "pixel (" << x << ", " << y << ") channel " << c << ": " << mean
                                 << ", the closed form ranges over [" << low << ", " << high << "] +- " << slack << "\n";
                }
            }
        }
    }
    INFO(tested << " floor pixels tested, " << lit << " lit; failures:\n" << failures.str());
    CHECK(tested > width * height / 2);
    CHECK(lit > 10);
    CHECK(failed == 0);
}

}  // namespace

TEST_CASE("a diffuse floor under a point light is rho / pi * I cos / r^2 with pt-nee and pt-mis (a missing cosine, "
          "1 / r instead of 1 / r^2 or a missing 1 / pi would not be)",
          "[convergence][ch03]") {
    DeltaLightOnFloor light;
    light.position = Vec3(0.3f, 1.0f, -0.2f);
    light.intensity = Spectrum(2.0f, 1.5f, 1.0f);
    light.albedo = Spectrum(0.8f, 0.5f, 0.3f);
    check_floor_closed_form("hard/point-light/scene.json", light, "pt-nee", 411);
    check_floor_closed_form("hard/point-light/scene.json", light, "pt-mis", 412);
}

TEST_CASE("a diffuse floor under a spot light follows the cone and its smoothstep falloff with pt-nee and pt-mis",
          "[convergence][ch03]") {
    DeltaLightOnFloor light;
    light.position = Vec3(-0.2f, 1.5f, 0.1f);
    light.intensity = Spectrum(1.0f, 2.0f, 3.0f);
    light.albedo = Spectrum(0.8f, 0.5f, 0.3f);
    light.axis = Vec3(0.5f, 0.0f, 0.3f) - light.position;
    light.cos_cone = std::cos(glm::radians(35.0f));
    light.cos_falloff_start = std::cos(glm::radians(20.0f));
    check_floor_closed_form("hard/point-light/spot.json", light, "pt-nee", 413);
    check_floor_closed_form("hard/point-light/spot.json", light, "pt-mis", 414);
}

TEST_CASE("pt-is, pt-nee and pt-mis agree on the Cornell box (a wrong area-to-solid-angle conversion, a light "
          "sample's emission counted twice or a wrong MIS weight would not)",
          "[convergence][ch03]") {
    // Three renders with independent seeds, every pair compared by Welch's t-test per channel over
    // the whole image (one 32x32 block: a global bias) and over 8x8 blocks (a local one), each at
    // 1e-5: 6 tests. The same depth (64 segments) for all, so they estimate the same image.
    //
    // Power: pt-is at 1024 spp has a whole-image relative standard error below 0.7 % (pt-naive's
    // at 1024 spp, test_importance_sampling.cpp; pt-is is less noisy), pt-nee and pt-mis far
    // less: a bias of 3 % is over 4.4 standard errors of the difference. Counting the light's
    // emission twice after a diffuse bounce adds about a third of the direct light.
    require_pairwise_agreement("cornell-box/scene.json", {"pt-is", "pt-nee", "pt-mis"}, 421, 1024, 32, 32, 64, {32, 8});
}

TEST_CASE("pt-is and pt-mis agree on veach-mis (small bright lights in glossy plates)", "[convergence][ch03]") {
    // Veach's scene at 96x64, 1024 spp, paths of at most 8 segments (the plates, the lights and a
    // bounce or two off the dark backdrop), compared over 16x16 blocks (24 blocks x 3 channels,
    // Sidak-corrected): 1 test at 1e-5. A block holds 262144 samples; pt-is's rare large ones
    // (a rough plate's sample hitting the smallest light, about 1 in 1000) number hundreds per
    // block, so its mean is close to normal, the t-test's assumption.
    //
    // pt-nee is not compared here: on the smoothest plate it finds the largest light by light
    // samples landing in a lobe of a few 1e-4 sr, about once in 2000 samples, each weighing
    // thousands of times the mean. Such a block's sample variance is underestimated and the
    // t-test fails a correct pt-nee (measured at 2048 spp: blocks 2.5 times pt-mis's). That is
    // the failure MIS was invented for; pt-nee is compared with pt-mis on the Cornell boxes above
    // and below, where its samples are bounded.
    require_pairwise_agreement("veach-mis/scene.json", {"pt-is", "pt-mis"}, 431, 1024, 96, 64, 8, {16});
}

TEST_CASE("pt-nee and pt-mis agree on the Cornell box with a point light and a spot light", "[convergence][ch03]") {
    // Delta lights are found by light sampling only (weight 1 in both); the area light is
    // weighted differently by the two. Whole image and 8x8 blocks: 2 tests at 1e-5.
    require_pairwise_agreement("cornell-box/point-and-spot.json", {"pt-nee", "pt-mis"}, 441, 256, 32, 32, 64, {32, 8});
}

// Chapter 10's light BVH (`--light-sampler bvh`) chooses lights by what they can send to each
// shading point; its probabilities enter the light samples and the MIS weights of emission found
// by BSDF sampling, so a wrong probability anywhere is a bias these comparisons see.

TEST_CASE("pt-mis with the light BVH agrees with pt-is on the Cornell box and on veach-mis", "[convergence][ch10]") {
    // As the chapter 03 tests above: the Cornell box over 8x8 blocks, veach-mis over 16x16
    // blocks: 2 tests at convergence_test_alpha.
    require_pairwise_agreement("cornell-box/scene.json", {"pt-is", "pt-mis@bvh"}, 451, 1024, 32, 32, 64, {8});
    require_pairwise_agreement("veach-mis/scene.json", {"pt-is", "pt-mis@bvh"}, 461, 1024, 96, 64, 8, {16});
}

TEST_CASE("pt-nee with the light BVH agrees with pt-mis on the Cornell box with a point light and a spot light",
          "[convergence][ch10]") {
    // Delta lights are found by light sampling alone, so the BVH's cones and bounds for point and
    // spot lights decide the image: 8x8 blocks, 1 test at convergence_test_alpha.
    require_pairwise_agreement("cornell-box/point-and-spot.json", {"pt-mis", "pt-nee@bvh"}, 471, 256, 32, 32, 64, {8});
}

TEST_CASE("pt-mis with the light BVH agrees with pt-mis choosing by power on a hall of 1,536 lamps", "[convergence][ch10]") {
    // scenes/many-lights at 32x32, 512 spp, paths of at most 4 segments, 8x8 blocks: 1 test at
    // convergence_test_alpha. Every pixel is lit by lamps a few metres away, which the BVH
    // chooses far more often than power does: a probability wrong for nearby or far lamps would
    // shift these blocks.
    require_pairwise_agreement("many-lights/scene.json", {"pt-mis", "pt-mis@bvh"}, 481, 512, 32, 32, 4, {8});
}
