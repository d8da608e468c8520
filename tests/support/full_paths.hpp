// Complete bidirectional paths for testing chapter 04's MIS weights: a path x[0] (the pinhole)
// ... x[n-1] (on a light) with the density of every vertex from both sides, cut into the light and
// camera subpaths of each strategy (s, t), and the heuristic written out from the full densities.
#pragma once

#include "freezeray/ch04/bdpt_mis_weight.hpp"

#include <cstdint>
#include <functional>
#include <vector>

namespace freezeray::testing {

struct FullPath {
    std::vector<ch04::PathVertex> x;
    ch04::PathVertex light_end;  // x[n-1] as the first vertex of a light subpath
    std::vector<float> from_camera, from_light;
};

// The densities of every vertex: from_camera[i] as sampled from x[i-1], from_light[i] from x[i+1]
// (the light's origin and emission densities for the last two).
FullPath with_densities(const Scene& scene, const ch03::FixedLightSampler& lights, std::vector<ch04::PathVertex> x,
                        const ch04::PathVertex& light_end);

// True when bdpt has strategy s for this path: the connecting edge (x[t-1], x[t]) has no delta
// end, s = 0 needs a light that rays can hit, (1, 1) an area light.
bool has_strategy(const FullPath& path, int s);

// The weight bdpt_mis_weight gives strategy s: the subpaths cut from the full path.
float weight_of(const Scene& scene, const ch03::FixedLightSampler& lights, ch03::MisHeuristic heuristic,
                const FullPath& path, int s);

// The heuristic written out: p_s = product of the densities each vertex has under strategy s
// (camera side for x[1 .. t-1], light side for x[t .. n-1]), w_s = p_s^b / sum over strategies.
// Only for paths without delta vertices (their densities are not comparable).
double direct_weight(const FullPath& path, int s, ch03::MisHeuristic heuristic);

// False when a non-delta vertex has a zero or infinite density (the path carries nothing).
bool densities_usable(const FullPath& path);

// Camera subpaths of 3 to 6 vertices through random pixels of `scene`, kept when they end on an
// emitter or escape to the environment; calls `check` on each complete path until `wanted` were
// checked. Returns how many were.
int for_paths_ending_on_emitters(const Scene& scene, const ch03::FixedLightSampler& lights, int wanted, std::uint64_t seed,
                                 const std::function<void(const FullPath&)>& check);

}  // namespace freezeray::testing
