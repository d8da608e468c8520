// What an accelerator found for the closest-hit rays of a batch, and its file format FRHITS01,
// so that two ray tracers' answers can be compared ray by ray.
//
// FRHITS01 (little-endian, packed): char[8] "FRHITS01", uint32 Na, Nb, triangle count, then for
// each of the Na primary and then the Nb diffuse rays: int32 triangle (-1 for a miss) and
// float32 t (+inf for a miss). Triangle indices are those of load_benchmark_mesh.
#pragma once

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace freezeray::benchmark {

struct ClosestHit {
    std::int32_t triangle = -1;                           // -1: the ray hits nothing
    float t = std::numeric_limits<float>::infinity();     // +inf for a miss

    bool is_miss() const { return triangle < 0; }
    bool operator==(const ClosestHit&) const = default;
};

struct HitFile {
    std::uint32_t triangle_count = 0;  // of the mesh the hits refer to
    std::vector<ClosestHit> primary;
    std::vector<ClosestHit> diffuse;
};

inline constexpr std::size_t HitFileHeaderBytes = 8 + 3 * 4;
inline constexpr std::size_t HitRecordBytes = 4 + 4;

// Writes FRHITS01 atomically. Throws InputError when the file cannot be written.
void write_hit_file(const std::string& path, const HitFile& hits);

// Reads FRHITS01. Refuses, naming the file and the record: a wrong magic, a size that disagrees
// with the counts, a triangle index below -1 or not below the triangle count, a miss whose t is
// not +inf, a hit whose t is not finite and positive.
HitFile read_hit_file(const std::string& path);

}  // namespace freezeray::benchmark
