// Chapter 04: the MIS weights of bidirectional path tracing. For one path, the weights of all the
// strategies that can make it sum to one (Veach 1997, section 10.3: the condition for an unbiased
// combination), and equal the heuristic written out with the full path densities. Paths come from
// real camera subpaths in the course's scenes, with delta BSDF vertices (glass, mirror), an
// environment, and point and spot lights. Deterministic (fixed seeds, no statistical test).
#include "freezeray/ch04/bdpt_mis_weight.hpp"
#include "freezeray/scene_loader.hpp"
#include "freezeray/ch04/subpaths.hpp"

#include "full_paths.hpp"
#include "test_scenes.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

using namespace freezeray;
using namespace freezeray::ch04;
using namespace freezeray::testing;

namespace {

struct Checked {
    int paths = 0;
    int with_delta_vertices = 0;
};

// Checks every strategy's weight of one path: they sum to one, and without delta vertices they
// equal direct_weight.
void check_path(const Scene& scene, const ch03::FixedLightSampler& lights, const FullPath& path, Checked& checked) {
    const int n = static_cast<int>(path.x.size());
    bool any_delta = false;
    for (const PathVertex& v : path.x) any_delta = any_delta || v.delta;
    for (const ch03::MisHeuristic heuristic : {ch03::MisHeuristic::Power, ch03::MisHeuristic::Balance}) {
        double sum = 0.0;
        for (int s = 0; s < n; ++s) {
            if (!has_strategy(path, s)) continue;
            const float w = weight_of(scene, lights, heuristic, path, s);
            INFO("path of " << n << " vertices, s = " << s << ", weight " << w);
            REQUIRE(std::isfinite(w));
            REQUIRE(w >= 0.0f);
            REQUIRE(w <= 1.0f + 1e-6f);
            sum += w;
            if (!any_delta) CHECK(w == Approx(direct_weight(path, s, heuristic)).epsilon(1e-3).margin(1e-6));
        }
        INFO("path of " << n << " vertices" << (any_delta ? " with delta vertices" : "") << ": weights sum to " << sum);
        CHECK(sum == Approx(1.0).epsilon(1e-4));
    }
    ++checked.paths;
    if (any_delta) ++checked.with_delta_vertices;
}

// Complete paths that end on an emitter (or escape to the environment), from camera subpaths.
Checked check_paths_ending_on_emitters(const std::string& scene_file, int wanted, std::uint64_t seed) {
    const Scene scene = load_scene(testing::scene_path(scene_file), testing::full_registry());
    const ch03::FixedLightSampler lights(scene.lights, ch03::LightSelection::Power);
    Checked checked;
    for_paths_ending_on_emitters(scene, lights, wanted, seed, [&](const FullPath& path) {
        check_path(scene, lights, path, checked);
    });
    return checked;
}

// Camera subpaths of 2 to 5 vertices ending at a non-delta surface, completed by a vertex on a
// delta-position light (point or spot) chosen by the light sampler.
Checked check_paths_ending_on_delta_lights(const std::string& scene_file, int wanted, std::uint64_t seed) {
    const Scene scene = load_scene(testing::scene_path(scene_file), testing::full_registry());
    const ch03::FixedLightSampler lights(scene.lights, ch03::LightSelection::Power);
    PCG32 random(seed, 11);
    IndependentSamples samples(random);
    ScratchArena arena;
    Checked checked;
    std::vector<PathVertex> vertices(8);
    for (int attempt = 0; attempt < 200000 && checked.paths < wanted; ++attempt) {
        arena.reset();
        const int n = 3 + attempt % 4;
        const Vec2 film(random.next_float() * scene.camera->width(), random.next_float() * scene.camera->height());
        const int count = camera_subpath(scene, scene.camera->generate_ray(film), samples, arena, n - 1, vertices.data());
        const auto choice = lights.sample(random.next_float());
        if (count != n - 1 || !choice || !is_delta_light(choice->light->type())) continue;
        const PathVertex& last = vertices[n - 2];
        if (last.type != VertexType::Surface || !last.connectible()) continue;
        const auto sample = choice->light->sample_li(last.position, Vec2(0.5f));
        if (!sample || is_black(sample->radiance)) continue;
        std::vector<PathVertex> x(vertices.begin(), vertices.begin() + n - 1);
        PathVertex light_end;
        light_end.type = VertexType::Light;
        light_end.transport = Transport::Importance;
        light_end.position = sample->position;
        light_end.light = choice->light;
        x.push_back(light_end);
        const FullPath path = with_densities(scene, lights, x, light_end);
        if (!densities_usable(path)) continue;
        check_path(scene, lights, path, checked);
    }
    return checked;
}

}  // namespace

TEST_CASE("bdpt's MIS weights of one path sum to one over its strategies and equal the heuristic written out "
          "(Cornell box: diffuse, an area light)",
          "[unit][ch04]") {
    const Checked checked = check_paths_ending_on_emitters("cornell-box/scene.json", 200, 21);
    CHECK(checked.paths == 200);
}

TEST_CASE("bdpt's MIS weights of one path sum to one with delta vertices (glass, mirror, gold of "
          "material-spheres)",
          "[unit][ch04]") {
    const Checked checked = check_paths_ending_on_emitters("material-spheres/scene.json", 300, 22);
    CHECK(checked.paths == 300);
    CHECK(checked.with_delta_vertices >= 20);  // the case this test is for
}

TEST_CASE("bdpt's MIS weights of one path sum to one when it ends on the environment (solid-angle densities)",
          "[unit][ch04]") {
    const Checked checked = check_paths_ending_on_emitters("material-spheres/scene-environment.json", 200, 23);
    CHECK(checked.paths == 200);
    CHECK(checked.with_delta_vertices >= 10);
}

TEST_CASE("bdpt's MIS weights of one path sum to one when it ends on a point or spot light (no s = 0 strategy)",
          "[unit][ch04]") {
    const Checked checked = check_paths_ending_on_delta_lights("cornell-box/point-and-spot.json", 200, 24);
    CHECK(checked.paths == 200);
}
