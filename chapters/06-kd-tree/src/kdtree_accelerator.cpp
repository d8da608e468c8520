// Building the KD-tree accelerator over a scene's meshes.
#include "freezeray/ch06/kdtree_accelerator.hpp"

#include "freezeray/ch06/kdtree_builder.hpp"

#include <chrono>
#include <stdexcept>

namespace freezeray::ch06 {

KdTreeAccelerator::KdTreeAccelerator(const KdTreeSettings& settings) : settings_(settings) {}

void KdTreeAccelerator::build(const std::vector<TriangleMesh>& meshes) {
    const auto start = std::chrono::steady_clock::now();
    meshes_ = &meshes;
    vertices_.clear();
    ids_.clear();
    brute_force_.build(meshes);
    // Global indices in mesh order, then triangle order: the order in which brute force tests
    // them, so "lower global index" is its tie-breaking rule.
    for (std::uint32_t m = 0; m < meshes.size(); ++m) {
        const TriangleMesh& mesh = meshes[m];
        for (std::uint32_t i = 0; i < mesh.triangles.size(); ++i) {
            const auto& idx = mesh.triangles[i];
            vertices_.push_back({mesh.positions[idx[0]], mesh.positions[idx[1]], mesh.positions[idx[2]]});
            ids_.push_back({m, i});
        }
    }
    if (vertices_.size() > 0xffffffffull) throw std::length_error("kd-tree: more than 2^32 triangles");
    tree_ = build_kdtree(vertices_, settings_, statistics_);
    statistics_.memory_bytes += vertices_.size() * sizeof(TriangleVertices) + ids_.size() * sizeof(TriangleId);
    statistics_.build_milliseconds =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

std::vector<std::pair<std::string, std::string>> KdTreeAccelerator::describe() const {
    std::vector<std::pair<std::string, std::string>> lines{{"kind", "kdtree (SAH, Wald and Havran 2006)"}};
    for (auto& line : statistics_.describe()) lines.push_back(std::move(line));
    return lines;
}

}  // namespace freezeray::ch06
