// The packet test on 4 lanes with SSE, which every x86-64 processor has (SSE and SSE2 are part of
// the architecture): the baseline of the wide kernels. Compiled with the project's default flags.
#include "freezeray/ch07/packet_kernels.hpp"

#include "freezeray/ch07/packet_kernel.hpp"

#include <immintrin.h>

namespace freezeray::ch07 {

namespace {

// A mask is a register of 4 lanes, each all ones (true) or all zeros (false), as SSE's comparisons
// give it.
struct SseMask {
    __m128 lanes;
    static SseMask all() { return {_mm_castsi128_ps(_mm_set1_epi32(-1))}; }
};
SseMask operator&(SseMask a, SseMask b) { return {_mm_and_ps(a.lanes, b.lanes)}; }
SseMask operator|(SseMask a, SseMask b) { return {_mm_or_ps(a.lanes, b.lanes)}; }
SseMask and_not(SseMask a, SseMask b) { return {_mm_andnot_ps(b.lanes, a.lanes)}; }
std::uint32_t bits(SseMask m) { return static_cast<std::uint32_t>(_mm_movemask_ps(m.lanes)); }

struct SseLanes {
    using Mask = SseMask;
    static constexpr int width = 4;
    __m128 lanes;
    static SseLanes load(const float* p) { return {_mm_load_ps(p)}; }
    static SseLanes broadcast(float x) { return {_mm_set1_ps(x)}; }
    void store(float* p) const { _mm_store_ps(p, lanes); }
};
SseLanes operator+(SseLanes a, SseLanes b) { return {_mm_add_ps(a.lanes, b.lanes)}; }
SseLanes operator-(SseLanes a, SseLanes b) { return {_mm_sub_ps(a.lanes, b.lanes)}; }
SseLanes operator*(SseLanes a, SseLanes b) { return {_mm_mul_ps(a.lanes, b.lanes)}; }
SseLanes operator/(SseLanes a, SseLanes b) { return {_mm_div_ps(a.lanes, b.lanes)}; }
// |x|: the sign bit cleared.
SseLanes abs(SseLanes a) { return {_mm_andnot_ps(_mm_set1_ps(-0.0f), a.lanes)}; }
SseLanes max(SseLanes a, SseLanes b) { return {_mm_max_ps(a.lanes, b.lanes)}; }
SseMask operator<(SseLanes a, SseLanes b) { return {_mm_cmplt_ps(a.lanes, b.lanes)}; }
SseMask operator<=(SseLanes a, SseLanes b) { return {_mm_cmple_ps(a.lanes, b.lanes)}; }
SseMask operator>(SseLanes a, SseLanes b) { return {_mm_cmpgt_ps(a.lanes, b.lanes)}; }
SseMask operator>=(SseLanes a, SseLanes b) { return {_mm_cmpge_ps(a.lanes, b.lanes)}; }
SseMask operator==(SseLanes a, SseLanes b) { return {_mm_cmpeq_ps(a.lanes, b.lanes)}; }

}  // namespace

void intersect_packet_sse(const PacketRay& ray, const float* coordinates, std::uint32_t valid_lanes, PacketHits& hits) {
    intersect_packet<SseLanes>(ray, coordinates, valid_lanes, hits);
}

}  // namespace freezeray::ch07
