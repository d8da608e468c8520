// Rays through alpha-masked surfaces (cut-outs): the accelerator finds the closest surface, and
// where that surface's mask has a hole at the hit, the ray goes on from just behind it. The
// accelerators themselves know nothing of materials; scenes without masks never come here.
#include "freezeray/scene.hpp"

namespace freezeray {

// BOOK(alpha-cutout)
std::optional<Hit> Scene::intersect_through_cutouts(const Ray& ray) const {
    Ray r = ray;
    for (int crossing = 0;; ++crossing) {
        std::optional<Hit> hit = accelerator->intersect(r);
        if (!hit || crossing == MaxCutoutCrossings || !materials[hit->material]->is_cut_out(*hit)) {
            // The distance along the ray the caller traced, not along the last piece of it.
            if (hit && crossing > 0) hit->t = glm::dot(hit->position - ray.origin, ray.direction);
            return hit;
        }
        r = continue_behind(r, *hit);
        if (!(r.tmax > 0.0f)) return std::nullopt;
    }
}

bool Scene::occluded_through_cutouts(const Ray& ray) const {
    // A shadow ray that meets an opaque triangle (one whose material has no alpha mask) is
    // blocked, whatever the masked surfaces in front of it do: the accelerator's any-hit test over
    // those triangles settles most blocked rays without a closest hit or a material.
    if (opaque_triangles.size() == meshes.size() && accelerator->occluded_by(ray, opaque_triangles)) return true;
    // Then only masked surfaces can block it. Most shadow rays that meet nothing at all are
    // settled by the any-hit test at its usual cost; only those that meet something look at
    // what it is, closest first.
    if (!accelerator->occluded(ray)) return false;
    Ray r = ray;
    for (int crossing = 0;; ++crossing) {
        const std::optional<Hit> hit = accelerator->intersect(r);
        if (!hit) return false;
        if (crossing == MaxCutoutCrossings || !materials[hit->material]->is_cut_out(*hit)) return true;
        r = continue_behind(r, *hit);
        if (!(r.tmax > 0.0f)) return false;
    }
}
// END BOOK

}  // namespace freezeray
