// The interface every ray-intersection accelerator implements (brute force here; the KD-tree
// and its SIMD variant in chapters 06 and 07).
#pragma once

#include "freezeray/hit.hpp"
#include "freezeray/mesh.hpp"
#include "freezeray/ray.hpp"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace freezeray {

// One flag per triangle of each mesh: flags[m][t] for meshes[m].triangles[t].
using TriangleFlags = std::vector<std::vector<std::uint8_t>>;

class Accelerator {
public:
    virtual ~Accelerator() = default;

    // Prepares for queries over these meshes (world space). The meshes outlive the accelerator.
    virtual void build(const std::vector<TriangleMesh>& meshes) = 0;

    // The closest hit with t in (0, ray.tmax), with position, normals, uv and ids filled in.
    virtual std::optional<Hit> intersect(const Ray& ray) const = 0;

    // True if anything lies on the ray with t in (0, ray.tmax): the cheaper shadow-ray query.
    virtual bool occluded(const Ray& ray) const = 0;

    // True if a triangle whose flag is set in `counted` lies on the ray with t in (0, ray.tmax);
    // the others are looked through. Scene::occluded_through_cutouts asks it with the triangles
    // whose material has no alpha mask: one of those on the ray blocks it, whatever the masked
    // surfaces do. This default follows the closest hits one behind the other; the KD-trees
    // test the flag in their any-hit walk instead.
    virtual bool occluded_by(const Ray& ray, const TriangleFlags& counted) const;

    // What the accelerator built, as (name, value) lines for `info` and `render` to print
    // (sizes, build time); none by default.
    virtual std::vector<std::pair<std::string, std::string>> describe() const { return {}; }

    // The bytes of what build() made beyond the meshes themselves, when the accelerator counts
    // them (the ray benchmark's memory column); nothing by default.
    virtual std::optional<std::size_t> memory_bytes() const { return std::nullopt; }
};

// The ray that continues `ray` behind `hit`: the same direction, from just beyond the surface
// (offset as every spawned ray is), as far as `ray` still had to go.
Ray continue_behind(const Ray& ray, const Hit& hit);

// The most surfaces a ray is continued behind, one after the other; a ray that meets more is
// taken to stop at the last (Accelerator::occluded_by's default, and the scene's cut-outs).
inline constexpr int MaxCrossingsBehind = 64;

// BOOK(first-hit-where)
// The first surface along `ray` at which stops(hit) holds, found closest hit after closest hit,
// the ray continued behind each surface that does not stop it; the surface met after
// MaxCrossingsBehind crossings stops it whatever it is. Its t is measured along `ray`, not along
// the last piece of it. Nothing when the ray runs out first. Accelerator::occluded_by's default
// and the scene's cut-outs (Scene::intersect, Scene::occluded) walk rays so.
template <typename Stops>
std::optional<Hit> first_hit_where(const Accelerator& accelerator, const Ray& ray, Stops&& stops) {
    Ray r = ray;
    for (int crossing = 0;; ++crossing) {
        std::optional<Hit> hit = accelerator.intersect(r);
        if (!hit) return std::nullopt;
        if (crossing == MaxCrossingsBehind || stops(*hit)) {
            if (crossing > 0) hit->t = glm::dot(hit->position - ray.origin, ray.direction);
            return hit;
        }
        r = continue_behind(r, *hit);
        if (!(r.tmax > 0.0f)) return std::nullopt;
    }
}
// END BOOK

// Fills in a Hit from a triangle, its barycentrics and the ray distance: interpolated position
// (with its error bound), normals and uv. Shared by every accelerator.
struct TriangleHit;
Hit make_hit(const std::vector<TriangleMesh>& meshes, std::uint32_t mesh, std::uint32_t triangle,
             const TriangleHit& triangle_hit);

// Tests every triangle of every mesh whose bounding box the ray meets: O(n) per ray, the
// baseline the KD-tree chapter measures itself against.
class BruteForceAccelerator final : public Accelerator {
public:
    void build(const std::vector<TriangleMesh>& meshes) override;
    std::optional<Hit> intersect(const Ray& ray) const override;
    bool occluded(const Ray& ray) const override;
    bool occluded_by(const Ray& ray, const TriangleFlags& counted) const override;

    // The boxes it culls meshes by, one per mesh (an accelerator that must agree with brute force
    // to the bit replays this culling).
    const std::vector<Bounds3>& mesh_bounds() const { return mesh_bounds_; }

    std::optional<std::size_t> memory_bytes() const override { return mesh_bounds_.size() * sizeof(Bounds3); }

private:
    // occluded and occluded_by: whether a triangle for which counts(mesh, triangle) holds lies on the ray.
    template <typename Counts>
    bool any_hit(const Ray& ray, Counts&& counts) const;

    const std::vector<TriangleMesh>* meshes_ = nullptr;
    std::vector<Bounds3> mesh_bounds_;
};

// Slab test: does the ray meet the box within (0, tmax)? (Kay and Kajiya 1986.)
bool ray_intersects_bounds(const Ray& ray, const Vec3& inverse_direction, const Bounds3& bounds);

// The same test, also giving the part [t_enter, t_exit] of (0, tmax) inside the box, its far end
// widened by 2 gamma(3) (PBR 3rd ed., section 3.9.2). A zero direction component gives infinite
// or, for an origin on the slab's face, NaN distances, which the comparisons let through.
bool clip_ray_to_bounds(const Ray& ray, const Vec3& inverse_direction, const Bounds3& bounds, float& t_enter,
                        float& t_exit);

}  // namespace freezeray
