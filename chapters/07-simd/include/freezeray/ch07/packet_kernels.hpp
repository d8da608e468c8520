// The packet tests for each width, and the choice among them by what the processor can run.
#pragma once

#include "freezeray/ch07/packet_ray.hpp"
#include "freezeray/ray.hpp"
#include "freezeray/triangle_intersection.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace freezeray::ch07 {

// One kernel per width, each in its own file (packet_kernel_*.cpp). The AVX and AVX-512 ones
// exist only in builds for x86-64 and may be called only where cpu_runs() says so.
void intersect_packet_scalar(const PacketRay& ray, const float* coordinates, std::uint32_t valid_lanes, PacketHits& hits);
void intersect_packet_sse(const PacketRay& ray, const float* coordinates, std::uint32_t valid_lanes, PacketHits& hits);
void intersect_packet_avx(const PacketRay& ray, const float* coordinates, std::uint32_t valid_lanes, PacketHits& hits);
void intersect_packet_avx512(const PacketRay& ray, const float* coordinates, std::uint32_t valid_lanes, PacketHits& hits);

// The ray as the kernels read it: its origin and tmax, and the permutation and shear of `shear`.
// (Defined in packet_kernels.cpp, compiled with the default flags, as everything outside the
// kernels' own files.)
PacketRay make_packet_ray(const Ray& ray, const RayShear& shear);

// The mask of a packet's first `count` lanes: those that hold a triangle.
std::uint32_t first_lanes(std::uint32_t count);

struct PacketKernel {
    int width;                 // lanes: 1, 4, 8 or 16
    const char* instructions;  // "scalar", "SSE", "AVX", "AVX-512"
    PacketTest test;
};

// The kernels this build holds, narrowest first (on x86-64: 1, 4, 8, 16).
const std::vector<PacketKernel>& built_kernels();

// Whether this processor (and its operating system, which must save the wide registers) can run
// the kernel.
bool cpu_runs(const PacketKernel& kernel);

// The widest kernel this processor runs.
const PacketKernel& widest_kernel();

// The kernel of `width` lanes; throws InputError at `where` when the build has none of that
// width or this processor cannot run it (the message lists the widths it can).
const PacketKernel& kernel_of_width(int width, const std::string& where);

// "1, 4, 8 and 16": the widths this processor runs.
std::string runnable_widths();

}  // namespace freezeray::ch07
