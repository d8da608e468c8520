// Between the batches of a splatting render (see splat_batches.hpp).
#include "freezeray/ch04/splat_batches.hpp"

#include "freezeray/progress.hpp"

#include <cstdint>

namespace freezeray::ch04 {

namespace {

// As render_pixels: a target error is checked only once this many samples per pixel are done.
constexpr std::uint64_t MinimumSamplesForErrorEstimate = 8;

}  // namespace

SplatBatches::SplatBatches(const RenderSettings& settings, Progress& progress, std::uint64_t pixels)
    : settings_(settings),
      progress_(progress),
      cap_(settings.time_seconds > 0.0 ? UINT64_MAX : settings.samples_per_pixel),
      start_(std::chrono::steady_clock::now()) {
    progress_.start("render", settings.time_seconds > 0.0 ? 0 : cap_ * pixels, settings.time_seconds);
}

double SplatBatches::elapsed() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

bool SplatBatches::stop_requested() const {
    return settings_.stop_requested != nullptr && settings_.stop_requested->load(std::memory_order_relaxed);
}

bool SplatBatches::next_batch(RenderResult& result) const {
    // A stop request ends the render between batches: the film only ever holds complete
    // batches, so its sample count stays exact.
    if (stop_requested()) result.interrupted = true;
    return !result.interrupted && done_ < cap_;
}

bool SplatBatches::batch_done(const SplatFilm& film, RenderResult& result) {
    ++done_;
    const double estimate = film.estimated_relative_mse();
    progress_.set_estimated_error(estimate);
    // Observers see the film at 1, 2, 4, ... batches (as render_pixels' passes), or after every
    // batch when checkpoints ask for a bound on the time between calls; their time is not counted.
    const bool power_of_two = (done_ & (done_ - 1)) == 0;
    if (settings_.on_pass && (power_of_two || settings_.max_pass_seconds > 0.0 || done_ == cap_)) {
        const auto before = std::chrono::steady_clock::now();
        settings_.on_pass(film.to_film(done_), done_, elapsed());
        start_ += std::chrono::steady_clock::now() - before;
    }
    if (stop_requested()) result.interrupted = true;
    if (result.interrupted || done_ >= cap_) return false;
    if (settings_.time_seconds > 0.0 && elapsed() >= settings_.time_seconds) return false;
    if (settings_.target_error > 0.0 && done_ >= MinimumSamplesForErrorEstimate && estimate >= 0.0 &&
        estimate <= settings_.target_error)
        return false;
    return true;
}

void SplatBatches::finish(const SplatFilm& film, RenderResult& result) {
    progress_.finish();
    result.image = film.mean();
    result.variance = film.variance_of_mean();
    result.samples_per_pixel = done_;
    result.seconds = elapsed();
    result.invalid_samples += film.invalid_splat_count();
    result.estimated_relative_mse = film.estimated_relative_mse();
    result.film = std::make_shared<const Film>(film.to_film(done_));
}

}  // namespace freezeray::ch04
