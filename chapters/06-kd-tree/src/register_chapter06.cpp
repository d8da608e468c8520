// Chapter 06's registrations.
#include "freezeray/ch06/register_chapter06.hpp"

#include "freezeray/ch06/kdtree_accelerator.hpp"

namespace freezeray {

void register_chapter06(Registry& registry) {
    registry.add_accelerator("kdtree", 6,
                             "SAH KD-tree built in O(N log N) with perfect splits (Wald and Havran 2006), "
                             "traversed front to back; hits identical to bruteforce",
                             [] {
                                 // The accelerator's parameters will come in here: ch06::read_kdtree_settings(parameters).
                                 return std::make_unique<ch06::KdTreeAccelerator>(ch06::KdTreeSettings{});
                             });
}

}  // namespace freezeray
