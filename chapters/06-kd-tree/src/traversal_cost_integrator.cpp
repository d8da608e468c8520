// The traversal-cost integrator: the KD-tree's work per camera ray, in false colour.
#include "freezeray/ch06/traversal_cost_integrator.hpp"

#include "freezeray/ch06/kdtree_accelerator.hpp"
#include "freezeray/error.hpp"
#include "freezeray/false_colour.hpp"
#include "freezeray/film.hpp"
#include "freezeray/scene.hpp"

#include <algorithm>
#include <cstdio>
#include <memory>
#include <vector>

namespace freezeray::ch06 {

TraversalQuantity read_traversal_quantity(const Parameters& parameters) {
    const std::string show = parameters.get_string("traversal_cost_show", "nodes");
    if (show == "nodes") return TraversalQuantity::InteriorNodes;
    if (show == "leaves") return TraversalQuantity::Leaves;
    if (show == "tests") return TraversalQuantity::TriangleTests;
    throw InputError(parameters.where("traversal_cost_show"), "'" + show + "' is not nodes, leaves or tests");
}

namespace {

const char* quantity_name(TraversalQuantity quantity) {
    switch (quantity) {
        case TraversalQuantity::InteriorNodes: return "interior nodes visited";
        case TraversalQuantity::Leaves: return "leaves visited";
        case TraversalQuantity::TriangleTests: return "triangle tests";
    }
    return "";
}

}  // namespace

RenderResult TraversalCostIntegrator::render(const Scene& scene, const RenderSettings& settings,
                                             Progress& progress) const {
    const auto* tree = dynamic_cast<const CountedTraversal*>(scene.accelerator.get());
    if (tree == nullptr)
        throw InputError("--integrator", "traversal-cost counts the KD-tree's work, but this scene's accelerator is '" +
                                             scene.accelerator_name + "' (use --accel kdtree)");
    // The count, in every channel: the film averages it over the pixel's camera rays.
    RenderResult result = render_pixels(scene, settings, progress, [&](const Ray& ray, Sampler&, ScratchArena&) {
        const TraversalCounts counts = tree->count_traversal(ray);
        const std::uint32_t n = quantity_ == TraversalQuantity::InteriorNodes ? counts.interior_nodes
                                : quantity_ == TraversalQuantity::Leaves      ? counts.leaves
                                                                              : counts.triangle_tests;
        return Spectrum(static_cast<float>(n));
    });

    // From 0 to the 99th percentile: a few pixels of extreme cost would otherwise darken the rest.
    Image& image = result.image;
    std::vector<float> values;
    values.reserve(image.pixels().size());
    double sum = 0.0;
    for (const Spectrum& p : image.pixels()) {
        values.push_back(p.r);
        sum += p.r;
    }
    if (values.empty()) return result;
    std::vector<float> sorted = values;
    const std::size_t at = std::min(sorted.size() - 1, sorted.size() * 99 / 100);
    std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(at), sorted.end());
    const double top = std::max(1.0, static_cast<double>(sorted[at]));
    const double largest = *std::max_element(values.begin(), values.end());
    for (std::size_t i = 0; i < values.size(); ++i) image[i] = viridis_linear(values[i] / top);

    char note[256];
    std::snprintf(note, sizeof note,
                  "traversal-cost: %s per camera ray, viridis from 0 (dark) to %.0f (bright, the 99th percentile); "
                  "mean %.1f, largest %.0f",
                  quantity_name(quantity_), top, sum / static_cast<double>(values.size()), largest);
    result.notes.emplace_back(note);
    // The film is what `render` writes: one holding the colours, with no variance (that of the
    // counts says nothing about the colours).
    result.variance = Image(image.width(), image.height());
    result.film = std::make_shared<const Film>(Film::from_images(image, result.variance, result.samples_per_pixel));
    result.estimated_relative_mse = -1.0;
    return result;
}

}  // namespace freezeray::ch06
