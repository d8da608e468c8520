// Measuring ray throughput: one batch through one accelerator on N threads, timed over
// repeated runs.
#pragma once

#include "ray_answers.hpp"
#include "ray_batch.hpp"

#include "freezeray/accelerator.hpp"

#include <cstddef>
#include <vector>

namespace freezeray::benchmark {

struct ThroughputMeasurement {
    std::vector<double> run_seconds;  // each timed run, in order
    double median_seconds = 0.0;
    RayAnswers answers;               // of the last run (every run gives the same answers)

    // Millions of rays per second at the median time; 0 for an empty batch.
    double mrays_per_second(std::size_t ray_count) const;
};

// Rays a thread takes at once: small enough that the threads finish together (rays differ in
// cost by orders of magnitude, and neighbouring rays alike: a fixed half of the batch each leaves
// one thread idle while the other traces the harder half), large enough that taking a chunk
// (one atomic add) costs nothing beside tracing it.
inline constexpr std::size_t ChunkRays = 1024;

// Traces the batch (Accelerator::intersect, or occluded for shadow rays) once to warm caches and
// branch predictors up, then `repetitions` times timed, and returns the median time. intersect
// fills in a whole Hit, as the renderer needs: that is part of what is measured. With several
// threads (one std::thread each), each takes the next chunk of ChunkRays consecutive rays until
// none is left, so that they finish together, as a renderer's threads take tiles.
ThroughputMeasurement measure_throughput(const Accelerator& accelerator, const std::vector<Ray>& rays, RayKind kind,
                                         int threads, int repetitions);

// The median of the values (the mean of the middle two for an even count); 0 when empty.
double median(std::vector<double> values);

}  // namespace freezeray::benchmark
