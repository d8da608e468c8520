// Hard lights (scenes/hard/): zero-power lights of every kind, lights on and touching surfaces,
// tiny emissive triangles, an environment with black rows and a one-pixel sun, and the classic
// white furnace (a constant environment) around every lossless material.
#include "stability_support.hpp"

#include <catch2/catch.hpp>

#include "freezeray/image.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

using namespace freezeray;
using namespace freezeray::stability;

TEST_CASE("a zero-emission light leaves the scene exactly black", "[stability][lights]") {
    const Scene scene = load("zero-emission/scene.json");
    CHECK(scene.emissive_triangles.empty());
    CHECK_FALSE(scene.effects.area_emitters);
    for (const std::string& integrator : all_integrators()) {
        HardRender request;
        request.scene = "zero-emission/scene.json";
        request.integrator = integrator;
        request.size = 32;
        request.samples_per_pixel = 16;
        request.seed = 120;
        const RenderResult result = render(request);
        check_valid(result, "zero-emission with " + integrator);
        std::size_t lit = 0;
        for (const Spectrum& p : result.image.pixels()) lit += is_black(p) ? 0 : 1;
        for (const Spectrum& v : result.variance.pixels()) lit += is_black(v) ? 0 : 1;
        INFO(integrator << ": " << lit << " pixels or variances are not zero");
        CHECK(lit == 0u);
    }
}

TEST_CASE("area lights touching walls, coplanar with the ceiling and standing on the floor give valid samples",
          "[stability][lights]") {
    for (const std::string& integrator : all_integrators()) {
        HardRender request;
        request.scene = "light-touching-wall/scene.json";
        request.integrator = integrator;
        request.samples_per_pixel = 64;
        request.seed = 121;
        const RenderResult result = render(request);
        check_valid(result, "light-touching-wall with " + integrator);
        double sum = 0.0;
        for (const Spectrum& p : result.image.pixels()) sum += luminance(p);
        CHECK(sum > 0.0);
    }
}

// --- Chapter 03: lights sampled directly -----------------------------------------------------------

