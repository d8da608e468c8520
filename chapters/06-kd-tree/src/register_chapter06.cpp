// Chapter 06's registrations: the KD-tree, its settings as options, and the KD-tree as the
// default accelerator from this chapter on.
#include "freezeray/ch06/register_chapter06.hpp"
#include "freezeray/ch05/register_chapter05.hpp"

#include "freezeray/ch06/kdtree_accelerator.hpp"
#include "freezeray/ch06/traversal_cost_integrator.hpp"

#include <string>

namespace freezeray {

void register_chapter06(Registry& registry) {
    register_chapter05(registry);  // chapters 01 to 05 first
    registry.accelerators.add("kdtree", 6,
                             "SAH KD-tree built in O(N log N) with perfect splits (Wald and Havran 2006), "
                             "traversed front to back; hits identical to bruteforce",
                             [](const Parameters& parameters) {
                                 return std::make_unique<ch06::KdTreeAccelerator>(ch06::read_kdtree_settings(parameters));
                             });
    registry.accelerators.set_default("kdtree");
    registry.integrators.add("traversal-cost", 6,
                            "not light: the KD-tree's interior nodes, leaves or triangle tests per camera ray, in false colour",
                            // Per pixel, from the sampler; a false-colour image is no film that later
                            // samples could go on from.
                            {{.draws_from_sampler = true, .resumable = false},
                             [](const RenderSettings&, const Parameters& parameters) {
                                 return std::make_unique<ch06::TraversalCostIntegrator>(
                                     ch06::read_traversal_quantity(parameters));
                             }});
    registry.add_option({"--traversal-cost-show", "traversal_cost_show", OptionType::Text, OptionTarget::Integrator,
                         "traversal-cost: nodes (interior nodes visited), leaves or tests (triangle tests); default nodes",
                         {"traversal-cost"}, 6});

    // The settings of kdtree_settings.hpp, as flags; a scene's "accelerator" block takes the
    // same keys ({"type": "kdtree", "intersection_cost": 20}).
    const ch06::KdTreeSettings defaults;
    auto declare = [&](const char* flag, const char* key, OptionType type, const std::string& help) {
        registry.add_option({flag, key, type, OptionTarget::Accelerator, help, {"kdtree"}, 6});
    };
    declare("--kdtree-traversal-cost", "traversal_cost", OptionType::Number,
            "kdtree: the SAH cost of one traversal step (default " + option_default_text(defaults.traversal_cost) + ")");
    declare("--kdtree-intersection-cost", "intersection_cost", OptionType::Number,
            "kdtree: the SAH cost of one ray-triangle test (default " + option_default_text(defaults.intersection_cost) + ")");
    declare("--kdtree-empty-bonus", "empty_bonus", OptionType::Number,
            "kdtree: the share of the cost saved by an empty child, in [0, 1) (default " +
                option_default_text(defaults.empty_bonus) + ")");
    declare("--kdtree-max-depth", "max_depth", OptionType::Integer,
            "kdtree: the deepest node (0: 8 + 1.3 log2 N, at most 64; default 0)");
    declare("--kdtree-leaf-size", "leaf_size", OptionType::Integer,
            "kdtree: nodes with at most this many triangles become leaves untried (default " +
                std::to_string(defaults.leaf_size) + ")");
    declare("--kdtree-build-threads", "build_threads", OptionType::Integer,
            "kdtree: threads the build may use (0: one per core; the tree is the same for any; default 0)");
}

}  // namespace freezeray
