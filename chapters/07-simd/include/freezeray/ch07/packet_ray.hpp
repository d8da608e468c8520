// What the vectorised triangle test reads and writes: plain data only, so that the kernels, each
// compiled for its own instruction set (packet_kernel_*.cpp), share no inline code with the
// rest of the renderer (see packet_kernel.hpp, "Why the kernels see only plain data").
#pragma once

#include <cstdint>

namespace freezeray::ch07 {

// The widest packet: 16 lanes of 32-bit floats fill one AVX-512 register.
inline constexpr int MaxLanes = 16;

// A ray as the watertight test uses it (Woop, Benthin and Wald 2013, section 3): its origin,
// the axis permutation that makes kz the direction's largest component, and the shear that turns
// the direction into +z. The same numbers as freezeray::RayShear, computed once per ray.
struct PacketRay {
    float origin[3];
    int kx, ky, kz;
    float sx, sy, sz;
    float tmax;
};

// The answer for one packet of W triangles. Bit i of a mask is lane i.
//  - hit_lanes: lanes whose triangle the ray hits in (0, tmax); t and the barycentric
//    coordinates of those lanes are written (the others' entries may be overwritten too: read
//    only the hit lanes').
//  - edge_lanes: lanes where a single-precision edge function is exactly zero; the scalar test
//    recomputes those in double precision (triangle_intersection.hpp) and decides them.
// A lane is in at most one of the two masks; padded lanes are in neither.
struct alignas(64) PacketHits {
    std::uint32_t hit_lanes = 0;
    std::uint32_t edge_lanes = 0;
    alignas(64) float t[MaxLanes];
    alignas(64) float b0[MaxLanes];
    alignas(64) float b1[MaxLanes];
    alignas(64) float b2[MaxLanes];
};

// A packet's coordinates, structure of arrays: for vertex v (0, 1, 2) and axis a (x, y, z), the W
// lanes' values are the W floats at coordinates + (3 v + a) W. 9 W floats, 64-byte aligned.
inline constexpr int packet_floats(int width) { return 9 * width; }

// Tests a ray against one packet. `valid_lanes` has a bit for each lane that holds a triangle
// (the lanes of a leaf's last packet beyond its triangles are padding).
using PacketTest = void (*)(const PacketRay& ray, const float* coordinates, std::uint32_t valid_lanes, PacketHits& hits);

}  // namespace freezeray::ch07
