// The deterministic parallel tile loop: the image is cut into square tiles and the threads take
// tiles from a shared counter. Which thread renders a tile changes from run to run; what is
// computed for a pixel does not, since its random streams depend only on (seed, pixel, sample).
#pragma once

#include <functional>

namespace freezeray {

struct Tile {
    int x0, y0, x1, y1;  // pixels [x0, x1) x [y0, y1)
};

// Number of threads to use: `requested` if positive, else every core.
int resolve_thread_count(int requested);

// Calls work(tile, thread_index) for every tile of a width x height image, on `threads` threads,
// and returns when all are done. An exception thrown by `work` is rethrown here.
void parallel_for_tiles(int width, int height, int tile_size, int threads,
                        const std::function<void(const Tile&, int thread_index)>& work);

// Calls work(i, thread_index) for i in [0, count) in parallel (chunks from a shared counter).
void parallel_for(std::size_t count, int threads, const std::function<void(std::size_t, int)>& work);

}  // namespace freezeray
