// light-sampler-benchmark (chapter 10): what a light choice costs with each light sampler, in
// nanoseconds, measured side by side in one process. The shading points are the first hits of
// the scene's camera rays through every pixel centre (position and shading normal), visited in
// the image's order; each pass draws one choice per point with a fixed stream of numbers, after
// a warm-up pass; the median pass is reported. The tree's build time is reported apart.
//
//   light-sampler-benchmark SCENE [--samplers power,uniform,bvh-tree,bvh] [--reps N] [--width W --height H] [--json]
//                           [--choice-map FILE.png --map-sampler NAME]
//
// --choice-map draws which lights a sampler chooses where: each light gets the colour of its
// mesh (a hue per mesh, in the order the scene lists them: an emissive sphere, a block of lamps),
// and each pixel the colour of the mesh whose lights are most likely chosen at its first hit,
// as bright as that probability (the sum of its lights'); black where no light can be chosen.
#include "freezeray/complete_renderer.hpp"
#include "freezeray/error.hpp"
#include "freezeray/image.hpp"
#include "freezeray/material.hpp"
#include "freezeray/random.hpp"
#include "freezeray/scene.hpp"
#include "freezeray/scene_loader.hpp"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cmath>
#include <iostream>
#include <map>
#include <string>
#include <vector>

using namespace freezeray;

