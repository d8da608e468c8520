// The watertight ray-triangle test for W triangles at once (Woop, Benthin and Wald, "Watertight
// Ray/Triangle Intersection", JCGT 2(1), 2013), written once over a type of W float lanes.
//
// Each instruction set gets its own translation unit (packet_kernel_sse.cpp, _avx.cpp,
// _avx512.cpp, and _scalar.cpp with one lane), compiled with that set's flags, which defines a
// `Lanes` type in an anonymous namespace and instantiates intersect_packet<Lanes> there.
//
// Why the kernels see only plain data. A translation unit compiled with -mavx512f may encode any
// inline function it emits with AVX-512 instructions, and where several units emit the same
// inline function the linker keeps one copy for all of them: a std:: or glm helper emitted from
// the AVX-512 unit could then run on a machine without AVX-512 and crash it. So the kernels call
// no inline function of external linkage at run time: they read PacketRay and the packet's floats
// and write PacketHits (packet_ray.hpp), and the one include below is used only for constants
// evaluated by the compiler.
//
// Why the answer is the scalar test's to the bit. Every lane performs the same IEEE operations in
// the same order as intersect_triangle (triangle_intersection.hpp): a packet holds the three
// vertices as they are, not a vertex and two edges, since p0 + (p1 - p0) is not always p1 in
// floating point; the division is a division, not the approximate reciprocal (rcpps, 12 bits);
// and the project compiles with -ffp-contract=off, so that no a * b + c is fused into one
// rounding in one path and not in the other. Lanes whose edge functions are exactly zero, where
// the scalar test recomputes in double precision and applies its tie-breaking rule, are handed
// back to the scalar test (edge_lanes).
#pragma once

#include "freezeray/ch07/packet_ray.hpp"
#include "freezeray/triangle_intersection.hpp"  // only triangle_detail::gamma_bound, at compile time

#include <cstdint>

