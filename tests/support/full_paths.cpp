// Complete bidirectional paths for the MIS-weight tests (see full_paths.hpp).
#include "full_paths.hpp"

#include "freezeray/ch04/subpaths.hpp"

#include <cmath>

namespace freezeray::testing {

using namespace freezeray::ch04;

FullPath with_densities(const Scene& scene, const ch03::FixedLightSampler& lights, std::vector<PathVertex> x,
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

bool has_strategy(const FullPath& path, int s) {
    const int n = static_cast<int>(path.x.size());
    const int t = n - s;
    if (s == 0) return !path.light_end.is_delta_light();
    if (s == 1 && t == 1) return path.light_end.light->type() == LightType::Area;
    return !path.x[t - 1].delta && !path.x[t].delta;
}

float weight_of(const Scene& scene, const ch03::FixedLightSampler& lights, ch03::MisHeuristic heuristic,
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

int for_paths_ending_on_emitters(const Scene& scene, const ch03::FixedLightSampler& lights, int wanted, std::uint64_t seed,
                                 const std::function<void(const FullPath&)>& check) {
    PCG32 random(seed, 7);
    IndependentSamples samples(random);
    ScratchArena arena;
    int checked = 0;
    std::vector<PathVertex> vertices(8);
    for (int attempt = 0; attempt < 200000 && checked < wanted; ++attempt) {
        arena.reset();
        const int n = 3 + attempt % 4;
        const Vec2 film(random.next_float() * scene.camera->width(), random.next_float() * scene.camera->height());
        const int count = camera_subpath(scene, scene.camera->generate_ray(film), samples, arena, n, vertices.data());
        if (count != n || !vertices[n - 1].is_light()) continue;
        std::vector<PathVertex> x(vertices.begin(), vertices.begin() + n);
        PathVertex light_end = x[n - 1];
        light_end.type = VertexType::Light;
        light_end.transport = Transport::Importance;
        if (light_end.infinite) light_end.geometric_normal = Vec3(0.0f);
        const FullPath path = with_densities(scene, lights, x, light_end);
        if (!densities_usable(path)) continue;
        check(path);
        ++checked;
    }
    return checked;
}

}  // namespace freezeray::testing
