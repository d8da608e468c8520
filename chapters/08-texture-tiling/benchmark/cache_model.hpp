// A model of a processor's data caches for texture-benchmark: set-associative, least recently used
// replacement, 64-byte lines, three levels each holding what the level above holds (inclusive).
// Fed with the cache lines a texture lookup reads, and nothing else, it counts the misses the
// texture alone causes: what `perf stat` would count on a machine that exposes its counters
// (this one does not: a virtual machine), without the rest of the program's traffic. A model,
// not the real caches: their replacement policies and prefetchers differ, so its counts say which
// layout touches fewer lines, not how many nanoseconds a lookup takes.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace freezeray::ch08 {

class CacheLevelModel {
public:
    // `bytes` of capacity in sets of `ways` lines of 64 bytes.
    CacheLevelModel(std::size_t bytes, int ways)
        : ways_(static_cast<std::size_t>(ways)), sets_(std::max<std::size_t>(1, bytes / 64 / static_cast<std::size_t>(ways))),
          tags_(sets_ * ways_, Empty) {}

    // Reads `line` (an address divided by 64): true when it was held, else it is brought in,
    // evicting the set's least recently used line.
    bool access(std::uintptr_t line) {
        std::uintptr_t* set = &tags_[(line % sets_) * ways_];  // most recent first
        std::size_t i = 0;
        while (i < ways_ && set[i] != line) ++i;
        const bool hit = i < ways_;
        if (!hit) i = ways_ - 1;
        std::copy_backward(set, set + i, set + i + 1);
        set[0] = line;
        return hit;
    }

private:
    static constexpr std::uintptr_t Empty = ~std::uintptr_t{0};
    std::size_t ways_;
    std::size_t sets_;
    std::vector<std::uintptr_t> tags_;
};

// L1, L2 and L3 of a common server core (32 KiB 8-way, 1 MiB 8-way, 32 MiB 16-way: what lscpu
// reported on the machine of the first measurements; processors differ, and the model is
// fixed so that its counts compare across machines); misses of each level counted.
struct CacheHierarchyModel {
    CacheLevelModel l1{32 * 1024, 8};
    CacheLevelModel l2{1024 * 1024, 8};
    CacheLevelModel l3{32 * 1024 * 1024, 16};
    std::uint64_t reads = 0, l1_misses = 0, l2_misses = 0, l3_misses = 0;

    void read(std::uintptr_t line) {
        ++reads;
        if (l1.access(line)) return;
        ++l1_misses;
        if (l2.access(line)) return;
        ++l2_misses;
        if (!l3.access(line)) ++l3_misses;
    }
};

}  // namespace freezeray::ch08
