// The image loop shared by every per-pixel integrator: passes of samples over all tiles, until
// the sample count, the time budget or the target error is reached.
#include "freezeray/integrator.hpp"

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

}  // namespace

// BOOK(pixel-loop)
RenderResult PixelIntegrator::render(const Scene& scene, const RenderSettings& settings, Progress& progress) const {
    const PinholeCamera& camera = *scene.camera;
    const int width = camera.width();
    const int height = camera.height();
    const int threads = resolve_thread_count(settings.threads);
    const bool by_time = settings.time_seconds > 0.0;
    const bool by_error = settings.target_error > 0.0;
    // With a time budget or a target error, the sample count is only a cap (unlimited if by time).
    const std::uint64_t sample_cap = by_time ? UINT64_MAX : settings.samples_per_pixel;

    Film film(width, height);
    std::vector<ScratchArena> arenas(static_cast<std::size_t>(threads));
    auto start = std::chrono::steady_clock::now();
    auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
    progress.start("render", by_time ? 0 : sample_cap * width * height, settings.time_seconds);

    RenderResult result;
    std::uint64_t done = 0;  // samples per pixel completed in every pixel
    while (done < sample_cap && !result.interrupted) {
        // Passes double the sample count, so checkpoints fall at 1, 2, 4, 8, ... samples.
        std::uint64_t pass = std::max<std::uint64_t>(1, done);
        pass = std::min(pass, sample_cap - done);
        if (by_time && done > 0) {
            // Do not overshoot the budget by more than a fraction of one pass.
            const double seconds_per_sample = elapsed() / static_cast<double>(done);
            const double left = settings.time_seconds - elapsed();
            pass = std::clamp<std::uint64_t>(static_cast<std::uint64_t>(left / seconds_per_sample), 1, pass);
        }
        parallel_for_tiles(width, height, TileSize, threads, [&](const Tile& tile, int thread) {
            if (stop_requested(settings)) return;
            ScratchArena& arena = arenas[static_cast<std::size_t>(thread)];
            for (int y = tile.y0; y < tile.y1; ++y) {
                for (int x = tile.x0; x < tile.x1; ++x) {
                    const auto pixel_index = static_cast<std::uint32_t>(y * width + x);
                    for (std::uint64_t s = done; s < done + pass; ++s) {
                        // Every random number of this sample comes from its own stream.
                        PCG32 random = make_pixel_stream(settings.seed, pixel_index, s);
                        const Vec2 film_position(x + random.next_float(), y + random.next_float());
                        arena.reset();
                        film.add_sample(x, y, li(camera.generate_ray(film_position), scene, random, arena));
                    }
                }
            }
            progress.advance(pass * static_cast<std::uint64_t>((tile.x1 - tile.x0) * (tile.y1 - tile.y0)));
        });
        result.interrupted = stop_requested(settings);
        if (!result.interrupted) done += pass;
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
    result.variance = film.variance_of_mean();
    result.samples_per_pixel = done;
    result.seconds = elapsed();
    result.invalid_samples = film.invalid_sample_count();
    result.estimated_relative_mse = film.estimated_relative_mse();
    return result;
}
// END BOOK

}  // namespace freezeray
