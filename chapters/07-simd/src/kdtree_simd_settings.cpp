// Reading the vectorised KD-tree's settings.
#include "freezeray/ch07/kdtree_simd_settings.hpp"

#include "freezeray/ch07/packet_kernels.hpp"
#include "freezeray/error.hpp"

#include <string>

namespace freezeray::ch07 {

KdTreeSimdSettings read_kdtree_simd_settings(const Parameters& parameters) {
    KdTreeSimdSettings s;
    s.tree = ch06::read_kdtree_settings(parameters);
    s.simd_width = parameters.get_int("simd_width", s.simd_width);
    if (s.simd_width != 0) kernel_of_width(s.simd_width, parameters.where("simd_width"));  // refuses what cannot run
    const std::string leaf_cost = parameters.get_string("simd_leaf_cost", "packets");
    if (leaf_cost != "packets" && leaf_cost != "triangles")
        throw InputError(parameters.where("simd_leaf_cost"), "'" + leaf_cost + "' is not packets or triangles");
    s.packet_leaf_cost = leaf_cost == "packets";
    return s;
}

}  // namespace freezeray::ch07
