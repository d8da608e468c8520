// The white furnace with every material (scenes/hard/white-furnace, conductor-k0, flipped-normals):
// a closed black enclosure emitting radiance 1 around one object. An object that absorbs nothing
// leaves every pixel at exactly 1, the silhouette's grazing pixels included; one that absorbs
// (single-scattering microfacet models, conductors) leaves every pixel at most 1.
#include "stability_support.hpp"

#include <catch2/catch.hpp>

#include <algorithm>

using namespace freezeray;
using namespace freezeray::stability;

namespace {

struct FurnaceCase {
    std::string scene;                     // under scenes/hard/
    Expectation expectation;
    std::vector<std::string> energy_tested;  // integrators whose image must meet the expectation
    std::uint64_t seed;
};

// Renders the case with every integrator: each must be valid; those that can see the object's
// lobes must meet the expectation on every 16x16 block, on the silhouette pixels (seeing both the
// object and the enclosure) and on the pixels seeing only the object.
void run_furnace(const FurnaceCase& c) {
    const Scene scene = load(c.scene);
    const std::vector<int> coverage = pixel_coverage(scene);
    const std::vector<PixelGroup> groups = {{"silhouette pixels", pixels_where(coverage, Mixed)},
                                            {"object pixels", pixels_where(coverage, 1)}};
    REQUIRE(groups[0].pixels.size() > 20u);  // the case really has a silhouette to test
    for (const std::string& integrator : all_integrators()) {
        HardRender request;
        request.scene = c.scene;
        request.integrator = integrator;
        request.samples_per_pixel = 256;
        request.seed = c.seed;
        const RenderResult result = render(request);
        check_valid(result, c.scene + " with " + integrator);
        if (std::find(c.energy_tested.begin(), c.energy_tested.end(), integrator) == c.energy_tested.end()) continue;
        const EnergyTestResult test =
            energy_test(result, 1.0, c.expectation, 16, groups, one_sample_stability_alpha);
        INFO(c.scene << " with " << integrator);
        if (!test.passed)
            FAIL(test.message << "\nevidence: "
                              << write_evidence("furnace " + c.scene + " " + integrator, test.message, {{integrator, &result}}));
        SUCCEED(test.message);
    }
}

const std::vector<std::string> both = {"pt-naive", "pt-is"};
const std::vector<std::string> pt_is = {"pt-is"};

}  // namespace

// --- Materials that absorb nothing: exactly 1 -------------------------------------------------------

TEST_CASE("white furnace: white diffuse (albedo 1) is 1 at every pixel", "[stability][furnace]") {
    run_furnace({"white-furnace/scene.json", Expectation::Equal, both, 11});
}

TEST_CASE("white furnace: a mirror of reflectance 1 is 1 at every pixel", "[stability][furnace]") {
    run_furnace({"white-furnace/mirror.json", Expectation::Equal, pt_is, 12});
}

TEST_CASE("white furnace: smooth glass of index 1.5 is 1 at every pixel", "[stability][furnace]") {
    run_furnace({"white-furnace/dielectric.json", Expectation::Equal, pt_is, 13});
}

TEST_CASE("white furnace: smooth glass of index 0.67 is 1 at every pixel", "[stability][furnace]") {
    run_furnace({"white-furnace/dielectric-ior-0.67.json", Expectation::Equal, pt_is, 14});
}

TEST_CASE("white furnace: index-matched smooth glass (eta 1) is 1 at every pixel", "[stability][furnace]") {
    run_furnace({"white-furnace/dielectric-index-matched.json", Expectation::Equal, pt_is, 15});
}

TEST_CASE("white furnace: index-matched rough glass (eta 1) is 1 at every pixel", "[stability][furnace]") {
    run_furnace({"white-furnace/rough-dielectric-index-matched.json", Expectation::Equal, pt_is, 16});
}

TEST_CASE("white furnace: smooth plastic with a white base is 1 at every pixel", "[stability][furnace]") {
    run_furnace({"white-furnace/plastic.json", Expectation::Equal, pt_is, 17});
}

TEST_CASE("white furnace: a mix of white diffuse and mirror is 1 at every pixel", "[stability][furnace]") {
    run_furnace({"white-furnace/mix.json", Expectation::Equal, pt_is, 18});
}

TEST_CASE("white furnace: a glass cube (total internal reflection inside) is 1 at every pixel", "[stability][furnace]") {
    run_furnace({"white-furnace/glass-cube.json", Expectation::Equal, pt_is, 19});
}

