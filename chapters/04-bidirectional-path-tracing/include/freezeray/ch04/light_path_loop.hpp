// The image loop of the integrators that splat (light tracing, bidirectional path tracing):
// batches of light paths, each contributing anywhere on the film through a SplatBuffer.
#pragma once

#include "freezeray/image.hpp"
#include "freezeray/integrator.hpp"
#include "freezeray/random.hpp"
#include "freezeray/sampler.hpp"
#include "freezeray/scratch_arena.hpp"
#include "freezeray/ch04/splat_film.hpp"

#include <cstdint>
#include <functional>
#include <vector>

namespace freezeray::ch04 {

// One light path (or, for bidirectional path tracing, one pair of subpaths) for work slot
// `slot` in [0, pixel count): everything it contributes goes into `splats`, at any pixel. All
// randomness from `random`, the slot's own stream, or from `sampler` when it is not null: the
// render's sampler (RenderSettings::sampler, chapter 09), started at the slot's pixel and the
// batch's sample index (a bidirectional sample is that pixel's sample). Scratch allocations in
// `arena`, reset before every call.
using LightPathEstimator = std::function<void(std::uint32_t slot, PCG32& random, Sampler* sampler, ScratchArena& arena,
                                              SplatBuffer& splats)>;

// The image loop of integrators that splat : batches of one light path per slot
// (pixel count paths per batch, each from make_pixel_stream(seed, slot, sample)), so that a
// batch adds one "sample per pixel", until the sample count, the time or the target error is
// reached. A stop request ends the render between batches. The result's film is
// SplatFilm::to_film of the batches done. Refuses settings.resume with an InputError.
// With extra_layers > 0, splats into layers 1 ... extra_layers are summed into extra images,
// returned in `layers` (index 0 for layer 1) when it is not null.
RenderResult render_light_paths(const Scene& scene, const RenderSettings& settings, Progress& progress,
                                const LightPathEstimator& estimator, int extra_layers = 0,
                                std::vector<Image>* layers = nullptr);

}  // namespace freezeray::ch04