namespace {

// The first hit of the camera ray through the centre of pixel (x, y), as pt-mis shows it to the
// light sampler (with the glossy lobe of a rough metal); nothing where the ray misses.
std::optional<ShadingPoint> camera_hit(const Scene& scene, int x, int y, ScratchArena& arena) {
    const Ray ray = scene.camera->generate_ray(Vec2(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f));
    const std::optional<Hit> hit = scene.intersect(ray);
    if (!hit) return std::nullopt;
    arena.reset();
    const BSDF& bsdf = *scene.material(*hit).bsdf(*hit, arena);
    const Frame frame = shading_frame(*hit, bsdf, -ray.direction);
    return shading_point(*hit, frame, frame.to_local(-ray.direction), bsdf);
}

// The first hits of the camera rays through every pixel centre.
std::vector<ShadingPoint> camera_hits(const Scene& scene) {
    std::vector<ShadingPoint> points;
    ScratchArena arena;
    for (int y = 0; y < scene.camera->height(); ++y)
        for (int x = 0; x < scene.camera->width(); ++x)
            if (const std::optional<ShadingPoint> point = camera_hit(scene, x, y, arena)) points.push_back(*point);
    return points;
}

// A bright colour of hue h in [0, 1).
Spectrum hue_colour(float h) {
    const float r = std::abs(h * 6.0f - 3.0f) - 1.0f, g = 2.0f - std::abs(h * 6.0f - 2.0f), b = 2.0f - std::abs(h * 6.0f - 4.0f);
    return glm::clamp(Spectrum(r, g, b), 0.0f, 1.0f);
}

// The map of --choice-map (see the top of this file).
Image choice_map(const Scene& scene, const LightSampler& sampler) {
    // A light's group: its mesh ("mesh 'lamps_3', triangle 12"), or the light itself.
    std::map<std::string, int> groups;
    std::vector<int> group_of(scene.lights.size());
    for (const auto& light : scene.lights) {
        const std::string group = light->where.substr(0, light->where.find(", triangle"));
        group_of[light->index] = groups.emplace(group, static_cast<int>(groups.size())).first->second;
    }
    Image map(scene.camera->width(), scene.camera->height());
    ScratchArena arena;
    for (int y = 0; y < map.height(); ++y)
        for (int x = 0; x < map.width(); ++x) {
            const std::optional<ShadingPoint> point = camera_hit(scene, x, y, arena);
            if (!point) continue;
            std::vector<double> probability(groups.size(), 0.0);
            for (const auto& light : scene.lights) probability[group_of[light->index]] += sampler.probability(*point, *light);
            const auto most = std::max_element(probability.begin(), probability.end()) - probability.begin();
            map.at(x, y) = static_cast<float>(probability[most]) *
                           hue_colour(std::fmod(0.61803398875f * static_cast<float>(most), 1.0f));
        }
    return map;
}

struct Measurement {
    std::string sampler;
    double nanoseconds_per_choice = 0.0;
    double build_milliseconds = 0.0;
    double chosen_fraction = 0.0;  // choices that found a light
};

Measurement measure(const Registry& registry, const std::string& name, const Scene& scene,
                    const std::vector<ShadingPoint>& points, int repetitions) {
    Measurement m;
    m.sampler = name;
    const auto build_start = std::chrono::steady_clock::now();
    const std::unique_ptr<LightSampler> sampler = registry.light_samplers.make(name, "--samplers", scene.lights, Parameters::none());
    m.build_milliseconds = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - build_start).count();
    std::vector<double> passes;
    std::size_t chosen = 0;
    float sink = 0.0f;  // keeps the choices from being optimised away
    for (int pass = 0; pass <= repetitions; ++pass) {
        PCG32 random(7, 11);  // the same numbers in every pass and for every sampler
        chosen = 0;
        const auto start = std::chrono::steady_clock::now();
        for (const ShadingPoint& point : points) {
            if (const std::optional<LightChoice> choice = sampler->sample(point, random.next_float())) {
                sink += choice->probability;
                ++chosen;
            }
        }
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (pass > 0) passes.push_back(seconds);  // pass 0 warms the caches up
    }
    std::sort(passes.begin(), passes.end());
    m.nanoseconds_per_choice = passes[passes.size() / 2] * 1e9 / static_cast<double>(points.size());
    m.chosen_fraction = static_cast<double>(chosen) / static_cast<double>(points.size());
    volatile float keep = sink;  // the compiler must compute every choice's probability
    (void)keep;
    return m;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"light-sampler-benchmark: nanoseconds per light choice of each light sampler, at the first hits of a "
                 "scene's camera rays, measured side by side in one process"};
    std::string scene_path;
    std::vector<std::string> samplers{"power", "uniform", "bvh-tree", "bvh"};
    int repetitions = 5, width = 0, height = 0;
    bool json = false;
    std::string map_path, map_sampler = "bvh";
    app.add_option("scene", scene_path, "scene file (JSON)")->required();
    app.add_option("--samplers", samplers, "light samplers to measure, comma-separated")->delimiter(',');
    app.add_option("--reps", repetitions, "timed passes over the points (the median is reported)");
    app.add_option("--width", width, "image width (default: the scene's)");
    app.add_option("--height", height, "image height (default: the scene's)");
    app.add_flag("--json", json, "one JSON object per line and sampler");
    app.add_option("--choice-map", map_path, "also draw which lights --map-sampler chooses where, to this PNG");
    app.add_option("--map-sampler", map_sampler, "the light sampler of --choice-map (default bvh)");
    CLI11_PARSE(app, argc, argv);
    try {
        if (repetitions < 1) throw InputError("--reps", "must be at least 1");
        if (width < 0 || height < 0) throw InputError("--width/--height", "must be positive");
        const Registry registry = make_complete_registry("light-sampler-benchmark");
        for (const std::string& name : samplers) registry.require(CapabilityKind::LightSampler, name, "--samplers");
        registry.require(CapabilityKind::LightSampler, map_sampler, "--map-sampler");
        if (!map_path.empty()) check_image_writable(map_path);
        SceneLoadOptions options;
        options.width = width;
        options.height = height;
        const Scene scene = load_scene(scene_path, registry, options);
        if (scene.lights.empty()) throw InputError(scene_path, "has no lights to choose from");
        const std::vector<ShadingPoint> points = camera_hits(scene);
        if (points.empty()) throw InputError(scene_path, "no camera ray hits anything");
        if (!json)
            std::printf("%s: %zu lights, %zu shading points, median of %d passes\n", scene_path.c_str(), scene.lights.size(),
                        points.size(), repetitions);
        for (const std::string& name : samplers) {
            const Measurement m = measure(registry, name, scene, points, repetitions);
            if (json)
                std::printf("{\"scene\": \"%s\", \"sampler\": \"%s\", \"lights\": %zu, \"points\": %zu, \"ns_per_choice\": %.2f, "
                            "\"build_ms\": %.3f, \"chosen_fraction\": %.4f}\n",
                            scene_path.c_str(), m.sampler.c_str(), scene.lights.size(), points.size(), m.nanoseconds_per_choice,
                            m.build_milliseconds, m.chosen_fraction);
            else
                std::printf("  %-8s %8.1f ns per choice   build %8.3f ms   a light chosen in %.1f %% of the walks\n",
                            m.sampler.c_str(), m.nanoseconds_per_choice, m.build_milliseconds, 100.0 * m.chosen_fraction);
        }
        if (!map_path.empty()) {
            const std::unique_ptr<LightSampler> sampler = registry.light_samplers.make(map_sampler, "--map-sampler", scene.lights, Parameters::none());
            write_image(map_path, choice_map(scene, *sampler));
            std::fprintf(stderr, "choice map: %s\n", map_path.c_str());
        }
    } catch (const InputError& e) {
        std::cerr << "light-sampler-benchmark: " << e.what() << "\n";
        return 1;
    }
    return 0;
}