namespace {

// Every integrator renders the case at the same seed as the reference; the images and variances
// must be bit-identical.
void check_identical_to(const std::string& scene, const std::string& reference, std::uint64_t seed) {
    for (const std::string& integrator : all_integrators()) {
        HardRender request;
        request.integrator = integrator;
        request.samples_per_pixel = 16;
        request.seed = seed;
        request.size = 32;  // the reference is the course's 256x256 Cornell box
        request.scene = scene;
        const RenderResult result = render(request);
        request.scene = reference;
        const RenderResult expected = render(request);
        check_valid(result, scene + " with " + integrator);
        REQUIRE(result.image.pixel_count() == expected.image.pixel_count());
        std::size_t different = 0;
        for (std::size_t i = 0; i < result.image.pixel_count(); ++i) {
            different += result.image[i] != expected.image[i] ? 1 : 0;
            different += result.variance[i] != expected.variance[i] ? 1 : 0;
        }
        INFO(scene << " with " << integrator << ": " << different << " pixels or variances differ from " << reference);
        CHECK(different == 0u);
    }
}

void check_black(const std::string& scene, std::uint64_t seed) {
    for (const std::string& integrator : all_integrators()) {
        HardRender request;
        request.scene = scene;
        request.integrator = integrator;
        request.samples_per_pixel = 16;
        request.seed = seed;
        const RenderResult result = render(request);
        check_valid(result, scene + " with " + integrator);
        std::size_t lit = 0;
        for (const Spectrum& p : result.image.pixels()) lit += is_black(p) ? 0 : 1;
        for (const Spectrum& v : result.variance.pixels()) lit += is_black(v) ? 0 : 1;
        INFO(scene << " with " << integrator << ": " << lit << " pixels or variances are not zero");
        CHECK(lit == 0u);
    }
}

// Two renders of a case with independent seeds agree (Welch over 8x8 blocks, at the stability
// label's two-sample level: one test).
void check_agreement(const std::string& scene, const std::string& a_name, const std::string& b_name,
                     std::uint64_t spp, std::uint64_t seed) {
    HardRender request;
    request.scene = scene;
    request.samples_per_pixel = spp;
    request.integrator = a_name;
    request.seed = seed;
    const RenderResult a = render(request);
    request.integrator = b_name;
    request.seed = seed + 1;
    const RenderResult b = render(request);
    check_valid(a, scene + " with " + a_name);
    check_valid(b, scene + " with " + b_name);
    const EnergyTestResult test = agreement_test(a, b, 0.0, 8, stability_test_alpha);
    INFO(scene << ": " << b_name << " against " << a_name);
    if (!test.passed)
        FAIL(test.message << "\nevidence: "
                          << write_evidence(scene + " " + a_name + " " + b_name, test.message, {{a_name, &a}, {b_name, &b}}));
    SUCCEED(test.message);
}

// A light's samples from `reference` over a grid of u: nothing, or a finite positive density,
// finite non-negative radiance and a unit direction whose own density is finite.
std::size_t check_light_samples(const Light& light, const Vec3& reference, const std::string& what) {
    std::size_t returned = 0, bad = 0;
    constexpr int n = 32;
    for (int j = 0; j < n; ++j) {
        for (int i = 0; i < n; ++i) {
            const Vec2 u((static_cast<float>(i) + 0.5f) / n, (static_cast<float>(j) + 0.5f) / n);
            const std::optional<LightSample> s = light.sample_li(reference, u);
            if (!s) continue;
            ++returned;
            const float pdf_back = light.pdf_li(reference, s->wi);
            const bool ok = std::isfinite(s->pdf) && s->pdf > 0.0f && is_valid_radiance(s->radiance) &&
                            std::abs(glm::length(s->wi) - 1.0f) < 1e-4f &&
                            std::isfinite(pdf_back) && pdf_back >= 0.0f;
            bad += ok ? 0 : 1;
        }
    }
    INFO(what << ": " << bad << " of " << returned << " samples have a non-finite or non-positive density or radiance");
    CHECK(bad == 0u);
    CHECK(is_valid_radiance(light.power()));
    return returned;
}

}  // namespace

TEST_CASE("zero-power point, spot, directional and environment lights change nothing", "[stability][lights][ch03]") {
    check_identical_to("zero-power/scene.json", "zero-power/../../cornell-box/scene.json", 122);
    check_identical_to("zero-power/environment-map.json", "zero-power/../../cornell-box/scene.json", 123);
}

TEST_CASE("a scene whose only light has zero power is exactly black", "[stability][lights][ch03]") {
    // Light selection by power over a total of 0 falls back to uniform; the light sends nothing.
    check_black("zero-power/only-light.json", 124);
    check_black("zero-power/only-environment.json", 125);
    // And no light at all: the zero-emission Cornell box above, now also with pt-nee and pt-mis.
}

TEST_CASE("point and spot lights lying on surfaces give valid samples, and pt-nee agrees with pt-mis",
          "[stability][lights][ch03]") {
    const Scene scene = load("point-light/on-surface.json");
    CHECK(scene.warnings.empty());
    for (const std::string& integrator : all_integrators()) {
        HardRender request;
        request.scene = "point-light/on-surface.json";
        request.integrator = integrator;
        request.samples_per_pixel = 64;
        request.seed = 126;
        const RenderResult result = render(request);
        check_valid(result, "point-light/on-surface with " + integrator);
        if (integrator == "pt-nee" || integrator == "pt-mis") {
            double sum = 0.0;
            for (const Spectrum& p : result.image.pixels()) sum += luminance(p);
            CHECK(sum > 0.0);
        }
    }
    // The point light on the floor at the origin, seen from the origin (distance 0): no direction,
    // nothing sent; from 1e-30 away, I / r^2 overflows: nothing either, or a valid radiance.
    REQUIRE(scene.lights.size() == 4u);
    CHECK_FALSE(scene.lights[0]->sample_li(Vec3(0.0f), Vec2(0.5f)).has_value());
    const std::optional<LightSample> close = scene.lights[0]->sample_li(Vec3(1e-30f, 0.0f, 0.0f), Vec2(0.5f));
    CHECK((!close || is_valid_radiance(close->radiance)));
    check_agreement("point-light/on-surface.json", "pt-nee", "pt-mis", 256, 127);
}

