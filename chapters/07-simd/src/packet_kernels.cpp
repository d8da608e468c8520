// Choosing a packet kernel at run time: the build holds one per instruction set, the processor
// says which it can run (CPUID, read by GCC's __builtin_cpu_supports, which also checks that the
// operating system saves the AVX and AVX-512 registers).
#include "freezeray/ch07/packet_kernels.hpp"

#include "freezeray/error.hpp"

#include <string>

namespace freezeray::ch07 {

PacketRay make_packet_ray(const Ray& ray, const RayShear& shear) {
    return {{ray.origin.x, ray.origin.y, ray.origin.z}, shear.kx, shear.ky, shear.kz,
            shear.sx, shear.sy, shear.sz, ray.tmax};
}

std::uint32_t first_lanes(std::uint32_t count) { return count >= 32 ? ~0u : (1u << count) - 1u; }

const std::vector<PacketKernel>& built_kernels() {
    static const std::vector<PacketKernel> kernels{
        {1, "scalar", intersect_packet_scalar},
#if defined(__x86_64__)
        {4, "SSE", intersect_packet_sse},
        {8, "AVX", intersect_packet_avx},
        {16, "AVX-512", intersect_packet_avx512},
#endif
    };
    return kernels;
}

bool cpu_runs(const PacketKernel& kernel) {
#if defined(__x86_64__)
    switch (kernel.width) {
        case 8: return __builtin_cpu_supports("avx");
        case 16: return __builtin_cpu_supports("avx512f");
        default: return true;  // scalar, and SSE2, which x86-64 requires
    }
#else
    return kernel.width == 1;
#endif
}

const PacketKernel& widest_kernel() {
    const std::vector<PacketKernel>& kernels = built_kernels();
    for (auto it = kernels.rbegin(); it != kernels.rend(); ++it)
        if (cpu_runs(*it)) return *it;
    return kernels.front();
}

std::string runnable_widths() {
    std::vector<int> widths;
    for (const PacketKernel& k : built_kernels())
        if (cpu_runs(k)) widths.push_back(k.width);
    std::string text;
    for (std::size_t i = 0; i < widths.size(); ++i)
        text += (i == 0 ? "" : i + 1 == widths.size() ? " and " : ", ") + std::to_string(widths[i]);
    return text;
}

const PacketKernel& kernel_of_width(int width, const std::string& where) {
    for (const PacketKernel& k : built_kernels()) {
        if (k.width != width) continue;
        if (!cpu_runs(k))
            throw InputError(where, "a width of " + std::to_string(width) + " needs " + k.instructions +
                                        ", which this processor lacks; it runs widths " + runnable_widths());
        return k;
    }
    throw InputError(where, "no kernel of width " + std::to_string(width) + "; this processor runs widths " +
                                runnable_widths() + " (0: the widest)");
}

}  // namespace freezeray::ch07
