// Timing batches of rays over threads that take chunks of the batch as they go.
#include "throughput.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <thread>

namespace freezeray::benchmark {

namespace {

// The triangle and distance of the closest hit; triangle indices are those of the one benchmark
// mesh (mesh 0).
ClosestHit closest_hit(const Accelerator& accelerator, const Ray& ray) {
    const std::optional<Hit> hit = accelerator.intersect(ray);
    if (!hit) return ClosestHit{};
    return ClosestHit{static_cast<std::int32_t>(hit->triangle), hit->t};
}

// One run over the whole batch; answers are written into the preallocated vectors, each chunk
// by the one thread that took it, so that nothing is shared but read-only data and the counter.
void trace_batch(const Accelerator& accelerator, const std::vector<Ray>& rays, RayKind kind, int threads,
                 RayAnswers& answers) {
    const std::size_t count = rays.size();
    auto trace_range = [&](std::size_t first, std::size_t last) {
        if (asks_for_closest_hit(kind)) {
            for (std::size_t i = first; i < last; ++i) answers.closest[i] = closest_hit(accelerator, rays[i]);
        } else {
            for (std::size_t i = first; i < last; ++i) answers.occluded[i] = accelerator.occluded(rays[i]) ? 1 : 0;
        }
    };
    if (threads <= 1) {
        trace_range(0, count);
        return;
    }
    std::atomic<std::size_t> next_chunk{0};
    auto trace_chunks = [&] {
        for (;;) {
            const std::size_t first = next_chunk.fetch_add(ChunkRays, std::memory_order_relaxed);
            if (first >= count) return;
            trace_range(first, std::min(count, first + ChunkRays));
        }
    };
    std::vector<std::thread> pool;
    pool.reserve(static_cast<std::size_t>(threads));
    for (int t = 0; t < threads; ++t) pool.emplace_back(trace_chunks);
    for (std::thread& thread : pool) thread.join();
}

}  // namespace

double ThroughputMeasurement::mrays_per_second(std::size_t ray_count) const {
    if (ray_count == 0 || median_seconds <= 0.0) return 0.0;
    return static_cast<double>(ray_count) / median_seconds * 1e-6;
}

double median(std::vector<double> values) {
    if (values.empty()) return 0.0;
    std::sort(values.begin(), values.end());
    const std::size_t middle = values.size() / 2;
    return values.size() % 2 == 1 ? values[middle] : 0.5 * (values[middle - 1] + values[middle]);
}

ThroughputMeasurement measure_throughput(const Accelerator& accelerator, const std::vector<Ray>& rays, RayKind kind,
                                         int threads, int repetitions) {
    ThroughputMeasurement measurement;
    if (asks_for_closest_hit(kind))
        measurement.answers.closest.assign(rays.size(), ClosestHit{});
    else
        measurement.answers.occluded.assign(rays.size(), 0);

    trace_batch(accelerator, rays, kind, threads, measurement.answers);  // warm-up, not timed
    for (int run = 0; run < repetitions; ++run) {
        const auto start = std::chrono::steady_clock::now();
        trace_batch(accelerator, rays, kind, threads, measurement.answers);
        const auto stop = std::chrono::steady_clock::now();
        measurement.run_seconds.push_back(std::chrono::duration<double>(stop - start).count());
    }
    measurement.median_seconds = median(measurement.run_seconds);
    return measurement;
}

}  // namespace freezeray::benchmark