TEST_CASE("an area light touching a wall, sampled by next-event estimation, agrees with BSDF sampling",
          "[stability][lights][ch03]") {
    // Shadow rays to the shelf light end at distance 0 from the back wall; a shadow ray that
    // wrongly found the wall would darken the room for pt-nee and pt-mis, not for pt-is. The
    // light lying in the ceiling's plane is dark here: on it pt-is sees half of what light
    // sampling sees (rounding decides between the coplanar surfaces; measured 0.072 against 0.145).
    check_agreement("light-touching-wall/touching.json", "pt-is", "pt-nee", 512, 128);
    check_agreement("light-touching-wall/touching.json", "pt-is", "pt-mis", 512, 130);
}

TEST_CASE("tiny and degenerate emissive triangles give finite light samples and valid images",
          "[stability][lights][ch03]") {
    const Scene scene = load("tiny-emitters/scene.json");
    REQUIRE(scene.warnings.size() == 1u);
    CHECK(scene.warnings[0].find("dropped 2 degenerate triangles") != std::string::npos);
    CHECK(scene.lights.size() == 5u);  // the ceiling light's 2 triangles, bright, denormal and needle
    std::size_t returned = 0;
    for (const auto& light : scene.lights)
        for (const Vec3& reference : {Vec3(0.0f, 0.0f, -1.5f), Vec3(0.0f, -2.0f, 0.5f), Vec3(1e-10f, 1e-10f, -1e-9f)})
            returned += check_light_samples(*light, reference, light->where);
    CHECK(returned > 0u);
    for (const std::string& integrator : all_integrators()) {
        HardRender request;
        request.scene = "tiny-emitters/scene.json";
        request.integrator = integrator;
        request.samples_per_pixel = 32;
        request.seed = 132;
        check_valid(render(request), "tiny-emitters with " + integrator);
    }
    check_agreement("tiny-emitters/scene.json", "pt-nee", "pt-mis", 256, 133);
}

// --- The classic white furnace: a constant environment of radiance 1 -------------------------------

namespace {

// Every pixel of a lossless object under a constant environment of radiance 1 is exactly 1: every
// 16x16 block, the silhouette and the object pixels, for each integrator that can see the object's
// lobes (one one-sample test each); every integrator must be valid.
void run_environment_furnace(const std::string& scene_file, const std::vector<std::string>& energy_tested,
                             std::uint64_t seed) {
    const Scene scene = load(scene_file);
    REQUIRE(scene.environment != nullptr);
    const std::vector<int> coverage = pixel_coverage(scene);
    const std::vector<PixelGroup> groups = {{"silhouette pixels", pixels_where(coverage, Mixed)},
                                            {"object pixels", pixels_where(coverage, 0)}};
    REQUIRE(groups[0].pixels.size() > 20u);
    for (const std::string& integrator : all_integrators()) {
        HardRender request;
        request.scene = scene_file;
        request.integrator = integrator;
        request.samples_per_pixel = 128;
        request.seed = seed++;
        const RenderResult result = render(request);
        check_valid(result, scene_file + " with " + integrator);
        if (std::find(energy_tested.begin(), energy_tested.end(), integrator) == energy_tested.end()) continue;
        const EnergyTestResult test = energy_test(result, 1.0, Expectation::Equal, 16, groups, one_sample_stability_alpha);
        INFO(scene_file << " with " << integrator);
        if (!test.passed)
            FAIL(test.message << "\nevidence: "
                              << write_evidence("environment furnace " + scene_file + " " + integrator, test.message,
                                                {{integrator, &result}}));
        SUCCEED(test.message);
    }
}

const std::vector<std::string> sampling_integrators = {"pt-is", "pt-nee", "pt-mis"};

}  // namespace

