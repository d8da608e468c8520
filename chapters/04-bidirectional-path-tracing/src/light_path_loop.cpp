// The image loop of splatting integrators: batches of light paths, each batch's splats added to
// the film in a fixed order (see SplatBuffer), so images do not depend on the thread count.
#include "freezeray/ch04/light_path_loop.hpp"

#include "freezeray/error.hpp"
#include "freezeray/parallel.hpp"
#include "freezeray/progress.hpp"
#include "freezeray/scene.hpp"
#include "freezeray/ch04/splat_batches.hpp"

#include <algorithm>
#include <chrono>
#include <memory>
#include <vector>

namespace freezeray::ch04 {

namespace {

// Light paths per work unit: small enough that a 32x32 image still gives every thread work,
// large enough that handing out units costs nothing next to tracing the paths.
constexpr std::uint32_t SlotsPerWorkUnit = 64;
// Work units traced before their splats are added: 65536 light paths, a few MB of splats.
constexpr std::size_t UnitsPerRound = 1024;
}  // namespace

// BOOK(light-path-loop)
RenderResult render_light_paths(const Scene& scene, const RenderSettings& settings, Progress& progress,
                                const LightPathEstimator& estimator, int extra_layers, std::vector<Image>* layers) {
    if (settings.resume)
        throw InputError("--resume", "a splatting render (light tracing) cannot be resumed: its film keeps sums of "
                                     "splats, not per-pixel samples to go on from; render more samples with another "
                                     "--seed or --sample-offset and `merge` the two");
    const Camera& camera = *scene.camera;
    const int width = camera.width();
    const int height = camera.height();
    const auto slots = static_cast<std::uint32_t>(width * height);
    const int threads = resolve_thread_count(settings.threads);

    SplatFilm film(width, height, extra_layers);
    // Memory is bounded by one round of at most UnitsPerRound work units: one buffer per unit,
    // holding the splats of SlotsPerWorkUnit light paths (at most max depth + 1 splats each, a
    // few on average), reused round after round. The film adds a round's buffers in unit order,
    // and rounds in slot order, so each pixel's additions come in one fixed order.
    const std::size_t units = (slots + SlotsPerWorkUnit - 1) / SlotsPerWorkUnit;
    const std::size_t units_per_round = std::min(units, UnitsPerRound);
    std::vector<SplatBuffer> buffers(units_per_round, SplatBuffer(width, height));
    std::vector<ScratchArena> arenas(static_cast<std::size_t>(threads));
    // The render's sampler, one clone per thread, when it has one (see LightPathEstimator).
    const std::vector<std::unique_ptr<Sampler>> samplers =
        settings.sampler ? thread_samplers(*settings.sampler, settings, threads, width, height)
                         : std::vector<std::unique_ptr<Sampler>>{};
    RenderResult result;
    SplatBatches batches(settings, progress, slots);
    while (batches.next_batch(result)) {
        const std::uint64_t sample = settings.first_sample + batches.batches();
        for (std::size_t first_unit = 0; first_unit < units; first_unit += units_per_round) {
            const std::size_t round = std::min(units_per_round, units - first_unit);
            parallel_for(round, threads, [&](std::size_t i, int thread) {
                SplatBuffer& buffer = buffers[i];
                buffer.clear();
                ScratchArena& arena = arenas[static_cast<std::size_t>(thread)];
                const auto first = static_cast<std::uint32_t>((first_unit + i) * SlotsPerWorkUnit);
                const std::uint32_t last = std::min(slots, first + SlotsPerWorkUnit);
                for (std::uint32_t slot = first; slot < last; ++slot) {
                    // Every random number of this light path comes from its own stream.
                    PCG32 random = make_pixel_stream(settings.seed, slot, sample);
                    // The half-buffer alternates with the sample for each slot: a bidirectional
                    // sample's camera-path contributions stay in the slot's own pixel, so halves
                    // by slot alone (sample * slots + slot with an even pixel count) would put all
                    // of a pixel's camera samples in one half and the error estimate would
                    // measure the difference between two different things.
                    buffer.begin_light_path(sample + slot);
                    arena.reset();
                    Sampler* sampler = samplers.empty() ? nullptr : samplers[static_cast<std::size_t>(thread)].get();
                    if (sampler != nullptr)
                        sampler->start_pixel_sample(static_cast<int>(slot % static_cast<std::uint32_t>(width)),
                                                    static_cast<int>(slot / static_cast<std::uint32_t>(width)), slot, sample);
                    estimator(slot, random, sampler, arena, buffer);
                }
                progress.advance(last - first);
            });
            for (std::size_t i = 0; i < round; ++i) film.add(buffers[i]);  // in work-unit order
        }
        if (!batches.batch_done(film, result)) break;
    }
    batches.finish(film, result);
    if (layers != nullptr) {
        layers->clear();
        for (int layer = 1; layer <= extra_layers; ++layer) layers->push_back(film.layer_mean(layer));
    }
    return result;
}
// END BOOK

}  // namespace freezeray::ch04
