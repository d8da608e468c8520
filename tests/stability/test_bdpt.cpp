// Chapter 04's bidirectional path tracing on the hard cases: every strategy image, weighted and
// unweighted, is free of NaN, Inf and negative values, and the render counts no invalid sample.
// The cases stress what bdpt adds: light subpaths that start on a surface (a point light lying on
// it), connections of length 0 (an area light touching a wall), total internal reflection on
// both subpaths (densities of delta vertices), an environment and a sun as light-path origins,
// twisted shading normals (the adjoint correction), grazing and degenerate geometry, a camera
// inside a closed mesh, both extreme scales, and the white furnace with its materials.
// Deterministic.
#include "stability_support.hpp"

#include "test_scenes.hpp"

#include <catch2/catch.hpp>

#include "freezeray/image.hpp"

using namespace freezeray;
using namespace freezeray::stability;

TEST_CASE("bdpt's strategy images are valid on the hard cases (no NaN, Inf or negative value in any of them)",
          "[stability][ch04]") {
    for (const char* scene :
         {"point-light/scene.json", "point-light/on-surface.json", "point-light/spot.json",
          "light-touching-wall/scene.json", "light-touching-wall/touching.json", "glass-block/scene.json",
          "tiny-emitters/scene.json", "flipped-normals/twisted.json", "flipped-normals/twisted-glossy.json",
          "scale-1e-4/scene.json", "scale-1e4/scene.json", "grazing/scene.json", "degenerate-triangles/scene.json",
          "inside-closed-mesh/scene.json", "sun-environment/scene.json", "environment-furnace/glass-cube.json",
          "environment-furnace/rough-dielectric-index-matched.json", "white-furnace/mix.json",
          "white-furnace/rough-dielectric.json", "roughness-limit/conductor-roughness-1e-4.json",
          "roughness-limit/dielectric-roughness-1e-4.json", "zero-power/scene.json", "far-and-tiny/scene.json"}) {
        testing::TestRender request;
        request.scene = hard_scene(scene);
        request.integrator = "bdpt";
        request.width = request.height = 24;
        request.samples_per_pixel = 8;
        request.seed = 150;
        request.threads = 1;
        request.max_depth = 12;
        request.strategy_images = true;
        const RenderResult result = testing::render(request);
        check_valid(result, std::string(scene) + " with bdpt");
        std::size_t bad_values = 0;
        std::string first_bad;
        for (const auto& [name, image] : result.extra_images)
            for (const Spectrum& p : image.pixels())
                if (!is_valid_radiance(p)) {
                    if (bad_values++ == 0) first_bad = name;
                }
        INFO(scene << ": " << bad_values << " invalid strategy-image values, first in " << first_bad);
        CHECK(bad_values == 0u);
        CHECK(result.extra_images.size() == 2u * 20u + 3u);
    }
}
