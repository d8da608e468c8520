// Multiplexed MLT's state: one path length, one bidirectional strategy (book chapter 05;
// Hachisuka, Kaplanyan and Dachsbacher 2014; pbrt-v3, section 16.4).
#include "freezeray/ch05/metropolis_light_transport.hpp"

#include "freezeray/scene.hpp"
#include "freezeray/ch04/subpaths.hpp"

#include <algorithm>

namespace freezeray::ch05 {

// BOOK(multiplexed-path)
void evaluate_multiplexed_path(const Scene& scene, const ch03::FixedLightSampler& lights,
                               const ch04::BidirectionalSettings& settings, int segments, PrimarySamples& samples,
                               ScratchArena& arena, ch04::SubpathStorage& storage, PathContributions& out) {
    const Vec2 film = start_path(scene, samples, arena, out);
    // The strategy: s light vertices, t = segments + 1 - s camera vertices, each of the
    // segments + 1 strategies with probability 1 / (segments + 1). Because the choice is a primary
    // sample, small steps move between neighbouring strategies too.
    const int strategies = segments + 1;
    const int s = std::min(static_cast<int>(samples.next_float() * static_cast<float>(strategies)), strategies - 1);
    const int t = strategies - s;
    storage.camera.resize(static_cast<std::size_t>(t));
    storage.light.resize(static_cast<std::size_t>(std::max(s, 1)));
    if (ch04::camera_subpath(scene, scene.camera->generate_ray(film), samples, arena, t, storage.camera.data()) != t)
        return;
    if (ch04::light_subpath(scene, lights, samples, arena, s, storage.light.data()) != s) return;
    samples.start_stream(ch04::ConnectionStream);
    const ch04::StrategyContribution c = ch04::connect_strategy(scene, lights, settings.heuristic, storage.light.data(), s,
                                                                storage.camera.data(), t, samples);
    const Spectrum value = c.unweighted * (c.weight * static_cast<float>(strategies));
    if (is_black(value)) return;
    if (!is_valid_radiance(value)) {
        ++out.invalid;
        return;
    }
    out.splats.push_back({c.at_raster ? c.raster_position : film, value});
    out.value = luminance(value);
}
// END BOOK

}  // namespace freezeray::ch05
