// Replaying brute force's tests on the hits close to the closest one (see close_hits.hpp).
#include "freezeray/ch06/close_hits.hpp"

#include "freezeray/accelerator.hpp"

namespace freezeray::ch06 {

// BOOK(brute-force-choice)
std::optional<CloseHits::Entry> CloseHits::brute_force_choice(const Ray& ray, const Vec3& inverse_direction,
                                                               const RayShear& shear,
                                                               const std::vector<TriangleVertices>& vertices,
                                                               const std::vector<TriangleId>& ids,
                                                               const std::vector<Bounds3>& mesh_bounds) {
    // Global indices run in mesh order, then triangle order: brute force's order.
    std::sort(entries_, entries_ + count_, [](const Entry& a, const Entry& b) { return a.triangle < b.triangle; });
    Ray shortened = ray;
    std::optional<Entry> choice;
    std::uint32_t mesh = 0;
    bool mesh_tested = false, mesh_passes = false;
    for (int i = 0; i < count_; ++i) {
        const Entry& e = entries_[i];
        if (!mesh_tested || ids[e.triangle].mesh != mesh) {
            // Brute force tests a mesh's box once, with the closest distance found before it.
            mesh = ids[e.triangle].mesh;
            mesh_tested = true;
            mesh_passes = ray_intersects_bounds(shortened, inverse_direction, mesh_bounds[mesh]);
        }
        if (!mesh_passes) continue;
        // The first is kept: it passed the triangle test against a limit of at most ray.tmax, so
        // it passes against ray.tmax (the test is monotonic in tmax). The others are tested again
        // against the closest distance so far, as brute force tests them.
        const TriangleVertices& v = vertices[e.triangle];
        if (choice && !intersect_triangle(shortened, shear, v.p0, v.p1, v.p2)) continue;
        choice = e;
        shortened.tmax = e.hit.t;
    }
    return choice;
}
// END BOOK

}  // namespace freezeray::ch06
