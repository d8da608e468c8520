// The packet test on 16 lanes with AVX-512. This file alone is compiled with -mavx512f
// (CMakeLists.txt), and its function is called only when the processor reports AVX-512F
// (packet_kernels.cpp). AVX-512 comparisons give a mask register of 16 bits, not a vector.
#include "freezeray/ch07/packet_kernels.hpp"

#include "freezeray/ch07/packet_kernel.hpp"

#include <immintrin.h>

namespace freezeray::ch07 {

namespace {

struct Avx512Mask {
    __mmask16 lanes;
    static Avx512Mask all() { return {static_cast<__mmask16>(0xffff)}; }
};
Avx512Mask operator&(Avx512Mask a, Avx512Mask b) { return {static_cast<__mmask16>(a.lanes & b.lanes)}; }
Avx512Mask operator|(Avx512Mask a, Avx512Mask b) { return {static_cast<__mmask16>(a.lanes | b.lanes)}; }
Avx512Mask and_not(Avx512Mask a, Avx512Mask b) { return {static_cast<__mmask16>(a.lanes & ~b.lanes)}; }
std::uint32_t bits(Avx512Mask m) { return m.lanes; }

struct Avx512Lanes {
    using Mask = Avx512Mask;
    static constexpr int width = 16;
    __m512 lanes;
    static Avx512Lanes load(const float* p) { return {_mm512_load_ps(p)}; }
    static Avx512Lanes broadcast(float x) { return {_mm512_set1_ps(x)}; }
    void store(float* p) const { _mm512_store_ps(p, lanes); }
};
Avx512Lanes operator+(Avx512Lanes a, Avx512Lanes b) { return {_mm512_add_ps(a.lanes, b.lanes)}; }
Avx512Lanes operator-(Avx512Lanes a, Avx512Lanes b) { return {_mm512_sub_ps(a.lanes, b.lanes)}; }
Avx512Lanes operator*(Avx512Lanes a, Avx512Lanes b) { return {_mm512_mul_ps(a.lanes, b.lanes)}; }
Avx512Lanes operator/(Avx512Lanes a, Avx512Lanes b) { return {_mm512_div_ps(a.lanes, b.lanes)}; }
Avx512Lanes abs(Avx512Lanes a) { return {_mm512_abs_ps(a.lanes)}; }
// The zero-masked form, with every lane selected: the same maximum, and it spares g++ 12 a false
// "may be used uninitialized" warning inside _mm512_max_ps.
Avx512Lanes max(Avx512Lanes a, Avx512Lanes b) { return {_mm512_maskz_max_ps(0xffff, a.lanes, b.lanes)}; }
Avx512Mask operator<(Avx512Lanes a, Avx512Lanes b) { return {_mm512_cmp_ps_mask(a.lanes, b.lanes, _CMP_LT_OQ)}; }
Avx512Mask operator<=(Avx512Lanes a, Avx512Lanes b) { return {_mm512_cmp_ps_mask(a.lanes, b.lanes, _CMP_LE_OQ)}; }
Avx512Mask operator>(Avx512Lanes a, Avx512Lanes b) { return {_mm512_cmp_ps_mask(a.lanes, b.lanes, _CMP_GT_OQ)}; }
Avx512Mask operator>=(Avx512Lanes a, Avx512Lanes b) { return {_mm512_cmp_ps_mask(a.lanes, b.lanes, _CMP_GE_OQ)}; }
Avx512Mask operator==(Avx512Lanes a, Avx512Lanes b) { return {_mm512_cmp_ps_mask(a.lanes, b.lanes, _CMP_EQ_OQ)}; }

}  // namespace

void intersect_packet_avx512(const PacketRay& ray, const float* coordinates, std::uint32_t valid_lanes, PacketHits& hits) {
    intersect_packet<Avx512Lanes>(ray, coordinates, valid_lanes, hits);
}

}  // namespace freezeray::ch07
