// The parallel tile loop.
#include "freezeray/parallel.hpp"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace freezeray {

int resolve_thread_count(int requested) {
    if (requested > 0) return requested;
    const unsigned cores = std::thread::hardware_concurrency();
    return cores > 0 ? static_cast<int>(cores) : 1;
}

void parallel_for(std::size_t count, int threads, const std::function<void(std::size_t, int)>& work) {
    threads = std::max(1, std::min<int>(threads, static_cast<int>(std::max<std::size_t>(count, 1))));
    std::atomic<std::size_t> next{0};
    std::exception_ptr failure;
    std::mutex failure_mutex;
    auto worker = [&](int thread_index) {
        for (;;) {
            const std::size_t i = next.fetch_add(1);
            if (i >= count) return;
            try {
                work(i, thread_index);
            } catch (...) {
                std::lock_guard<std::mutex> lock(failure_mutex);
                if (!failure) failure = std::current_exception();
                next.store(count);  // the others stop after their current item
                return;
            }
        }
    };
    if (threads == 1) {
        worker(0);
    } else {
        std::vector<std::thread> pool;
        for (int t = 0; t < threads; ++t) pool.emplace_back(worker, t);
        for (std::thread& thread : pool) thread.join();
    }
    if (failure) std::rethrow_exception(failure);
}

void parallel_for_tiles(int width, int height, int tile_size, int threads,
                        const std::function<void(const Tile&, int thread_index)>& work) {
    const int tiles_x = (width + tile_size - 1) / tile_size;
    const int tiles_y = (height + tile_size - 1) / tile_size;
    parallel_for(static_cast<std::size_t>(tiles_x) * tiles_y, threads, [&](std::size_t i, int thread_index) {
        const int tx = static_cast<int>(i % tiles_x);
        const int ty = static_cast<int>(i / tiles_x);
        const Tile tile{tx * tile_size, ty * tile_size, std::min(width, (tx + 1) * tile_size),
                        std::min(height, (ty + 1) * tile_size)};
        work(tile, thread_index);
    });
}

}  // namespace freezeray
