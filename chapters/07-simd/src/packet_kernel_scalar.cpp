// The packet test with one lane (W = 1): plain floats, for the book and for machines without the
// vector instructions of the other kernels. The same template as the wide kernels, so the scalar
// and the vector code cannot drift apart.
#include "freezeray/ch07/packet_kernels.hpp"

#include "freezeray/ch07/packet_kernel.hpp"

#include <algorithm>
#include <cmath>

namespace freezeray::ch07 {

namespace {

struct ScalarMask {
    bool lane;
    static ScalarMask all() { return {true}; }
};
ScalarMask operator&(ScalarMask a, ScalarMask b) { return {a.lane && b.lane}; }
ScalarMask operator|(ScalarMask a, ScalarMask b) { return {a.lane || b.lane}; }
ScalarMask and_not(ScalarMask a, ScalarMask b) { return {a.lane && !b.lane}; }
std::uint32_t bits(ScalarMask m) { return m.lane ? 1u : 0u; }

struct ScalarLanes {
    using Mask = ScalarMask;
    static constexpr int width = 1;
    float value;
    static ScalarLanes load(const float* p) { return {*p}; }
    static ScalarLanes broadcast(float x) { return {x}; }
    void store(float* p) const { *p = value; }
};
ScalarLanes operator+(ScalarLanes a, ScalarLanes b) { return {a.value + b.value}; }
ScalarLanes operator-(ScalarLanes a, ScalarLanes b) { return {a.value - b.value}; }
ScalarLanes operator*(ScalarLanes a, ScalarLanes b) { return {a.value * b.value}; }
ScalarLanes operator/(ScalarLanes a, ScalarLanes b) { return {a.value / b.value}; }
ScalarLanes abs(ScalarLanes a) { return {std::fabs(a.value)}; }
ScalarLanes max(ScalarLanes a, ScalarLanes b) { return {std::max(a.value, b.value)}; }
ScalarMask operator<(ScalarLanes a, ScalarLanes b) { return {a.value < b.value}; }
ScalarMask operator<=(ScalarLanes a, ScalarLanes b) { return {a.value <= b.value}; }
ScalarMask operator>(ScalarLanes a, ScalarLanes b) { return {a.value > b.value}; }
ScalarMask operator>=(ScalarLanes a, ScalarLanes b) { return {a.value >= b.value}; }
ScalarMask operator==(ScalarLanes a, ScalarLanes b) { return {a.value == b.value}; }

}  // namespace

void intersect_packet_scalar(const PacketRay& ray, const float* coordinates, std::uint32_t valid_lanes, PacketHits& hits) {
    intersect_packet<ScalarLanes>(ray, coordinates, valid_lanes, hits);
}

}  // namespace freezeray::ch07
