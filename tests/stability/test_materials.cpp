// Hard materials in scenes (scenes/hard/): the roughness limit, index-matched glass, total
// internal reflection seen from inside a glass block, white diffuse of albedo exactly 1 in a
// closed room. (The white furnace with every material is in test_furnace.cpp.)
#include "stability_support.hpp"

#include "test_scenes.hpp"

#include <catch2/catch.hpp>

#include <cstring>

using namespace freezeray;
using namespace freezeray::stability;

namespace {

bool bit_identical(const Image& a, const Image& b) {
    return a.pixel_count() == b.pixel_count() &&
           std::memcmp(a.pixels().data(), b.pixels().data(), a.pixel_count() * sizeof(Spectrum)) == 0;
}

RenderResult render_pt_is(const std::string& scene, std::uint64_t seed, std::uint64_t spp = 64) {
    HardRender request;
    request.scene = scene;
    request.samples_per_pixel = spp;
    request.seed = seed;
    return render(request);
}

void require_agreement(const RenderResult& a, const RenderResult& b, double tolerance, const std::string& name) {
    const EnergyTestResult test = agreement_test(a, b, tolerance, 8, stability_test_alpha);
    INFO(name);
    if (!test.passed) FAIL(test.message << "\nevidence: " << write_evidence(name, test.message, {{"a", &a}, {"b", &b}}));
    SUCCEED(test.message);
}

// Every case of a folder is also rendered by pt-naive, which must give valid samples.
void check_valid_with_every_integrator(const std::string& scene) {
    for (const std::string& integrator : all_integrators()) {
        HardRender request;
        request.scene = scene;
        request.integrator = integrator;
        request.samples_per_pixel = 16;
        request.seed = 70;
        check_valid(render(request), scene + " with " + integrator);
    }
}

}  // namespace

TEST_CASE("GGX roughness 0 and 1e-4 render exactly as the smooth material, 0.0317 within 1 % of it",
          "[stability][roughness]") {
    struct Family {
        std::string smooth;
        std::vector<std::string> same;         // must be bit-identical with the same seed
        std::vector<std::string> approaching;  // must agree within 1 % (independent seeds)
    };
    const Family families[] = {
        {"roughness-limit/scene.json",
         {"roughness-limit/conductor-roughness-0.json", "roughness-limit/conductor-roughness-1e-4.json"},
         {"roughness-limit/conductor-roughness-0.0317.json", "roughness-limit/conductor-anisotropic.json"}},
        {"roughness-limit/dielectric.json",
         {"roughness-limit/dielectric-roughness-0.json", "roughness-limit/dielectric-roughness-1e-4.json"},
         {"roughness-limit/dielectric-roughness-0.0317.json"}},
    };
    std::uint64_t seed = 80;
    for (const Family& family : families) {
        const RenderResult smooth = render_pt_is(family.smooth, 1000, 256);
        check_valid(smooth, family.smooth);
        for (const std::string& file : family.same) {
            const RenderResult same = render_pt_is(file, 1000, 256);
            check_valid(same, file);
            INFO(file << " against " << family.smooth);
            CHECK(bit_identical(same.image, smooth.image));
        }
        for (const std::string& file : family.approaching) {
            const RenderResult rough = render_pt_is(file, seed++, 256);
            check_valid(rough, file);
            require_agreement(rough, smooth, 0.01, file + " approaches " + family.smooth);
        }
        for (const std::string& file : family.approaching) check_valid_with_every_integrator(file);
        check_valid_with_every_integrator(family.smooth);
    }
}

TEST_CASE("an index-matched glass sphere (eta 1) vanishes from the Cornell box", "[stability][index-matched]") {
    testing::TestRender empty_request;
    empty_request.scene = testing::scene_path("cornell-box/scene.json");
    empty_request.integrator = "pt-is";
    empty_request.width = empty_request.height = 32;
    empty_request.samples_per_pixel = 256;
    empty_request.seed = 90;
    empty_request.threads = 1;
    const RenderResult empty = testing::render(empty_request);
    std::uint64_t seed = 91;
    for (const std::string& file : {std::string("index-matched/scene.json"), std::string("index-matched/rough.json")}) {
        HardRender request;
        request.scene = file;
        request.size = 32;
        request.samples_per_pixel = 256;
        request.seed = seed++;
        const RenderResult matched = render(request);
        check_valid(matched, file);
        require_agreement(matched, empty, 0.0, file + " against the empty Cornell box");
        check_valid_with_every_integrator(file);
    }
}

