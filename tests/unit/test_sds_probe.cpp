// The specular-diffuse-specular probe (common/sds_probe.hpp) and what `auto` does with it: exact
// shares on scenes built so that the answer is known (tests/data/sds/), the limit's margin on the
// book's scenes, and auto's choice where the share is above it.
#include "freezeray/ch05/auto_integrator.hpp"
#include "freezeray/ch01/register_chapter01.hpp"
#include "freezeray/ch02/register_chapter02.hpp"
#include "freezeray/ch03/register_chapter03.hpp"
#include "freezeray/ch04/register_chapter04.hpp"
#include "freezeray/progress.hpp"
#include "freezeray/registry.hpp"
#include "freezeray/scene.hpp"
#include "freezeray/scene_loader.hpp"
#include "freezeray/ch05/sds_probe.hpp"
#include "freezeray/integrator_advice.hpp"

#include "test_scenes.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <numbers>

using namespace freezeray;
using namespace freezeray::ch05;

namespace {

SdsShare probe_scene(const std::string& path, int threads = 0, std::size_t probes = 1u << 14) {
    const Scene scene = load_scene(path, testing::full_registry());
    SdsProbeSettings settings;
    settings.probes = probes;
    settings.threads = threads;
    settings.seed = 3;
    return measure_sds_share(scene, nullptr, settings);
}

}  // namespace

TEST_CASE("the SDS share is exactly 1 through an interface that bends nothing, and 0 where a connection is possible",
          "[unit][auto]") {
    // through.json: every camera ray passes a smooth dielectric plane of index 1 to reach the
    // floor, and every light sample from the floor meets the plane first.
    const SdsShare through = probe_scene(testing::test_data_path("sds/through.json"));
    CHECK(through.share == 1.0);
    CHECK(through.standard_error == 0.0);
    CHECK(through.lit_through_specular_view == 1.0);
    // The floor seen directly: the camera connects to it.
    const SdsShare direct = probe_scene(testing::test_data_path("sds/direct.json"));
    CHECK(direct.share == 0.0);
    CHECK(direct.lit_through_specular_view == 0.0);
    // Seen through the plane but lit directly, by a light under it: light samples connect.
    const SdsShare below = probe_scene(testing::test_data_path("sds/light-below.json"));
    CHECK(below.share == 0.0);
    CHECK(below.lit_through_specular_view == 1.0);
    // The plane diffuse: what the camera sees is the plane itself.
    const SdsShare opaque = probe_scene(testing::test_data_path("sds/opaque.json"));
    CHECK(opaque.share == 0.0);
    CHECK(opaque.lit_through_specular_view == 0.0);
}

TEST_CASE("the SDS share is the same on any number of threads", "[unit][auto]") {
    // caustic: the floor seen through the glass sphere, lit partly through it (a share of about 0.003).
    const SdsShare one = probe_scene(testing::scene_path("caustic/scene.json"), 1);
    const SdsShare two = probe_scene(testing::scene_path("caustic/scene.json"), 2);
    CHECK(one.share > 0.0);
    CHECK(one.share == two.share);
    CHECK(one.standard_error == two.standard_error);
}

TEST_CASE("the SDS limit lies far from every scene of the book: above it water-caustic only", "[unit][auto]") {
    // The choice the limit makes is robust only if no scene lies near it. Each share below is a
    // mean of 2^14 probes with a standard error of at most 0.004 (values in [0, 1]); a failure
    // here means a scene moved by more than 10 standard errors, or a scene was added near the limit.
    for (const char* file : {"caustic/scene.json", "material-spheres/scene.json", "cornell-box/scene.json",
                             "veach-mis/scene.json", "cornell-lamp/scene.json", "door-ajar/scene.json"}) {
        INFO(file);
        CHECK(probe_scene(testing::scene_path(file)).share < SdsShareLimit / 2.0);
    }
    const std::optional<std::string> shared = testing::shared_scenes_folder();
    if (!shared || !std::filesystem::exists(*shared + "/water-caustic/water-caustic.obj")) {
        WARN("skipped the shared scenes: Bitterli's scenes are not there (set FREEZERAY_SHARED_SCENES)");
        return;
    }
    for (const char* file : {"staircase2/scene.json", "veach-bidir/scene.json", "material-testball/scene.json"}) {
        INFO(file);
        CHECK(probe_scene(testing::scene_path(file)).share < SdsShareLimit / 2.0);
    }
    CHECK(probe_scene(testing::scene_path("water-caustic/scene.json")).share > 10.0 * SdsShareLimit);
}