namespace freezeray::ch07 {

// A `Lanes` type has: width; load (aligned), broadcast, store; + - * /; abs and max; the six
// comparisons < <= > >= == giving a Mask (ordered: false where a lane is NaN, as in scalar C++);
// a Mask has &, | and and_not(a, b) = a & ~b, and bits(mask) gives its lanes as an integer.

// BOOK(packet-inside-mask)
// The lanes where the ray passes inside the triangle: the three edge functions have the same
// sign, either both all >= 0 or all <= 0, so that either winding is accepted (the scalar test
// rejects a lane where some are negative and some positive).
template <typename Lanes, typename Mask>
Mask inside_lanes(const Lanes& u, const Lanes& v, const Lanes& w) {
    // EXERCISE(ch07/inside-mask): the lanes whose ray passes inside (or on the edge of) the triangle, from the signs of u, v and w as book chapter 07, "The watertight test, W at a time", decides it
    const Lanes zero = Lanes::broadcast(0.0f);
    const Mask some_negative = (u < zero) | (v < zero) | (w < zero);
    const Mask some_positive = (u > zero) | (v > zero) | (w > zero);
    return and_not(Mask::all(), some_negative & some_positive);
    // END EXERCISE
}
// END BOOK

// BOOK(intersect-packet)
// Tests the ray against the packet's W triangles; see PacketHits for what is written.
// The contract, lane by lane, for each lane whose bit is set in valid_lanes (the others are
// padding: in neither mask, whatever their coordinates):
// - edge_lanes: the lanes where one of the three edge functions, computed in single precision as
//   intersect_triangle computes them (same operations, same order), is exactly zero;
// - hit_lanes: the other lanes whose triangle intersect_triangle would hit in (0, tmax), with
//   t, b0, b1 and b2 in those lanes of `hits` equal to its answer to the bit; no lane in both.
// The entries of t and the barycentrics in other lanes may be overwritten. To be bit-identical,
// every lane performs intersect_triangle's IEEE operations in its order: the same shear of the
// vertices relative to the origin, the sign test (inside_lanes), the scaled distance against
// the interval before dividing, a true division, and the conservative rejection of t near 0.
template <typename Lanes>
void intersect_packet(const PacketRay& ray, const float* coordinates, std::uint32_t valid_lanes, PacketHits& hits) {
    // EXERCISE(ch07/packet-kernel): the watertight test of book chapter 07, "The watertight test, W at a time", on W lanes at once, as intersect_packet's comment in packet_kernel.hpp states its contract: every valid lane answers as intersect_triangle does, to the bit, lanes on an edge handed back, padding never reported
    using Mask = typename Lanes::Mask;
    constexpr int W = Lanes::width;
    // Vertex `vertex`'s coordinate on `axis`, relative to the ray's origin, in W lanes.
    auto relative = [&](int vertex, int axis) {
        return Lanes::load(coordinates + (3 * vertex + axis) * W) - Lanes::broadcast(ray.origin[axis]);
    };
    const Lanes sx = Lanes::broadcast(ray.sx), sy = Lanes::broadcast(ray.sy), sz = Lanes::broadcast(ray.sz);

    // Sheared so the ray runs along +z (paper, figure 2), as in the scalar test.
    const Lanes a_z = relative(0, ray.kz), b_z = relative(1, ray.kz), c_z = relative(2, ray.kz);
    const Lanes ax = relative(0, ray.kx) - sx * a_z, ay = relative(0, ray.ky) - sy * a_z;
    const Lanes bx = relative(1, ray.kx) - sx * b_z, by = relative(1, ray.ky) - sy * b_z;
    const Lanes cx = relative(2, ray.kx) - sx * c_z, cy = relative(2, ray.ky) - sy * c_z;

    // The edge functions (scaled barycentric coordinates).
    const Lanes u = cx * by - cy * bx;
    const Lanes v = ax * cy - ay * cx;
    const Lanes w = bx * ay - by * ax;

    const Lanes zero = Lanes::broadcast(0.0f);
    const std::uint32_t on_edge = bits((u == zero) | (v == zero) | (w == zero)) & valid_lanes;
    hits.edge_lanes = on_edge;
    std::uint32_t candidates = bits(inside_lanes<Lanes, Mask>(u, v, w)) & valid_lanes & ~on_edge;
    if (candidates == 0) {
        hits.hit_lanes = 0;
        return;
    }

    const Lanes det = u + v + w;
    const Lanes az = sz * a_z, bz = sz * b_z, cz = sz * c_z;
    const Lanes t_scaled = u * az + v * bz + w * cz;
    // The scaled distance against (0, tmax * det) before dividing (paper, section 3.3).
    const Lanes tmax = Lanes::broadcast(ray.tmax);
    const Lanes tmax_det = tmax * det;
    const Mask beyond = ((det < zero) & ((t_scaled >= zero) | (t_scaled < tmax_det))) |
                        ((det > zero) & ((t_scaled <= zero) | (t_scaled > tmax_det)));
    candidates &= ~bits((det == zero) | beyond);
    if (candidates == 0) {
        hits.hit_lanes = 0;
        return;
    }

    const Lanes inverse_det = Lanes::broadcast(1.0f) / det;
    const Lanes t = t_scaled * inverse_det;
    candidates &= bits((t > zero) & (t < tmax));

    // The rejection of a t within its own rounding error of zero (PBR 3rd ed., section 3.9.6),
    // the scalar test's bound computed in the same order.
    constexpr float gamma2 = triangle_detail::gamma_bound(2), gamma3 = triangle_detail::gamma_bound(3),
                    gamma5 = triangle_detail::gamma_bound(5);
    const Lanes max_z = max(max(abs(az), abs(bz)), abs(cz));
    const Lanes max_x = max(max(abs(ax), abs(bx)), abs(cx));
    const Lanes max_y = max(max(abs(ay), abs(by)), abs(cy));
    const Lanes delta_z = Lanes::broadcast(gamma3) * max_z;
    const Lanes delta_x = Lanes::broadcast(gamma5) * (max_x + max_z);
    const Lanes delta_y = Lanes::broadcast(gamma5) * (max_y + max_z);
    const Lanes delta_e =
        Lanes::broadcast(2.0f) * (Lanes::broadcast(gamma2) * max_x * max_y + delta_y * max_x + delta_x * max_y);
    const Lanes max_e = max(max(abs(u), abs(v)), abs(w));
    const Lanes delta_t = Lanes::broadcast(3.0f) *
                          (Lanes::broadcast(gamma3) * max_e * max_z + delta_e * max_z + delta_z * max_e) *
                          abs(inverse_det);
    candidates &= ~bits(t <= delta_t);

    hits.hit_lanes = candidates;
    if (candidates == 0) return;
    t.store(hits.t);
    (u * inverse_det).store(hits.b0);
    (v * inverse_det).store(hits.b1);
    (w * inverse_det).store(hits.b2);
    // END EXERCISE
}
// END BOOK

}  // namespace freezeray::ch07