TEST_CASE("white furnace: vertex normals opposite the geometric normal change nothing", "[stability][furnace][geometry]") {
    run_furnace({"flipped-normals/scene.json", Expectation::Equal, both, 20});
}

// --- Materials that absorb: at most 1 --------------------------------------------------------------

TEST_CASE("white furnace: a rough conductor of roughness 0.3 reflecting 100 % is at most 1", "[stability][furnace]") {
    run_furnace({"white-furnace/rough-conductor.json", Expectation::AtMost, both, 21});
}

TEST_CASE("white furnace: a rough conductor of roughness 1 reflecting 100 % is at most 1", "[stability][furnace]") {
    run_furnace({"white-furnace/rough-conductor-1.json", Expectation::AtMost, both, 22});
}

TEST_CASE("white furnace: rough glass of roughness 0.3 is at most 1", "[stability][furnace]") {
    run_furnace({"white-furnace/rough-dielectric.json", Expectation::AtMost, both, 23});
}

TEST_CASE("white furnace: rough glass of roughness 1 is at most 1", "[stability][furnace]") {
    run_furnace({"white-furnace/rough-dielectric-1.json", Expectation::AtMost, both, 24});
}

TEST_CASE("white furnace: rough plastic with a white base is at most 1", "[stability][furnace]") {
    run_furnace({"white-furnace/rough-plastic.json", Expectation::AtMost, both, 25});
}

TEST_CASE("white furnace: twisted shading normals create no energy", "[stability][furnace][geometry]") {
    run_furnace({"flipped-normals/twisted.json", Expectation::AtMost, both, 26});
}

TEST_CASE("twisted shading normals under rough glass give valid samples", "[stability][geometry]") {
    run_furnace({"flipped-normals/twisted-glossy.json", Expectation::AtMost, {}, 27});
}

// --- Conductors with k = 0 ---------------------------------------------------------------------------

TEST_CASE("a conductor with k = 0 and eta 0.5 is at most 1 in the furnace", "[stability][furnace]") {
    run_furnace({"conductor-k0/scene.json", Expectation::AtMost, pt_is, 28});
}

TEST_CASE("a conductor with k = 0 and eta 1.5 is at most 1 in the furnace", "[stability][furnace]") {
    run_furnace({"conductor-k0/eta-1.5.json", Expectation::AtMost, pt_is, 29});
}

TEST_CASE("a conductor with k = 0 and eta 1 reflects nothing", "[stability][furnace]") {
    // Every sample of a pixel that sees only the sphere is F = 0 exactly: deterministic.
    run_furnace({"conductor-k0/eta-1.json", Expectation::AtMost, pt_is, 30});
    const Scene scene = load("conductor-k0/eta-1.json");
    const std::vector<std::size_t> sphere = pixels_where(pixel_coverage(scene), 1);
    REQUIRE(sphere.size() > 100u);
    HardRender request;
    request.scene = "conductor-k0/eta-1.json";
    request.seed = 31;
    const RenderResult result = render(request);
    std::size_t lit = 0;
    for (const std::size_t i : sphere) lit += max_component(result.image[i]) > 0.0f ? 1 : 0;
    INFO(lit << " of " << sphere.size() << " sphere pixels reflect light");
    CHECK(lit == 0u);
}

TEST_CASE("the furnace's energy test sees a 3 % error in either direction", "[stability][furnace]") {
    // Power, not luck: the white diffuse furnace rendered by pt-naive (the noisiest case) fails
    // "equal to 0.97", "at most 0.97" and "equal to 1.03", and passes "at most 1.03".
    const Scene scene = load("white-furnace/scene.json");
    const std::vector<int> coverage = pixel_coverage(scene);
    const std::vector<PixelGroup> groups = {{"silhouette pixels", pixels_where(coverage, Mixed)},
                                            {"object pixels", pixels_where(coverage, 1)}};
    HardRender request;
    request.scene = "white-furnace/scene.json";
    request.integrator = "pt-naive";
    request.samples_per_pixel = 256;
    request.seed = 32;
    const RenderResult result = render(request);
    CHECK_FALSE(energy_test(result, 0.97, Expectation::Equal, 16, groups, one_sample_stability_alpha).passed);
    CHECK_FALSE(energy_test(result, 0.97, Expectation::AtMost, 16, groups, one_sample_stability_alpha).passed);
    CHECK_FALSE(energy_test(result, 1.03, Expectation::Equal, 16, groups, one_sample_stability_alpha).passed);
    CHECK(energy_test(result, 1.03, Expectation::AtMost, 16, groups, one_sample_stability_alpha).passed);
}
