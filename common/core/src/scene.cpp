// The scene's own work: its size, and rays through alpha-masked surfaces (cut-outs). The
// accelerator finds the closest surface, and where that surface's mask has a hole at the hit,
// the ray goes on from just behind it. The accelerators themselves know nothing of materials;
// scenes without masks never come here.
#include "freezeray/scene.hpp"

namespace freezeray {

std::size_t Scene::triangle_count() const {
    std::size_t n = 0;
    for (const TriangleMesh& m : meshes) n += m.triangle_count();
    return n;
}

// BOOK(alpha-cutout)
std::optional<Hit> Scene::intersect_through_cutouts(const Ray& ray) const {
    // The first surface that is not a hole at the hit; its t along the ray the caller traced.
    return first_hit_where(*accelerator, ray, [&](const Hit& hit) { return !material(hit).is_cut_out(hit); });
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
    return intersect_through_cutouts(ray).has_value();
}
// END BOOK

}  // namespace freezeray
