// Chapter 05's Metropolis light transport on the hard cases: a scene whose light no path reaches
// (a black image and a warning, at once: no hang looking for a starting state, no division by
// b = 0), a scene where almost every bootstrap path carries nothing (the chains still start and
// light the image), and validity (no NaN, Inf or negative value) on the hard cases bdpt is
// checked on. Deterministic.
#include "stability_support.hpp"

#include "test_scenes.hpp"

#include <catch2/catch.hpp>

#include "freezeray/image.hpp"
#include "freezeray/scene.hpp"
#include "freezeray/scene_loader.hpp"
#include "freezeray/ch05/metropolis_light_transport.hpp"

#include <algorithm>

using namespace freezeray;
using namespace freezeray::stability;

namespace {

RenderResult render_mlt(const std::string& scene, std::uint64_t bootstrap, int size = 0, std::uint64_t spp = 4,
                        const std::string& integrator = "mlt") {
    testing::TestRender request;
    request.scene = hard_scene(scene);
    request.integrator = integrator;
    request.width = request.height = size;
    request.samples_per_pixel = spp;
    request.seed = 160;
    request.threads = 1;
    request.max_depth = 12;
    request.mlt_bootstrap = bootstrap;
    request.mlt_chains = 64;
    return testing::render(request);
}

}  // namespace

TEST_CASE("mlt with no reachable light gives a black image and a warning", "[stability][ch05]") {
    const RenderResult result = render_mlt("unreachable-light/scene.json", 20000);
    check_valid(result, "unreachable-light with mlt");
    for (const Spectrum& p : result.image.pixels()) REQUIRE(p == Spectrum(0.0f));
    REQUIRE(result.warnings.size() == 1u);
    CHECK(result.warnings[0].find("none of the 20000 bootstrap paths carried light") != std::string::npos);
}

TEST_CASE("mlt starts and lights the image when almost every bootstrap path carries nothing (a tiny light "
          "behind a door open 1.5 degrees)",
          "[stability][ch05]") {
    SceneLoadOptions options;
    const Scene scene = load_scene(hard_scene("near-closed-door/scene.json"), testing::full_registry(), options);
    const ch03::FixedLightSampler lights(scene.lights, ch03::LightSelection::Power);
    ch05::MltSettings settings;
    settings.bootstrap_samples = 20000;
    const ch05::Bootstrap bootstrap =
        ch05::run_bootstrap(scene, lights, ch04::BidirectionalSettings{12, ch03::MisHeuristic::Power, ""}, settings, 160, 1);
    const auto carrying = std::count_if(bootstrap.values.begin(), bootstrap.values.end(), [](float v) { return v > 0.0f; });
    INFO(carrying << " of 20000 bootstrap paths carry light");
    CHECK(carrying > 0);
    CHECK(carrying < 20000 / 10);  // the case this test is for: at most a tenth find the light

    // 64 mutations per pixel: enough for 64 chains to spread over the camera's room.
    const RenderResult result = render_mlt("near-closed-door/scene.json", 20000, 0, 64);
    check_valid(result, "near-closed-door with mlt");
    CHECK(result.warnings.empty());
    const auto lit = std::count_if(result.image.pixels().begin(), result.image.pixels().end(),
                                   [](const Spectrum& p) { return !is_black(p); });
    INFO(lit << " of " << result.image.pixel_count() << " pixels lit");
    CHECK(static_cast<std::size_t>(lit) > result.image.pixel_count() / 2);
}

TEST_CASE("mlt's and multiplexed mlt's images are valid on the hard cases (no NaN, Inf or negative value)",
          "[stability][ch05]") {
    for (const char* scene :
         {"point-light/scene.json", "point-light/on-surface.json", "point-light/spot.json",
          "light-touching-wall/scene.json", "glass-block/scene.json", "tiny-emitters/scene.json",
          "flipped-normals/twisted.json", "scale-1e-4/scene.json", "scale-1e4/scene.json", "grazing/scene.json",
          "inside-closed-mesh/scene.json", "sun-environment/scene.json", "environment-furnace/glass-cube.json",
          "white-furnace/rough-dielectric.json", "zero-power/scene.json", "far-and-tiny/scene.json"}) {
        for (const std::string integrator : {"mlt", "mlt-multiplexed"}) {
            const RenderResult result = render_mlt(scene, 4000, 24, 4, integrator);
            check_valid(result, std::string(scene) + " with " + integrator);
        }
    }
}
