// The packet test on 8 lanes with AVX. This file alone is compiled with -mavx (CMakeLists.txt),
// and its function is called only when the processor reports AVX (packet_kernels.cpp).
#include "freezeray/ch07/packet_kernels.hpp"

#include "freezeray/ch07/packet_kernel.hpp"

#include <immintrin.h>

namespace freezeray::ch07 {

namespace {

struct AvxMask {
    __m256 lanes;
    static AvxMask all() { return {_mm256_castsi256_ps(_mm256_set1_epi32(-1))}; }
};
AvxMask operator&(AvxMask a, AvxMask b) { return {_mm256_and_ps(a.lanes, b.lanes)}; }
AvxMask operator|(AvxMask a, AvxMask b) { return {_mm256_or_ps(a.lanes, b.lanes)}; }
AvxMask and_not(AvxMask a, AvxMask b) { return {_mm256_andnot_ps(b.lanes, a.lanes)}; }
std::uint32_t bits(AvxMask m) { return static_cast<std::uint32_t>(_mm256_movemask_ps(m.lanes)); }

struct AvxLanes {
    using Mask = AvxMask;
    static constexpr int width = 8;
    __m256 lanes;
    static AvxLanes load(const float* p) { return {_mm256_load_ps(p)}; }
    static AvxLanes broadcast(float x) { return {_mm256_set1_ps(x)}; }
    void store(float* p) const { _mm256_store_ps(p, lanes); }
};
AvxLanes operator+(AvxLanes a, AvxLanes b) { return {_mm256_add_ps(a.lanes, b.lanes)}; }
AvxLanes operator-(AvxLanes a, AvxLanes b) { return {_mm256_sub_ps(a.lanes, b.lanes)}; }
AvxLanes operator*(AvxLanes a, AvxLanes b) { return {_mm256_mul_ps(a.lanes, b.lanes)}; }
AvxLanes operator/(AvxLanes a, AvxLanes b) { return {_mm256_div_ps(a.lanes, b.lanes)}; }
AvxLanes abs(AvxLanes a) { return {_mm256_andnot_ps(_mm256_set1_ps(-0.0f), a.lanes)}; }
AvxLanes max(AvxLanes a, AvxLanes b) { return {_mm256_max_ps(a.lanes, b.lanes)}; }
// The ordered, non-signalling predicates: false where a lane is NaN, as C++'s comparisons.
AvxMask operator<(AvxLanes a, AvxLanes b) { return {_mm256_cmp_ps(a.lanes, b.lanes, _CMP_LT_OQ)}; }
AvxMask operator<=(AvxLanes a, AvxLanes b) { return {_mm256_cmp_ps(a.lanes, b.lanes, _CMP_LE_OQ)}; }
AvxMask operator>(AvxLanes a, AvxLanes b) { return {_mm256_cmp_ps(a.lanes, b.lanes, _CMP_GT_OQ)}; }
AvxMask operator>=(AvxLanes a, AvxLanes b) { return {_mm256_cmp_ps(a.lanes, b.lanes, _CMP_GE_OQ)}; }
AvxMask operator==(AvxLanes a, AvxLanes b) { return {_mm256_cmp_ps(a.lanes, b.lanes, _CMP_EQ_OQ)}; }

}  // namespace

void intersect_packet_avx(const PacketRay& ray, const float* coordinates, std::uint32_t valid_lanes, PacketHits& hits) {
    intersect_packet<AvxLanes>(ray, coordinates, valid_lanes, hits);
}

}  // namespace freezeray::ch07
