// An allocator for std::vector whose memory starts on a cache line (64 bytes): chapter 07's
// triangle packets are then read with aligned loads that never straddle two lines, and chapter
// 08's texture tiles each fill whole lines.
#pragma once

#include <cstddef>
#include <new>

namespace freezeray {

inline constexpr std::size_t CacheLineBytes = 64;

template <typename T>
struct CacheLineAllocator {
    using value_type = T;
    CacheLineAllocator() = default;
    template <typename U>
    CacheLineAllocator(const CacheLineAllocator<U>&) {}
    T* allocate(std::size_t n) { return static_cast<T*>(::operator new(n * sizeof(T), std::align_val_t(CacheLineBytes))); }
    void deallocate(T* p, std::size_t) { ::operator delete(p, std::align_val_t(CacheLineBytes)); }
    bool operator==(const CacheLineAllocator&) const { return true; }
};

}  // namespace freezeray
