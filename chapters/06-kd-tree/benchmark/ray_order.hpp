// Putting a batch's rays in a coherent order: an experiment on what memory costs the traversal.
// Rays whose origins lie close together and whose directions point the same way visit the same
// nodes and triangles, which the caches then still hold (Pharr, Kolb, Gershbein and Hanrahan,
// "Rendering Complex Scenes with Memory-Coherent Ray Tracing", 1997, reorder rays for this).
#pragma once

#include "ray_batch.hpp"

#include "freezeray/math.hpp"

#include <cstdint>

namespace freezeray::benchmark {

// The Morton code of a point in `bounds`: 10 bits per axis, interleaved (z y x from bit 2 down),
// so that points close in the code are close in space (Morton, 1966).
std::uint32_t morton_code(const Vec3& point, const Bounds3& bounds);

// Sorts each batch by its rays' direction octant, then the Morton code of their origin in
// `bounds`; a stable sort, so rays that tie keep the file's order. Answers, and the hits written
// with --hits-out, follow the new order.
void sort_for_coherence(RayBatches& batches, const Bounds3& bounds);

}  // namespace freezeray::benchmark