TEST_CASE("auto renders a scene lit by SDS paths with the Markov chain, without pilots, and says why", "[unit][auto]") {
    const Registry& registry = testing::full_registry();
    const Scene scene = load_scene(testing::test_data_path("sds/through.json"), registry);
    RenderSettings settings;
    settings.samples_per_pixel = 8;
    settings.seed = 2;
    settings.threads = 2;
    Progress quiet(true);
    const RenderResult result = registry.integrators.make("auto", "test", settings, Parameters::none())->render(scene, settings, quiet);
    CHECK(result.integrator == "mlt");
    CHECK_THAT(result.integrator_choice, Catch::StartsWith("mlt: the only candidate; pt-mis, bdpt left out before the pilots: 1 of "
                                                           "the image is lit through a specular surface and seen through one"));
    CHECK_THAT(result.notes.front(), Catch::Contains("(no pilots; SDS probe 1 of the image, "));
    // The whole budget is mlt's own render: the same image as mlt's with the same settings.
    const RenderResult mlt = registry.integrators.make("mlt", "test", settings, Parameters::none())->render(scene, settings, quiet);
    CHECK(result.samples_per_pixel == mlt.samples_per_pixel);
    CHECK(result.image.pixels() == mlt.image.pixels());
}

TEST_CASE("the advice is mlt above the SDS limit when the renderer has it, the effects' guess elsewhere", "[unit][auto]") {
    CHECK_FALSE(chain_advice(SdsShareLimit / 2.0).has_value());
    CHECK(chain_advice(1.0).has_value());
    // Smooth transmission and an area light: where the probe finds no SDS path (the light under
    // the plane, share 0), the effects alone advise bdpt (caustics); seen and lit through the
    // plane (share 1), mlt.
    const Scene below = load_scene(testing::test_data_path("sds/light-below.json"), testing::full_registry());
    CHECK(advise_integrator(below, testing::full_registry()).name == "bdpt");
    const Scene through = load_scene(testing::test_data_path("sds/through.json"), testing::full_registry());
    CHECK(advise_integrator(through, testing::full_registry()).name == "mlt");
    // Before chapter 05 there is no chain to advise.
    Registry chapter04("ch04", 4);
    register_chapter04(chapter04);
    CHECK(advise_integrator(through, chapter04).name == "bdpt");
}

TEST_CASE("the camera strategy's chance is the light's configuration factor where it is known exactly", "[unit][auto]") {
    // through-narrow.json: every probe sees the floor within 0.03 of the point under the 1 x 1
    // light at height 2, through a plane of index 1 that bends nothing. A cosine-distributed
    // direction from there reaches the light with the configuration factor of a parallel square
    // above its centre: four rectangles with a corner above the point (Howell's catalogue).
    const double a = 0.5 / 2.0;  // the rectangles' sides over the height
    const double corner = (a / std::sqrt(1.0 + a * a) * std::atan(a / std::sqrt(1.0 + a * a))) * 2.0 / (2.0 * std::numbers::pi);
    const double expected = 4.0 * corner;  // 0.0735
    const Scene scene = load_scene(testing::test_data_path("sds/through-narrow.json"), testing::full_registry());
    SdsProbeSettings settings;
    settings.probes = 1u << 12;
    settings.camera_strategy_tries = 1u << 18;
    settings.seed = 4;
    const SdsShare sds = measure_sds_share(scene, nullptr, settings);
    REQUIRE(sds.share == 1.0);
    REQUIRE(sds.camera_strategy_tries >= settings.camera_strategy_tries);
    const CameraStrategyChance chance = camera_strategy_chance(sds);
    // Binomial: 4 standard errors (about 0.0021), a false failure about once in 16,000 seeds.
    const double standard_error = std::sqrt(expected * (1.0 - expected) / double(sds.camera_strategy_tries));
    CHECK(std::abs(chance.p - expected) < 4.0 * standard_error);
    CHECK(chance.p_upper > chance.p);
    CHECK(chance.tail_per_sample == Approx(1.0 / chance.p));
}

TEST_CASE("with no hit, the camera strategy's chance is bounded by the Poisson limit of 3 events", "[unit][auto]") {
    SdsShare sds;
    sds.share = 0.5;
    sds.camera_strategy_tries = 1000;
    sds.camera_strategy_hits = 0;
    const CameraStrategyChance none = camera_strategy_chance(sds);
    CHECK(none.p == 0.0);
    CHECK(none.p_upper == Approx(0.003));
    CHECK(std::isinf(none.tail_per_sample));
    CHECK(none.tail_lower == Approx(0.5 / 0.003));
    // Many hits: the bound n + 1.645 sqrt(n + 1) + 1.569 (Gehrels 1986, equation 9).
    sds.camera_strategy_hits = 100;
    const CameraStrategyChance many = camera_strategy_chance(sds);
    CHECK(many.p == Approx(0.1));
    CHECK(many.p_upper == Approx((100.0 + 1.645 * std::sqrt(101.0) + (1.645 * 1.645 + 2.0) / 3.0) / 1000.0));
}
