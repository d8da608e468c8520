// Batches of rays for measuring accelerators, and their file format FRRAYS01, so that every
// accelerator (and any other ray tracer) is measured on exactly the same rays.
//
// FRRAYS01 (little-endian, packed): char[8] "FRRAYS01", uint32 Na, Nb, Nc, then Na + Nb + Nc
// records of 29 bytes: float32 ox oy oz dx dy dz tmax, uint8 tag (0 primary, 1 diffuse,
// 2 shadow), the Na primary rays first, then the Nb diffuse, then the Nc shadow rays. tnear is 0.
// Primary and diffuse rays ask for the closest hit, shadow rays whether anything lies on the
// ray before tmax.
#pragma once

#include "freezeray/ray.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace freezeray::benchmark {

// The tag of a record; the order of the batches in a file.
enum class RayKind : std::uint8_t { Primary = 0, Diffuse = 1, Shadow = 2 };

inline constexpr std::array<RayKind, 3> all_ray_kinds = {RayKind::Primary, RayKind::Diffuse, RayKind::Shadow};

// "primary", "diffuse", "shadow".
const char* ray_kind_name(RayKind kind);

// Shadow rays ask "is anything in the way?" (Accelerator::occluded); the others the closest hit.
inline bool asks_for_closest_hit(RayKind kind) { return kind != RayKind::Shadow; }

struct RayBatches {
    std::array<std::vector<Ray>, 3> rays;  // indexed by RayKind

    std::vector<Ray>& of(RayKind kind) { return rays[static_cast<std::size_t>(kind)]; }
    const std::vector<Ray>& of(RayKind kind) const { return rays[static_cast<std::size_t>(kind)]; }

    // Keeps the first `count` rays of each kind.
    void keep_first(std::size_t count);
};

inline constexpr std::size_t RayFileHeaderBytes = 8 + 3 * 4;
inline constexpr std::size_t RayRecordBytes = 7 * 4 + 1;

// Writes the batches as FRRAYS01, atomically. Throws InputError when the file cannot be written
// or a batch has more than 2^32 - 1 rays.
void write_ray_batches(const std::string& path, const RayBatches& batches);

// Reads an FRRAYS01 file. Refuses, with an InputError naming the file and the record (numbered
// from 0, with its byte offset): a wrong magic, a file shorter or longer than its counts say, a
// tag out of range or out of the place its counts give it, a non-finite origin or direction, a
// direction that is not unit length (within 1e-3), a tmax that is NaN or not positive.
RayBatches read_ray_batches(const std::string& path);

}  // namespace freezeray::benchmark
