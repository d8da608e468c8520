// Hits identical to brute force: the contract every accelerator keeps (docs/ARCHITECTURE.md), and
// the tool that keeps it. For every ray an accelerator reports the hit BruteForceAccelerator
// reports, to the bit, so that changing the accelerator never changes an image.
//
// Brute force tests the meshes in order, skips a mesh whose bounding box the ray misses within
// the closest distance so far, and keeps a hit only if its distance is below that distance as
// the triangle test computes it (Woop et al. 2013, section 3.3: before the division). Where two
// hits lie within a few roundings of each other (a block standing on the floor, triangles that
// cross), rounding in those tests can keep the first in index order even if the second is an ulp
// closer. An accelerator that visits triangles in another order (chapter 06's KD-tree, chapter
// 07's SIMD leaves) keeps every hit within a relative width of 2^-20 of the closest here, and
// replays brute force's tests on them, in index order, so that it reports the same triangle.
#pragma once

#include "freezeray/accelerator.hpp"
#include "freezeray/triangle_intersection.hpp"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

namespace freezeray {

class CloseHits {
public:
    static constexpr int Capacity = 16;
    static constexpr float RelativeWidth = 0x1p-20f;

    struct Entry {
        std::uint32_t triangle;  // global index: the triangles of all meshes in mesh order, then triangle order
        TriangleHit hit;
    };

    bool empty() const { return count_ == 0; }
    int size() const { return count_; }
    const Entry& operator[](int i) const { return entries_[i]; }

    // Hits beyond this cannot be the answer (infinite while there is none).
    float limit() const { return best_ * (1.0f + RelativeWidth); }

    // Adds a hit of a triangle (again, if another leaf holds it too: kept once). When the window
    // is full, the hit farthest away (then of highest index) gives way.
    void add(std::uint32_t triangle, const TriangleHit& hit) {
        if (hit.t > limit()) return;
        for (int i = 0; i < count_; ++i)
            if (entries_[i].triangle == triangle) return;
        if (hit.t < best_) {
            best_ = hit.t;
            const float top = limit();
            count_ = static_cast<int>(std::remove_if(entries_, entries_ + count_, [top](const Entry& e) { return e.hit.t > top; }) - entries_);
        }
        if (count_ < Capacity) {
            entries_[count_++] = {triangle, hit};
            return;
        }
        Entry* worst = std::max_element(entries_, entries_ + count_, closer);
        if (closer(Entry{triangle, hit}, *worst)) *worst = {triangle, hit};
    }

    // BOOK(brute-force-choice)
    // Brute force's choice among the hits: their meshes' boxes and the triangles tested in index
    // order against the closest distance so far, as BruteForceAccelerator does. Nothing when its
    // box test culls every one of them (the ray grazes their meshes' boxes): then only brute force
    // itself knows its answer. mesh_of(triangle) is a global triangle's mesh, vertices_of(triangle)
    // its vertices p0, p1, p2 (the same floats as the mesh's).
    template <typename MeshOf, typename VerticesOf>
    std::optional<Entry> brute_force_choice(const Ray& ray, const Vec3& inverse_direction, const RayShear& shear,
                                            const std::vector<Bounds3>& mesh_bounds, MeshOf&& mesh_of,
                                            VerticesOf&& vertices_of) {
        // Global indices run in mesh order, then triangle order: brute force's order.
        std::sort(entries_, entries_ + count_, [](const Entry& a, const Entry& b) { return a.triangle < b.triangle; });
        Ray shortened = ray;
        std::optional<Entry> choice;
        std::uint32_t mesh = 0;
        bool mesh_tested = false, mesh_passes = false;
        for (int i = 0; i < count_; ++i) {
            const Entry& e = entries_[i];
            if (!mesh_tested || mesh_of(e.triangle) != mesh) {
                // Brute force tests a mesh's box once, with the closest distance found before it.
                mesh = mesh_of(e.triangle);
                mesh_tested = true;
                mesh_passes = ray_intersects_bounds(shortened, inverse_direction, mesh_bounds[mesh]);
            }
            if (!mesh_passes) continue;
            // The first is kept: it passed the triangle test against a limit of at most ray.tmax,
            // so it passes against ray.tmax (the test is monotonic in tmax). The others are tested
            // again against the closest distance so far, as brute force tests them.
            const auto& v = vertices_of(e.triangle);
            if (choice && !intersect_triangle(shortened, shear, v.p0, v.p1, v.p2)) continue;
            choice = e;
            shortened.tmax = e.hit.t;
        }
        return choice;
    }
    // END BOOK

private:
    // Order by distance, then index.
    static bool closer(const Entry& a, const Entry& b) {
        return a.hit.t != b.hit.t ? a.hit.t < b.hit.t : a.triangle < b.triangle;
    }

    Entry entries_[Capacity];
    int count_ = 0;
    float best_ = std::numeric_limits<float>::infinity();
};

}  // namespace freezeray
