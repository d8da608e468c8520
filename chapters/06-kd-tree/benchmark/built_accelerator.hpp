// An accelerator under measurement, built, with what building it cost: one of the registry's,
// or Embree (embree_yardstick.hpp).
#pragma once

#include "freezeray/accelerator.hpp"
#include "freezeray/registry.hpp"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace freezeray::benchmark {

struct BuiltAccelerator {
    std::string name;                     // "bruteforce", "kdtree", ..., "embree"
    std::unique_ptr<Accelerator> accelerator;
    double build_milliseconds = 0.0;
    std::optional<double> memory_bytes;   // when the accelerator reports it
};

// Builds the accelerator over `meshes` (which must outlive it), timing the build.
BuiltAccelerator build_timed(std::string name, std::unique_ptr<Accelerator> accelerator,
                             const std::vector<TriangleMesh>& meshes);

// Makes the registry's accelerator `name` with its `settings` (the keys of a scene's
// "accelerator" block) and builds it, timed, with the memory it reports. An unknown name is an
// InputError at "--accel" that names the chapter introducing it.
BuiltAccelerator build_registry_accelerator(const Registry& registry, const std::string& name,
                                            const Parameters& settings, const std::vector<TriangleMesh>& meshes);

}  // namespace freezeray::benchmark
