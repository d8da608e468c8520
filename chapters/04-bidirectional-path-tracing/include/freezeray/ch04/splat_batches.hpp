// The bookkeeping between the batches of a splatting render (chapter 04's render_light_paths,
// chapter 05's Markov chains): the clock, the error estimate shown while rendering, the
// observers (checkpoints, convergence plots) at 1, 2, 4, ... batches, when to stop, and the
// result made from the film. A batch is one sample (light path, mutation) per pixel.
#pragma once

#include "freezeray/integrator.hpp"
#include "freezeray/ch04/splat_film.hpp"

#include <chrono>
#include <cstdint>

namespace freezeray::ch04 {

class SplatBatches {
public:
    // Starts the clock and the progress line for `pixels` samples per batch.
    SplatBatches(const RenderSettings& settings, Progress& progress, std::uint64_t pixels);

    // True while another batch may start: below the sample cap and no stop requested (a request
    // marks `result` interrupted).
    bool next_batch(RenderResult& result) const;
    // After a batch was added to the film: counts it, shows the estimate, calls the observers,
    // and returns false when the render is done (time, target error, stop request).
    bool batch_done(const SplatFilm& film, RenderResult& result);
    // Finishes the progress line and fills the result from the film: image, variance, the film
    // itself, batches (samples per pixel), time, invalid splats, estimated relMSE.
    void finish(const SplatFilm& film, RenderResult& result);

    std::uint64_t batches() const { return done_; }
    // Render time so far, not counting the observers.
    double elapsed() const;

private:
    bool stop_requested() const;

    const RenderSettings& settings_;
    Progress& progress_;
    std::uint64_t cap_;
    std::uint64_t done_ = 0;
    std::chrono::steady_clock::time_point start_;
};

}  // namespace freezeray::ch04
