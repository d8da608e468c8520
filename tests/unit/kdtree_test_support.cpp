// Meshes, rays and the brute-force comparison of the KD-tree tests.
#include "kdtree_test_support.hpp"
#include "test_scenes.hpp"

#include "freezeray/ch07/packet_kernels.hpp"

#include "freezeray/ch01/warps.hpp"

#include <bit>
#include <cstdio>
#include <map>
#include <optional>

namespace freezeray::testing {

std::unique_ptr<Accelerator> AcceleratorUnderTest::make() const {
    const Parameters parameters(settings, "test", "/accelerator", ".");
    return full_registry().accelerators.make(name, "test", parameters);
}

const std::vector<AcceleratorUnderTest>& accelerators_under_test() {
    static const std::vector<AcceleratorUnderTest> accelerators = [] {
        std::vector<AcceleratorUnderTest> result;
        for (const Registry::Entry& e : full_registry().list(CapabilityKind::Accelerator)) {
            if (e.name == "bruteforce") continue;
            if (e.name != "kdtree-simd") {
                result.push_back({e.name, e.name});
                continue;
            }
            for (const ch07::PacketKernel& kernel : ch07::built_kernels())
                if (ch07::cpu_runs(kernel))
                    result.push_back({e.name + " (width " + std::to_string(kernel.width) + ")", e.name,
                                      nlohmann::json{{"simd_width", kernel.width}}});
        }
        return result;
    }();
    return accelerators;
}

TriangleMesh make_mesh(std::vector<Vec3> positions, std::vector<std::array<std::uint32_t, 3>> triangles) {
    TriangleMesh mesh;
    mesh.positions = std::move(positions);
    mesh.triangles = std::move(triangles);
    mesh.face_materials.assign(mesh.triangles.size(), 0u);
    return mesh;
}

TriangleMesh icosphere(int levels, float radius, const Vec3& centre) {
    const float t = (1.0f + std::sqrt(5.0f)) / 2.0f;
    std::vector<Vec3> p = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                           {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
    for (Vec3& v : p) v = glm::normalize(v);
    std::vector<std::array<std::uint32_t, 3>> tris = {
        {0, 11, 5}, {0, 5, 1}, {0, 1, 7}, {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
        {3, 9, 4}, {3, 4, 2}, {3, 2, 6}, {3, 6, 8}, {3, 8, 9}, {4, 9, 5}, {2, 4, 11}, {6, 2, 10}, {8, 6, 7}, {9, 8, 1}};
    for (int level = 0; level < levels; ++level) {
        std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> midpoints;
        auto midpoint = [&](std::uint32_t a, std::uint32_t b) {
            const auto key = std::minmax(a, b);
            if (const auto it = midpoints.find(key); it != midpoints.end()) return it->second;
            p.push_back(glm::normalize(p[a] + p[b]));
            return midpoints[key] = static_cast<std::uint32_t>(p.size() - 1);
        };
        std::vector<std::array<std::uint32_t, 3>> finer;
        for (const auto& [a, b, c] : tris) {
            const std::uint32_t ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
            finer.push_back({a, ab, ca});
            finer.push_back({b, bc, ab});
            finer.push_back({c, ca, bc});
            finer.push_back({ab, bc, ca});
        }
        tris = std::move(finer);
    }
    for (Vec3& v : p) v = centre + radius * v;
    return make_mesh(std::move(p), std::move(tris));
}

TriangleMesh random_soup(int n, float size, std::uint64_t seed) {
    PCG32 random(seed, 7);
    auto uniform = [&] { return Vec3(random.next_float(), random.next_float(), random.next_float()); };
    std::vector<Vec3> p;
    std::vector<std::array<std::uint32_t, 3>> tris;
    for (int i = 0; i < n; ++i) {
        const Vec3 centre = uniform();
        const auto first = static_cast<std::uint32_t>(p.size());
        for (int k = 0; k < 3; ++k) p.push_back(centre + size * (uniform() - Vec3(0.5f)));
        tris.push_back({first, first + 1, first + 2});
    }
    return make_mesh(std::move(p), std::move(tris));
}

TriangleMesh planar_grid(int n, float height) {
    std::vector<Vec3> p;
    std::vector<std::array<std::uint32_t, 3>> tris;
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i)
            p.emplace_back(-1.0f + 2.0f * static_cast<float>(i) / static_cast<float>(n),
                           -1.0f + 2.0f * static_cast<float>(j) / static_cast<float>(n), height);
    const auto at = [n](int i, int j) { return static_cast<std::uint32_t>(j * (n + 1) + i); };
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            tris.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
            tris.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
        }
    return make_mesh(std::move(p), std::move(tris));
}

std::vector<Ray> mixed_rays(const std::vector<TriangleMesh>& meshes, const Bounds3& origins, int count,
                            std::uint64_t seed) {
    PCG32 random(seed, 11);
    std::vector<Vec3> vertices;
    std::vector<std::pair<Vec3, Vec3>> edges;
    for (const TriangleMesh& mesh : meshes)
        for (const auto& t : mesh.triangles)
            for (int k = 0; k < 3; ++k) {
                vertices.push_back(mesh.positions[t[static_cast<std::size_t>(k)]]);
                edges.emplace_back(mesh.positions[t[static_cast<std::size_t>(k)]], mesh.positions[t[static_cast<std::size_t>((k + 1) % 3)]]);
            }
    const Vec3 extent = origins.diagonal();
    auto origin = [&] { return origins.min + extent * Vec3(random.next_float(), random.next_float(), random.next_float()); };
    auto direction = [&] { return ch01::sample_uniform_sphere(Vec2(random.next_float(), random.next_float())); };
    auto vertex = [&] { return vertices[random.next_below(static_cast<std::uint32_t>(vertices.size()))]; };
    auto axis = [&] { return static_cast<int>(random.next_below(3)); };
    std::vector<Ray> rays;
    rays.reserve(static_cast<std::size_t>(count));
    for (int i = 0; i < count; ++i) {
        Ray ray{origin(), direction()};
        switch (vertices.empty() ? 0 : i % 8) {
            case 0:
            case 1: break;  // random
            case 2: ray.direction = glm::normalize(vertex() - ray.origin); break;  // at a vertex
            case 3: {  // at a point of an edge: its midpoint or a random one
                const auto& [a, b] = edges[random.next_below(static_cast<std::uint32_t>(edges.size()))];
                const float s = (i / 8) % 2 == 0 ? 0.5f : random.next_float();
                ray.direction = glm::normalize(a + s * (b - a) - ray.origin);
                break;
            }
            case 4: {  // along an axis exactly through a vertex
                const int k = axis();
                const Vec3 v = vertex();
                const float side = random.next_float() < 0.5f ? -1.0f : 1.0f;
                ray.origin = v;
                ray.origin[k] = side < 0.0f ? origins.max[k] : origins.min[k];
                ray.direction = Vec3(0.0f);
                ray.direction[k] = side;
                break;
            }
            case 5: {  // along an axis from a random origin
                const int k = axis();
                ray.direction = Vec3(0.0f);
                ray.direction[k] = random.next_float() < 0.5f ? -1.0f : 1.0f;
                break;
            }
            case 6: {  // in a plane of constant coordinate through a vertex (a likely split plane)
                const int k = axis();
                ray.origin[k] = vertex()[k];
                ray.direction[k] = 0.0f;
                ray.direction = glm::normalize(ray.direction);
                break;
            }
            case 7: ray.tmax = glm::length(extent) * random.next_float(); break;
        }
        rays.push_back(ray);
    }
    return rays;
}

std::string describe_ray(const Ray& ray) {
    char buffer[256];
    std::snprintf(buffer, sizeof buffer, "origin (%a, %a, %a) direction (%a, %a, %a) tmax %a",
                  static_cast<double>(ray.origin.x), static_cast<double>(ray.origin.y), static_cast<double>(ray.origin.z),
                  static_cast<double>(ray.direction.x), static_cast<double>(ray.direction.y),
                  static_cast<double>(ray.direction.z), static_cast<double>(ray.tmax));
    return buffer;
}

namespace {

std::string describe_hit(const std::optional<Hit>& hit) {
    if (!hit) return "no hit";
    char buffer[128];
    std::snprintf(buffer, sizeof buffer, "mesh %u triangle %u t %a", hit->mesh, hit->triangle, static_cast<double>(hit->t));
    return buffer;
}

bool same_hit(const std::optional<Hit>& a, const std::optional<Hit>& b) {
    if (!a || !b) return !a && !b;
    return a->mesh == b->mesh && a->triangle == b->triangle && std::bit_cast<std::uint32_t>(a->t) == std::bit_cast<std::uint32_t>(b->t);
}

}  // namespace

Conformance compare_with_brute_force(const AcceleratorUnderTest& under_test, const std::vector<TriangleMesh>& meshes,
                                     const std::vector<Ray>& rays, std::uint64_t seed) {
    const auto brute_force = full_registry().accelerators.make("bruteforce", "test", Parameters::none());
    const auto tested = under_test.make();
    const std::string& accelerator = under_test.label;
    brute_force->build(meshes);
    tested->build(meshes);
    Bounds3 bounds;
    for (const TriangleMesh& mesh : meshes) bounds.expand(mesh.bounds());
    const float scene_size = bounds.empty() ? 1.0f : glm::length(bounds.diagonal());

    PCG32 random(seed, 13);
    // For occluded_by: each triangle counted or looked through by a coin of its own stream.
    PCG32 coins(seed, 14);
    TriangleFlags counted;
    for (const TriangleMesh& mesh : meshes) {
        std::vector<std::uint8_t>& flags = counted.emplace_back(mesh.triangles.size());
        for (std::uint8_t& flag : flags) flag = static_cast<std::uint8_t>(coins.next_below(2));
    }
    Conformance result;
    auto report = [&](const std::string& what) {
        if (++result.mismatches <= 5) result.report += what + "\n";
    };
    for (std::size_t i = 0; i < rays.size(); ++i) {
        const Ray& ray = rays[i];
        ++result.rays;
        const auto expected = brute_force->intersect(ray);
        const auto found = tested->intersect(ray);
        if (!same_hit(expected, found))
            report("intersect, ray " + std::to_string(i) + ": " + describe_ray(ray) + ": bruteforce " +
                   describe_hit(expected) + ", " + accelerator + " " + describe_hit(found));
        // Shadow rays ending before, exactly at, one ulp past and well past the closest hit.
        // Exactly at it and one ulp past it, intersect is compared too: there bruteforce's box
        // test may cull the mesh of the hit it found with a longer ray.
        Ray shadow = ray;
        const float u = random.next_float();
        if (expected && i % 8 == 0) shadow.tmax = expected->t;
        else if (expected && i % 8 == 1) shadow.tmax = std::nextafter(expected->t, INFINITY);
        else if (expected) shadow.tmax = 2.0f * u * expected->t;
        else shadow.tmax = std::min(ray.tmax, 2.0f * u * scene_size);
        if (!(shadow.tmax > 0.0f)) shadow.tmax = ray.tmax;
        const bool blocked = brute_force->occluded(shadow);
        if (blocked != tested->occluded(shadow))
            report("occluded, ray " + std::to_string(i) + ": " + describe_ray(shadow) + ": bruteforce " +
                   (blocked ? "true" : "false") + ", " + accelerator + " " + (blocked ? "false" : "true"));
        const bool blocked_by = brute_force->occluded_by(shadow, counted);
        if (blocked_by != tested->occluded_by(shadow, counted))
            report("occluded_by, ray " + std::to_string(i) + ": " + describe_ray(shadow) + ": bruteforce " +
                   (blocked_by ? "true" : "false") + ", " + accelerator + " " + (blocked_by ? "false" : "true"));
        if (expected && i % 8 < 2) {
            const auto shortened_expected = brute_force->intersect(shadow);
            const auto shortened_found = tested->intersect(shadow);
            if (!same_hit(shortened_expected, shortened_found))
                report("intersect, ray " + std::to_string(i) + ": " + describe_ray(shadow) + ": bruteforce " +
                       describe_hit(shortened_expected) + ", " + accelerator + " " + describe_hit(shortened_found));
        }
    }
    return result;
}

}  // namespace freezeray::testing
