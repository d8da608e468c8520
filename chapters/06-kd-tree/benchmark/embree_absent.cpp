// The benchmark built without Embree: no yardstick, and a message saying so.
#include "embree_yardstick.hpp"

namespace freezeray::benchmark {

bool embree_is_available() { return false; }

std::string embree_description() { return "Embree not found"; }

std::optional<BuiltAccelerator> build_embree(const std::vector<TriangleMesh>& /*meshes*/) { return std::nullopt; }

}  // namespace freezeray::benchmark
