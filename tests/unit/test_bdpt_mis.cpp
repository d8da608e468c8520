// Chapter 04: the MIS weights of bidirectional path tracing. For one path, the weights of all the
// strategies that can make it sum to one (Veach 1997, section 10.3: the condition for an unbiased
// combination), and equal the heuristic written out with the full path densities. Paths come from
// real camera subpaths in the course's scenes, with delta BSDF vertices (glass, mirror), an
// environment, and point and spot lights. Deterministic (fixed seeds, no statistical test).
#include "freezeray/ch04/bdpt_mis_weight.hpp"
#include "freezeray/ch04/subpaths.hpp"

#include "test_scenes.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

using namespace freezeray;
using namespace freezeray::ch04;

namespace {

// A complete path x[0] (the pinhole) ... x[n-1] (on a light), with the density of every vertex
// as the camera side samples it (from x[i-1]) and as the light side does (from x[i+1]).
struct FullPath {
    std::vector<PathVertex> x;
    PathVertex light_end;  // x[n-1] as the first vertex of a light subpath
    std::vector<float> from_camera, from_light;
};

FullPath with_densities(const Scene& scene, const ch03::LightSampler& lights, std::vector<PathVertex> x,
                        const PathVertex& light_end) {
    FullPath path{std::move(x), light_end, {}, {}};
    const int n = static_cast<int>(path.x.size());
    path.from_camera.assign(static_cast<std::size_t>(n), 0.0f);
    path.from_light.assign(static_cast<std::size_t>(n), 0.0f);
    for (int i = 1; i < n; ++i)
        path.from_camera[i] = vertex_pdf(scene, path.x[i - 1], i >= 2 ? &path.x[i - 2] : nullptr, path.x[i]);
    path.from_light[n - 1] = light_origin_pdf(lights, light_end, path.x[n - 2]);
    path.from_light[n - 2] = light_pdf(light_end, path.x[n - 2]);
    for (int i = n - 3; i >= 1; --i) path.from_light[i] = vertex_pdf(scene, path.x[i + 1], &path.x[i + 2], path.x[i]);
    return path;
}

// True when bdpt has strategy s for this path: the connecting edge (x[t-1], x[t]) has no delta
// end, s = 0 needs a light that rays can hit, (1, 1) an area light.
bool has_strategy(const FullPath& path, int s) {
    const int n = static_cast<int>(path.x.size());
    const int t = n - s;
    if (s == 0) return !path.light_end.is_delta_light();
    if (s == 1 && t == 1) return path.light_end.light->type() == LightType::Area;
    return !path.x[t - 1].delta && !path.x[t].delta;
}

// The weight bdpt gives strategy s: the subpaths cut from the full path with their densities.
float weight_of(const Scene& scene, const ch03::LightSampler& lights, ch03::MisHeuristic heuristic,
                const FullPath& path, int s) {
    const int n = static_cast<int>(path.x.size());
    const int t = n - s;
    std::vector<PathVertex> camera(path.x.begin(), path.x.begin() + t);
    for (int i = 0; i < t; ++i) {
        camera[i].pdf_fwd = path.from_camera[i];
        camera[i].pdf_rev = path.from_light[i];
    }
    std::vector<PathVertex> light;
    for (int j = 0; j < s; ++j) {
        const int i = n - 1 - j;
        PathVertex v = j == 0 ? path.light_end : path.x[i];
        v.transport = Transport::Importance;
        if (v.type == VertexType::Surface) v.wo = glm::normalize(path.x[i + 1].position - v.position);
        v.pdf_fwd = path.from_light[i];
        v.pdf_rev = path.from_camera[i];
        light.push_back(v);
    }
    return bdpt_mis_weight(scene, lights, heuristic, light.data(), s, camera.data(), t, nullptr);
}

// The heuristic written out: p_s = product of the densities each vertex has under strategy s
// (camera side for x[1 .. t-1], light side for x[t .. n-1]), w_s = p_s^b / sum over strategies.
// Only for paths without delta vertices (their densities are not comparable).
double direct_weight(const FullPath& path, int s, ch03::MisHeuristic heuristic) {
    const int n = static_cast<int>(path.x.size());
    auto density = [&](int strategy) {
        const int t = n - strategy;
        double p = 1.0;
        for (int i = 1; i < t; ++i) p *= path.from_camera[i];
        for (int i = t; i < n; ++i)  // a delta light's origin: a common factor of every strategy (s >= 1)
            p *= (i == n - 1 && path.light_end.is_delta_light()) ? 1.0f : path.from_light[i];
        return heuristic == ch03::MisHeuristic::Power ? p * p : p;
    };
    double sum = 0.0;
    for (int other = 0; other < n; ++other)
        if (has_strategy(path, other)) sum += density(other);
    return density(s) / sum;
}

bool densities_usable(const FullPath& path) {
    // A zero density at a non-delta vertex means the path carries nothing (outside a spot's
    // cone, behind an emitter): no strategy makes it, nothing to weigh.
    for (std::size_t i = 1; i < path.x.size(); ++i) {
        const bool delta_here = path.x[i].delta || path.x[i - 1].delta;
        if (delta_here) continue;
        // A delta light's origin has no area density (s = 0 cannot make the path).
        if (i + 1 == path.x.size() && path.light_end.is_delta_light()) continue;
        if (!(path.from_camera[i] > 0.0f) || !(path.from_light[i] > 0.0f)) return false;
        if (!std::isfinite(path.from_camera[i]) || !std::isfinite(path.from_light[i])) return false;
    }
    return true;
}

struct Checked {
    int paths = 0;
    int with_delta_vertices = 0;
};

// Checks every strategy's weight of one path: they sum to one, and without delta vertices they
// equal direct_weight.
void check_path(const Scene& scene, const ch03::LightSampler& lights, const FullPath& path, Checked& checked) {
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

// Camera subpaths of 3 to 6 vertices through random pixels; those that end on an emitter (or
// escape to the environment) are complete paths.
Checked check_paths_ending_on_emitters(const std::string& scene_file, int wanted, std::uint64_t seed) {
    const Scene scene = load_scene(testing::scene_path(scene_file), testing::full_registry());
    const ch03::LightSampler lights(scene.lights, ch03::LightSelection::Power);
    PCG32 random(seed, 7);
    ScratchArena arena;
    Checked checked;
    std::vector<PathVertex> vertices(8);
    for (int attempt = 0; attempt < 200000 && checked.paths < wanted; ++attempt) {
        arena.reset();
        const int n = 3 + attempt % 4;
        const Vec2 film(random.next_float() * scene.camera->width(), random.next_float() * scene.camera->height());
        const int count = camera_subpath(scene, scene.camera->generate_ray(film), random, arena, n, vertices.data());
        if (count != n || !vertices[n - 1].is_light()) continue;
        std::vector<PathVertex> x(vertices.begin(), vertices.begin() + n);
        PathVertex light_end = x[n - 1];
        light_end.type = VertexType::Light;
        light_end.transport = Transport::Importance;
        if (light_end.infinite) light_end.geometric_normal = Vec3(0.0f);
        const FullPath path = with_densities(scene, lights, x, light_end);
        if (!densities_usable(path)) continue;
        check_path(scene, lights, path, checked);
    }
    return checked;
}

// Camera subpaths of 2 to 5 vertices ending at a non-delta surface, completed by a vertex on a
// delta-position light (point or spot) chosen by the light sampler.
Checked check_paths_ending_on_delta_lights(const std::string& scene_file, int wanted, std::uint64_t seed) {
    const Scene scene = load_scene(testing::scene_path(scene_file), testing::full_registry());
    const ch03::LightSampler lights(scene.lights, ch03::LightSelection::Power);
    PCG32 random(seed, 11);
    ScratchArena arena;
    Checked checked;
    std::vector<PathVertex> vertices(8);
    for (int attempt = 0; attempt < 200000 && checked.paths < wanted; ++attempt) {
        arena.reset();
        const int n = 3 + attempt % 4;
        const Vec2 film(random.next_float() * scene.camera->width(), random.next_float() * scene.camera->height());
        const int count = camera_subpath(scene, scene.camera->generate_ray(film), random, arena, n - 1, vertices.data());
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