TEST_CASE("environment furnace: white diffuse (albedo 1) is 1 at every pixel", "[stability][furnace][lights][ch03]") {
    run_environment_furnace("environment-furnace/diffuse.json", {"pt-naive", "pt-is", "pt-nee", "pt-mis"}, 140);
}

TEST_CASE("environment furnace: a mirror of reflectance 1 is 1 at every pixel", "[stability][furnace][lights][ch03]") {
    run_environment_furnace("environment-furnace/mirror.json", sampling_integrators, 144);
}

TEST_CASE("environment furnace: smooth glass of index 1.5 is 1 at every pixel", "[stability][furnace][lights][ch03]") {
    run_environment_furnace("environment-furnace/dielectric.json", sampling_integrators, 148);
}

TEST_CASE("environment furnace: smooth glass of index 0.67 is 1 at every pixel", "[stability][furnace][lights][ch03]") {
    run_environment_furnace("environment-furnace/dielectric-ior-0.67.json", sampling_integrators, 152);
}

TEST_CASE("environment furnace: index-matched smooth glass is 1 at every pixel", "[stability][furnace][lights][ch03]") {
    run_environment_furnace("environment-furnace/dielectric-index-matched.json", sampling_integrators, 156);
}

TEST_CASE("environment furnace: index-matched rough glass is 1 at every pixel", "[stability][furnace][lights][ch03]") {
    run_environment_furnace("environment-furnace/rough-dielectric-index-matched.json", sampling_integrators, 160);
}

TEST_CASE("environment furnace: smooth plastic with a white base is 1 at every pixel", "[stability][furnace][lights][ch03]") {
    run_environment_furnace("environment-furnace/plastic.json", sampling_integrators, 164);
}

TEST_CASE("environment furnace: a mix of white diffuse and mirror is 1 at every pixel", "[stability][furnace][lights][ch03]") {
    run_environment_furnace("environment-furnace/mix.json", sampling_integrators, 168);
}

TEST_CASE("environment furnace: a glass cube is 1 at every pixel", "[stability][furnace][lights][ch03]") {
    run_environment_furnace("environment-furnace/glass-cube.json", sampling_integrators, 172);
}

// --- An environment with black rows and a one-pixel sun --------------------------------------------

