// Chapter 07's registrations: the vectorised KD-tree, the default accelerator from this chapter
// on, which reads chapter 06's tree settings and its own packet width.
#include "freezeray/ch07/register_chapter07.hpp"
#include "freezeray/ch06/register_chapter06.hpp"

#include "freezeray/ch07/kdtree_simd_accelerator.hpp"
#include "freezeray/ch07/packet_kernels.hpp"

#include <algorithm>
#include <vector>

namespace freezeray {

void register_chapter07(Registry& registry) {
    register_chapter06(registry);  // chapters 01 to 06 first
    registry.accelerators.add("kdtree-simd", 7,
                             "chapter 06's KD-tree with its leaves in packets of 4, 8 or 16 triangles, tested at "
                             "once with SSE, AVX or AVX-512; hits identical to kdtree and bruteforce",
                             [](const Parameters& parameters) {
                                 return std::make_unique<ch07::KdTreeSimdAccelerator>(
                                     ch07::read_kdtree_simd_settings(parameters));
                             });
    registry.accelerators.set_default("kdtree-simd");
    registry.add_option({"--simd-width", "simd_width", OptionType::Integer, OptionTarget::Accelerator,
                         "kdtree-simd: triangles per packet, 1, 4, 8 or 16 (this processor runs " +
                             ch07::runnable_widths() + "; default 0, the widest)",
                         {"kdtree-simd"}, 7});
    registry.add_option({"--simd-leaf-cost", "simd_leaf_cost", OptionType::Text, OptionTarget::Accelerator,
                         "kdtree-simd: what the SAH charges a leaf, packets (ceil(n / W) packet tests) or "
                         "triangles (n tests: chapter 06's tree, repacked); default packets",
                         {"kdtree-simd"}, 7});
    // The tree is chapter 06's: its settings apply.
    for (const OptionDeclaration& option : std::vector<OptionDeclaration>(registry.options()))
        if (option.target == OptionTarget::Accelerator &&
            std::find(option.used_by.begin(), option.used_by.end(), "kdtree") != option.used_by.end())
            registry.add_option_user(option.flag, "kdtree-simd");
}

}  // namespace freezeray
