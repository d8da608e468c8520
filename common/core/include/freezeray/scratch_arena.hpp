// Per-thread scratch memory for objects that live for one path (BSDFs built at a hit), so that
// tracing a ray never touches the heap.
#pragma once

#include "freezeray/cache_line_allocator.hpp"

#include <cstddef>
#include <memory>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

namespace freezeray {

// Aligned to a cache line, so that the render threads' arenas, which sit side by side in one
// vector and move their `used_` on every allocation, never share a line (see Sampler).
class alignas(CacheLineBytes) ScratchArena {
public:
    explicit ScratchArena(std::size_t bytes = 64 * 1024) : buffer_(new std::byte[bytes]), capacity_(bytes) {}

    // Constructs a T in the arena. T must be trivially destructible or not need its destructor:
    // reset() frees everything at once without calling destructors.
    template <typename T, typename... Args>
    T* make(Args&&... args) {
        static_assert(std::is_trivially_destructible_v<T> || std::has_virtual_destructor_v<T>,
                      "arena objects are never destroyed individually");
        void* p = allocate(sizeof(T), alignof(T));
        return new (p) T(std::forward<Args>(args)...);
    }

    // Forgets every allocation; call once per path.
    void reset() { used_ = 0; }

    std::size_t used() const { return used_; }

private:
    void* allocate(std::size_t size, std::size_t alignment) {
        std::size_t start = (used_ + alignment - 1) & ~(alignment - 1);
        if (start + size > capacity_) throw std::bad_alloc();
        used_ = start + size;
        return buffer_.get() + start;
    }

    std::unique_ptr<std::byte[]> buffer_;
    std::size_t capacity_;
    std::size_t used_ = 0;
};

}  // namespace freezeray
