// Hard lights (scenes/hard/): a zero-power emitter and area lights touching walls. Point lights,
// environment maps and the sun arrive with chapter 03 (scenes/hard/README.md lists them).
#include "stability_support.hpp"

#include <catch2/catch.hpp>

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
