// The image loop of splatting integrators: batches of light paths, each batch's splats added to
// the film in a fixed order (see SplatBuffer), so images do not depend on the thread count.
#include "freezeray/integrator.hpp"

#include "freezeray/error.hpp"
#include "freezeray/parallel.hpp"
#include "freezeray/progress.hpp"
#include "freezeray/scene.hpp"

#include <algorithm>
#include <chrono>
#include <vector>

namespace freezeray {

namespace {

// Light paths per work unit: small enough that a 32x32 image still gives every thread work,
// large enough that handing out units costs nothing next to tracing the paths.
constexpr std::uint32_t SlotsPerWorkUnit = 64;
// Work units traced before their splats are added: 65536 light paths, a few MB of splats.
constexpr std::size_t UnitsPerRound = 1024;
// As render_pixels: a target error is checked only once this many samples per pixel are done.
constexpr std::uint64_t MinimumSamplesForErrorEstimate = 8;

bool stop_requested(const RenderSettings& settings) {
    return settings.stop_requested != nullptr && settings.stop_requested->load(std::memory_order_relaxed);
}

}  // namespace

// BOOK(light-path-loop)
RenderResult render_light_paths(const Scene& scene, const RenderSettings& settings, Progress& progress,
                                const LightPathEstimator& estimator, int extra_layers, std::vector<Image>* layers) {
    if (settings.resume)
        throw InputError("--resume", "a splatting render (light tracing) cannot be resumed: its film keeps sums of "
                                     "splats, not per-pixel samples to go on from; render more samples with another "
                                     "--seed or --sample-offset and `merge` the two");
    const PinholeCamera& camera = *scene.camera;
    const int width = camera.width();
    const int height = camera.height();
    const auto slots = static_cast<std::uint32_t>(width * height);
    const int threads = resolve_thread_count(settings.threads);
    const bool by_time = settings.time_seconds > 0.0;
    const bool by_error = settings.target_error > 0.0;
    const std::uint64_t sample_cap = by_time ? UINT64_MAX : settings.samples_per_pixel;

    SplatFilm film(width, height, extra_layers);
    // Memory is bounded by one round of at most UnitsPerRound work units: one buffer per unit,
    // holding the splats of SlotsPerWorkUnit light paths (at most max depth + 1 splats each, a
    // few on average), reused round after round. The film adds a round's buffers in unit order,
    // and rounds in slot order, so each pixel's additions come in one fixed order.
    const std::size_t units = (slots + SlotsPerWorkUnit - 1) / SlotsPerWorkUnit;
    const std::size_t units_per_round = std::min(units, UnitsPerRound);
    std::vector<SplatBuffer> buffers(units_per_round, SplatBuffer(width, height));
    std::vector<ScratchArena> arenas(static_cast<std::size_t>(threads));
    auto start = std::chrono::steady_clock::now();
    auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
    progress.start("render", by_time ? 0 : sample_cap * slots, settings.time_seconds);

    RenderResult result;
    std::uint64_t done = 0;  // batches (samples per pixel) added to the film
    while (done < sample_cap) {
        // A stop request ends the render between batches: the film only ever holds complete
        // batches, so its sample count stays exact (a batch is one light path per pixel).
        if (stop_requested(settings)) {
            result.interrupted = true;
            break;
        }
        const std::uint64_t sample = settings.first_sample + done;
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
                    estimator(slot, random, arena, buffer);
                }
                progress.advance(last - first);
            });
            for (std::size_t i = 0; i < round; ++i) film.add(buffers[i]);  // in work-unit order
        }
        ++done;
        const double estimate = film.estimated_relative_mse();
        progress.set_estimated_error(estimate);
        // Observers see the film at 1, 2, 4, ... samples per pixel (as render_pixels' passes),
        // or after every batch when checkpoints ask for a bound on the time between calls.
        const bool power_of_two = (done & (done - 1)) == 0;
        if (settings.on_pass && (power_of_two || settings.max_pass_seconds > 0.0 || done == sample_cap)) {
            const auto before = std::chrono::steady_clock::now();
            settings.on_pass(film.to_film(done), done, elapsed());
            start += std::chrono::steady_clock::now() - before;
        }
        if (stop_requested(settings)) result.interrupted = true;
        if (result.interrupted || (by_time && elapsed() >= settings.time_seconds)) break;
        if (by_error && done >= MinimumSamplesForErrorEstimate && estimate >= 0.0 && estimate <= settings.target_error)
            break;
    }
    progress.finish();

    result.image = film.mean();
    result.variance = film.variance_of_mean();
    result.samples_per_pixel = done;
    result.seconds = elapsed();
    result.invalid_samples = film.invalid_splat_count();
    result.estimated_relative_mse = film.estimated_relative_mse();
    result.film = std::make_shared<const Film>(film.to_film(done));
    if (layers != nullptr) {
        layers->clear();
        for (int layer = 1; layer <= extra_layers; ++layer) layers->push_back(film.layer_mean(layer));
    }
    return result;
}
// END BOOK

}  // namespace freezeray