TEST_CASE("inside a glass block, escaping directions see 1.5^2 and trapped ones 0", "[stability][tir]") {
    // The camera is at the centre of the cube; a pixel's ray (x, y, 1) escapes iff x^2 + y^2 < 0.8
    // (scenes/hard/glass-block/scene.json). Pixels all of whose 5 x 5 sub-rays have x^2 + y^2 < 0.6
    // are 2.25 within their statistical error (the margin keeps the critical angle, where internal
    // reflection approaches 1 and paths grow long, away); pixels all of whose sub-rays have
    // x^2 + y^2 > 1 are 0 (each path reflects totally until Russian roulette ends it).
    const Scene scene = load("glass-block/scene.json");
    const Camera& camera = *scene.camera;
    PixelGroup escaping{"escaping pixels", {}};
    std::vector<std::size_t> trapped;
    const float offsets[5] = {0.0f, 0.25f, 0.5f, 0.75f, 0.9999f};
    for (int y = 0; y < camera.height(); ++y) {
        for (int x = 0; x < camera.width(); ++x) {
            float smallest = 1e30f, largest = 0.0f;
            for (const float dy : offsets) {
                for (const float dx : offsets) {
                    const Vec3 d = camera.generate_ray(Vec2(x + dx, y + dy)).direction;
                    const float r2 = (d.x * d.x + d.y * d.y) / (d.z * d.z);
                    smallest = std::min(smallest, r2);
                    largest = std::max(largest, r2);
                }
            }
            const std::size_t i = static_cast<std::size_t>(y) * camera.width() + x;
            if (largest < 0.6f) escaping.pixels.push_back(i);
            if (smallest > 1.0f) trapped.push_back(i);
        }
    }
    REQUIRE(escaping.pixels.size() > 100u);
    REQUIRE(trapped.size() > 100u);

    const RenderResult result = render_pt_is("glass-block/scene.json", 100);
    check_valid(result, "glass-block with pt-is");
    const EnergyTestResult test = energy_test(result, 2.25, Expectation::Equal, 0, {escaping}, one_sample_stability_alpha);
    if (!test.passed)
        FAIL(test.message << "\nevidence: " << write_evidence("glass-block", test.message, {{"pt-is", &result}}));
    SUCCEED(test.message);
    // Trapped: every path reflects totally until Russian roulette ends it, and contributes 0, but
    // for the rare one that reflects within ~1e-5 of an edge: the conservative t of the
    // intersection test (triangle_intersection.cpp) then rejects its true hit on the adjacent face
    // and it leaks out (about 2e-6 of the bounces; 2 of the 10752 samples here). That is the price
    // of never hitting the triangle a ray leaves; more than 1e-3 on average would be a real leak.
    double leaked = 0.0;
    for (const std::size_t i : trapped) leaked += max_component(result.image[i]);
    leaked /= static_cast<double>(trapped.size());
    INFO("trapped pixels average " << leaked);
    CHECK(leaked < 1e-3);
    check_valid_with_every_integrator("glass-block/scene.json");
}

TEST_CASE("white diffuse of albedo exactly 1 in a closed room collects Le at every one of D segments",
          "[stability][albedo-1]") {
    // Le = 0.25 everywhere, albedo 1, no escape: a path of at most D segments has expectation
    // exactly D Le, for any sampling. pt-is at D = 16 (Russian roulette with throughput 1 all the
    // way), pt-naive at D = 4 (its weights 2 cos theta multiply: the deeper, the more skewed).
    const struct {
        std::string integrator;
        int depth;
        std::uint64_t seed;
    } runs[] = {{"pt-is", 16, 110}, {"pt-naive", 4, 111}};
    for (const auto& run : runs) {
        HardRender request;
        request.scene = "white-diffuse/scene.json";
        request.integrator = run.integrator;
        request.max_depth = run.depth;
        request.samples_per_pixel = 64;
        request.seed = run.seed;
        const RenderResult result = render(request);
        check_valid(result, "white-diffuse with " + run.integrator);
        const EnergyTestResult test =
            energy_test(result, 0.25 * run.depth, Expectation::Equal, 16, {}, one_sample_stability_alpha);
        INFO(run.integrator << " at maximum depth " << run.depth);
        if (!test.passed)
            FAIL(test.message << "\nevidence: "
                              << write_evidence("white-diffuse " + run.integrator, test.message, {{run.integrator, &result}}));
        SUCCEED(test.message);
    }
    // The integrators' own default depths (pt-is 64, pt-naive 10): large but finite values.
    check_valid_with_every_integrator("white-diffuse/scene.json");
}