TEST_CASE("an environment with black rows and a one-pixel sun: samples avoid the black rows, the floor is rho / pi "
          "times the map's irradiance",
          "[stability][lights][ch03]") {
    const Scene scene = load("sun-environment/scene.json");
    REQUIRE(scene.environment != nullptr);
    const Light& sky = *scene.environment;

    // The exact irradiance of an up-facing floor: the map is piecewise constant (nearest pixel), so
    // pixel (x, y) of the upper half contributes L (2 pi / W) (sin^2 theta1 - sin^2 theta0) / 2.
    const Image map = read_image(hard_scene("sun-environment/sun.pfm"));
    const int width = map.width(), height = map.height();
    double irradiance_d[3] = {0.0, 0.0, 0.0};
    for (int y = 0; y < height / 2; ++y) {
        const double s0 = std::sin(Pi * y / static_cast<double>(height)), s1 = std::sin(Pi * (y + 1) / static_cast<double>(height));
        const double cell = (2.0 * Pi / width) * (s1 * s1 - s0 * s0) / 2.0;
        for (int x = 0; x < width; ++x)
            for (int c = 0; c < 3; ++c) irradiance_d[c] += map.at(x, y)[c] * cell;
    }

    // Light samples: never in a black row (radiance 0 there), always of finite positive density,
    // and the density of a black row's direction is 0.
    std::size_t black = 0, bad = 0, sun = 0;
    constexpr int n = 200;
    for (int j = 0; j < n; ++j) {
        for (int i = 0; i < n; ++i) {
            const Vec2 u((static_cast<float>(i) + 0.5f) / n, (static_cast<float>(j) + 0.5f) / n);
            const std::optional<LightSample> s = sky.sample_li(Vec3(0.0f), u);
            if (!s || !(s->pdf > 0.0f) || !std::isfinite(s->pdf) || !is_valid_radiance(s->radiance)) {
                ++bad;
                continue;
            }
            black += is_black(s->radiance) ? 1 : 0;
            sun += s->radiance.r > 1e5f ? 1 : 0;
        }
    }
    INFO(bad << " invalid samples, " << black << " in black rows, " << sun << " on the sun, of " << n * n);
    CHECK(bad == 0u);
    CHECK(black == 0u);
    CHECK(sun > static_cast<std::size_t>(n * n * 9 / 10));  // the sun holds 99.9 % of the sampling weight
    CHECK(sky.pdf_li(Vec3(0.0f), Vec3(0.0f, 1.0f, 0.0f)) == 0.0f);    // the zenith: a black row
    CHECK(sky.pdf_li(Vec3(0.0f), Vec3(0.0f, -1.0f, 0.0f)) == 0.0f);   // the nadir
    CHECK(sky.pdf_li(Vec3(0.0f), glm::normalize(Vec3(1.0f, -0.3f, 0.2f))) == 0.0f);  // the black ground

    // The floor fills the image; each pixel is rho / pi E (one-sample tests over 16x16 blocks,
    // pt-nee and pt-mis; pt-naive and pt-is find the one-pixel sun too rarely for a t-test: valid only).
    const std::vector<int> coverage = pixel_coverage(scene);
    REQUIRE(pixels_where(coverage, 0).size() == coverage.size());
    const double expected = 0.5 / Pi * irradiance_d[0];
    std::uint64_t seed = 180;
    for (const std::string& integrator : all_integrators()) {
        HardRender request;
        request.scene = "sun-environment/scene.json";
        request.integrator = integrator;
        request.samples_per_pixel = 64;
        request.seed = seed++;
        const RenderResult result = render(request);
        check_valid(result, "sun-environment with " + integrator);
        if (integrator != "pt-nee" && integrator != "pt-mis") continue;
        // The map is grey but for the sky's tint: test the red channel's value on all three by
        // rescaling green and blue to red's expectation.
        RenderResult scaled = result;
        for (std::size_t i = 0; i < scaled.image.pixel_count(); ++i) {
            for (int c = 1; c < 3; ++c) {
                const float k = static_cast<float>(irradiance_d[0] / irradiance_d[c]);
                scaled.image[i][c] *= k;
                scaled.variance[i][c] *= k * k;
            }
        }
        const EnergyTestResult test = energy_test(scaled, expected, Expectation::Equal, 16, {}, one_sample_stability_alpha);
        INFO("sun-environment with " << integrator << ", expected " << expected);
        if (!test.passed)
            FAIL(test.message << "\nevidence: " << write_evidence("sun-environment " + integrator, test.message, {{integrator, &result}}));
        SUCCEED(test.message);
    }
}

// --- Chapter 04: the scenes of bidirectional methods ----------------------------------------------

TEST_CASE("the lamp behind a shade and the glass sphere's caustic give valid, lit images with every integrator",
          "[stability][lights][ch04]") {
    // A bulb seen only through a shade's opening (light reaching the room after a bounce) and a
    // small light focused through smooth glass: paths rarely found from the camera side.
    for (const char* scene : {"../cornell-lamp/scene.json", "../caustic/scene.json"}) {
        for (const std::string& integrator : all_integrators()) {
            HardRender request;
            request.scene = scene;
            request.integrator = integrator;
            request.size = 32;
            request.samples_per_pixel = 16;
            request.seed = 141;
            const RenderResult result = render(request);
            check_valid(result, std::string(scene) + " with " + integrator);
            std::size_t lit = 0;
            for (const Spectrum& p : result.image.pixels()) lit += is_black(p) ? 0 : 1;
            INFO(scene << " with " << integrator << ": " << lit << " lit pixels");
            CHECK(lit > 0u);
        }
    }
}
