// The image loop shared by every per-pixel integrator: passes of samples over all tiles, until
// the sample count, the time budget or the target error is reached.
#include "freezeray/integrator.hpp"

#include "freezeray/error.hpp"
#include "freezeray/parallel.hpp"
#include "freezeray/progress.hpp"
#include "freezeray/scene.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <vector>

namespace freezeray {

namespace {

constexpr int TileSize = 16;
// The error estimate from the per-pixel variance is unreliable with very few samples; a target
// error is checked only once every pixel has at least this many.
constexpr std::uint64_t MinimumSamplesForErrorEstimate = 8;

bool stop_requested(const RenderSettings& settings) {
    return settings.stop_requested != nullptr && settings.stop_requested->load(std::memory_order_relaxed);
}

// How many samples per pixel the next pass adds. Passes double the sample count, so checkpoints
// fall at 1, 2, 4, 8, ... samples; with a time budget the last pass is cut so as not to overshoot
// it by much, and with checkpoints no pass takes much longer than their interval.
std::uint64_t next_pass_size(std::uint64_t done, std::uint64_t sample_cap, std::uint64_t samples_this_run,
                             double elapsed, const RenderSettings& settings) {
    std::uint64_t pass = std::min(std::max<std::uint64_t>(1, done), sample_cap - done);
    if (samples_this_run == 0) return pass;
    const double seconds_per_sample = elapsed / static_cast<double>(samples_this_run);
    if (settings.time_seconds > 0.0)
        pass = std::clamp<std::uint64_t>(static_cast<std::uint64_t>(std::max(0.0, settings.time_seconds - elapsed) / seconds_per_sample),
                                         1, pass);
    if (settings.max_pass_seconds > 0.0)
        pass = std::clamp<std::uint64_t>(static_cast<std::uint64_t>(settings.max_pass_seconds / seconds_per_sample), 1,
                                         pass);
    return pass;
}

}  // namespace

std::vector<std::unique_ptr<Sampler>> thread_samplers(const Sampler& prototype, const RenderSettings& settings,
                                                      int threads, int width, int height) {
    const bool counted = settings.time_seconds <= 0.0 && settings.target_error <= 0.0;
    std::vector<std::unique_ptr<Sampler>> samplers;
    for (int t = 0; t < threads; ++t) {
        samplers.push_back(prototype.clone());
        samplers.back()->set_seed(settings.seed);
        samplers.back()->plan_render(width, height, counted ? settings.samples_per_pixel : 0);
    }
    return samplers;
}

// BOOK(pixel-loop)
RenderResult render_pixels(const Scene& scene, const RenderSettings& settings, Progress& progress,
                           const RadianceEstimator& li) {
    const Camera& camera = *scene.camera;
    const int width = camera.width();
    const int height = camera.height();
    const int threads = resolve_thread_count(settings.threads);
    const bool by_time = settings.time_seconds > 0.0;
    const bool by_error = settings.target_error > 0.0;
    // With a time budget or a target error, the sample count is only a cap (unlimited if by time).
    const std::uint64_t sample_cap = by_time ? UINT64_MAX : settings.samples_per_pixel;

    Film film = settings.resume ? settings.resume->clone() : Film(width, height);
    if (film.width() != width || film.height() != height)
        throw InputError("--resume", "the saved render is " + std::to_string(film.width()) + "x" +
                                         std::to_string(film.height()) + " but this one is " + std::to_string(width) + "x" +
                                         std::to_string(height));
    std::vector<ScratchArena> arenas(static_cast<std::size_t>(threads));
    const IndependentSampler independent;
    const std::vector<std::unique_ptr<Sampler>> samplers =
        thread_samplers(settings.sampler ? *settings.sampler : independent, settings, threads, width, height);
    auto start = std::chrono::steady_clock::now();
    auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
    RenderResult result;
    std::uint64_t samples_this_run = 0;  // samples per pixel added by this call (for timing)
    std::uint64_t done = film.minimum_sample_count();  // samples every pixel has (a resumed film's too)
    // The progress counts this call's work only: a resumed film's samples are not this run's speed.
    progress.start("render", by_time ? 0 : (sample_cap - std::min(done, sample_cap)) * width * height, settings.time_seconds);
    while (done < sample_cap && !result.interrupted) {
        const std::uint64_t pass = next_pass_size(done, sample_cap, samples_this_run, elapsed(), settings);
        const std::uint64_t target = done + pass;
        parallel_for_tiles(width, height, TileSize, threads, [&](const Tile& tile, int thread) {
            if (stop_requested(settings)) return;
            ScratchArena& arena = arenas[static_cast<std::size_t>(thread)];
            Sampler& sampler = *samplers[static_cast<std::size_t>(thread)];
            for (int y = tile.y0; y < tile.y1; ++y) {
                for (int x = tile.x0; x < tile.x1; ++x) {
                    const auto pixel_index = static_cast<std::uint32_t>(y * width + x);
                    // Each pixel goes on from its own count (they differ only after an interrupted pass).
                    for (std::uint64_t s = film.sample_count(x, y); s < target; ++s) {
                        // Every number of this sample depends on (seed, pixel, sample index, dimension) only.
                        sampler.start_pixel_sample(x, y, pixel_index, settings.first_sample + s);
                        const Vec2 film_position = Vec2(x, y) + sampler.pixel_2d();
                        arena.reset();
                        film.add_sample(x, y, li(camera.generate_ray(film_position), sampler, arena));
                    }
                }
            }
            progress.advance(pass * static_cast<std::uint64_t>((tile.x1 - tile.x0) * (tile.y1 - tile.y0)));
        });
        result.interrupted = stop_requested(settings);
        if (!result.interrupted) {
            done = target;
            samples_this_run += pass;
        }
        const double estimate = film.estimated_relative_mse();
        progress.set_estimated_error(estimate);
        if (settings.on_pass && !result.interrupted) {
            // The observer's time (measuring errors, writing checkpoints) is not render time.
            const auto before = std::chrono::steady_clock::now();
            settings.on_pass(film, done, elapsed());
            start += std::chrono::steady_clock::now() - before;
        }
        if (by_time && elapsed() >= settings.time_seconds) break;
        if (by_error && done >= MinimumSamplesForErrorEstimate && estimate >= 0.0 && estimate <= settings.target_error)
            break;
    }
    progress.finish();

    result.image = film.mean();
    result.samples_per_pixel = film.minimum_sample_count();
    result.variance = film.variance_of_mean();
    result.seconds = elapsed();
    result.invalid_samples = film.invalid_sample_count();
    result.estimated_relative_mse = film.estimated_relative_mse();
    result.film = std::make_shared<const Film>(std::move(film));
    return result;
}
// END BOOK

RenderResult PixelIntegrator::render(const Scene& scene, const RenderSettings& settings, Progress& progress) const {
    return render_pixels(scene, settings, progress, [&](const Ray& ray, Sampler& sampler, ScratchArena& arena) {
        return li(ray, scene, sampler, arena);
    });
}

}  // namespace freezeray
