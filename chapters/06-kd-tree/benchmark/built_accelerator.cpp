// Building accelerators, timed.
#include "built_accelerator.hpp"

#include <chrono>

namespace freezeray::benchmark {

BuiltAccelerator build_timed(std::string name, std::unique_ptr<Accelerator> accelerator,
                             const std::vector<TriangleMesh>& meshes) {
    const auto start = std::chrono::steady_clock::now();
    accelerator->build(meshes);
    const auto stop = std::chrono::steady_clock::now();
    BuiltAccelerator built;
    built.name = std::move(name);
    built.accelerator = std::move(accelerator);
    built.build_milliseconds = std::chrono::duration<double, std::milli>(stop - start).count();
    return built;
}

BuiltAccelerator build_registry_accelerator(const Registry& registry, const std::string& name,
                                            const Parameters& settings, const std::vector<TriangleMesh>& meshes) {
    BuiltAccelerator built = build_timed(name, registry.accelerators.make(name, "--accel", settings), meshes);
    if (const std::optional<std::size_t> bytes = built.accelerator->memory_bytes())
        built.memory_bytes = static_cast<double>(*bytes);
    return built;
}

}  // namespace freezeray::benchmark
