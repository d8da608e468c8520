// Chapter 04's light tracing on the hard cases of lights: point and spot lights lying on the
// surfaces they light (light paths that start at distance 0 from a surface), area lights touching
// walls, tiny emitters, shading normals twisted away from the geometry (the adjoint correction
// divides by |wo.ng|), and both extreme scales. Deterministic: no invalid splat, and light arrives.
#include "stability_support.hpp"

#include <catch2/catch.hpp>

#include "freezeray/image.hpp"

using namespace freezeray;
using namespace freezeray::stability;

TEST_CASE("light tracing gives valid, lit images with lights on surfaces, tiny emitters, twisted normals and "
          "extreme scales",
          "[stability][lights][ch04]") {
    for (const char* scene : {"point-light/scene.json", "point-light/on-surface.json", "point-light/spot.json",
                              "light-touching-wall/scene.json", "light-touching-wall/touching.json",
                              "tiny-emitters/scene.json", "flipped-normals/twisted.json",
                              "flipped-normals/twisted-glossy.json", "scale-1e-4/scene.json", "scale-1e4/scene.json"}) {
        HardRender request;
        request.scene = scene;
        request.integrator = "light-tracing";
        request.size = 32;
        request.samples_per_pixel = 16;
        request.seed = 140;
        const RenderResult result = render(request);
        check_valid(result, std::string(scene) + " with light-tracing");
        std::size_t lit = 0;
        for (const Spectrum& p : result.image.pixels()) lit += is_black(p) ? 0 : 1;
        INFO(scene << ": " << lit << " lit pixels");
        CHECK(lit > 0u);
    }
}
