// The traversal-cost integrator (`--integrator traversal-cost`): not light, but the work the
// KD-tree does for each camera ray, as a false-colour image: the interior nodes it visits or the
// triangles it tests (Havran, "Heuristic Ray Shooting Algorithms", 2000, shows trees this way).
// Where the image is bright the tree is deep or its leaves crowded; a good tree is dark over
// empty space and bright only at the silhouettes and clutter that no plane separates.
#pragma once

#include "freezeray/integrator.hpp"
#include "freezeray/parameters.hpp"

#include <string>

namespace freezeray::ch06 {

// What the image shows: `--traversal-cost-show`, "nodes" (interior nodes visited, the default),
// "leaves" or "tests" (ray-triangle tests).
enum class TraversalQuantity { InteriorNodes, Leaves, TriangleTests };

TraversalQuantity read_traversal_quantity(const Parameters& parameters);

class TraversalCostIntegrator final : public Integrator {
public:
    explicit TraversalCostIntegrator(TraversalQuantity quantity) : quantity_(quantity) {}

    // The mean count per pixel over its camera rays, mapped to viridis from 0 (dark) to the
    // image's 99th percentile (bright; the few pixels above it are bright too); the scale is in
    // the result's notes. The scene's accelerator must be the KD-tree (InputError otherwise).
    RenderResult render(const Scene& scene, const RenderSettings& settings, Progress& progress) const override;

private:
    TraversalQuantity quantity_;
};

}  // namespace freezeray::ch06
