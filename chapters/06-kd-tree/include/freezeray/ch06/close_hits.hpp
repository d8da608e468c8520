// The hits a ray found within a hair of the closest one, and which of them brute force reports.
//
// Brute force tests the meshes in order, skips a mesh whose bounding box the ray misses within
// the closest distance so far, and keeps a hit only if its distance is below that distance as
// the triangle test computes it (Woop et al. 2013, section 3.3: before the division). Where two
// hits lie within a few roundings of each other (a block standing on the floor, triangles that
// cross), rounding in those tests can keep the first in index order even if the second is an ulp
// closer. The tree keeps every hit within a relative width of 2^-20 of the closest and replays
// brute force's tests on them, in index order, so that it reports the same triangle.
#pragma once

#include "freezeray/ch06/kdtree_node.hpp"
#include "freezeray/triangle_intersection.hpp"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

namespace freezeray::ch06 {

class CloseHits {
public:
    static constexpr int Capacity = 16;
    static constexpr float RelativeWidth = 0x1p-20f;

    struct Entry {
        std::uint32_t triangle;  // global index
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

    // Brute force's choice among the hits: their meshes' boxes and the triangles tested in index
    // order against the closest distance so far, as BruteForceAccelerator does. Nothing when its
    // box test culls every one of them (the ray grazes their meshes' boxes): then only brute force
    // itself knows its answer.
    std::optional<Entry> brute_force_choice(const Ray& ray, const Vec3& inverse_direction, const RayShear& shear,
                                            const std::vector<TriangleVertices>& vertices,
                                            const std::vector<TriangleId>& ids,
                                            const std::vector<Bounds3>& mesh_bounds);

private:
    // Order by distance, then index.
    static bool closer(const Entry& a, const Entry& b) {
        return a.hit.t != b.hit.t ? a.hit.t < b.hit.t : a.triangle < b.triangle;
    }

    Entry entries_[Capacity];
    int count_ = 0;
    float best_ = std::numeric_limits<float>::infinity();
};

}  // namespace freezeray::ch06
