// Chapter 07: the packet kernels give the scalar watertight test's answers lane by lane (the same
// hits, the same t and barycentric bits), padded lanes are never reported, leaves of every size
// around the packet width agree with brute force, and images rendered with kdtree-simd at every
// width are those of kdtree to the bit. (The conformance tests of test_kdtree_conformance.cpp run
// kdtree-simd at every width this processor has, on the same 1.1 million rays as kdtree.)
#include "determinism.hpp"
#include "kdtree_test_support.hpp"
#include "test_bounds.hpp"
#include "test_scenes.hpp"

#include "freezeray/ch07/kdtree_simd_accelerator.hpp"
#include "freezeray/ch07/packet_kernels.hpp"
#include "freezeray/ch07/triangle_packets.hpp"
#include "freezeray/error.hpp"
#include "freezeray/triangle_intersection.hpp"

#include <catch2/catch.hpp>

#include <bit>

using namespace freezeray;
using namespace freezeray::testing;

namespace {

std::vector<ch07::PacketKernel> runnable_kernels() {
    std::vector<ch07::PacketKernel> result;
    for (const ch07::PacketKernel& k : ch07::built_kernels())
        if (ch07::cpu_runs(k)) result.push_back(k);
    return result;
}

std::vector<ch06::TriangleVertices> vertices_of(const std::vector<TriangleMesh>& meshes) {
    std::vector<ch06::TriangleVertices> vertices;
    for (const TriangleMesh& mesh : meshes)
        for (const auto& t : mesh.triangles)
            vertices.push_back({mesh.positions[t[0]], mesh.positions[t[1]], mesh.positions[t[2]]});
    return vertices;
}

bool same_bits(float a, float b) { return std::bit_cast<std::uint32_t>(a) == std::bit_cast<std::uint32_t>(b); }

struct LaneComparison {
    std::size_t lanes_tested = 0, hits = 0, edge_lanes = 0, mismatches = 0;
    std::string first_mismatch;
};

// Every ray against every triangle, packed `width` at a time with the last packet padded: each
// valid lane's answer (hit or not; t and b0, b1, b2 bits) against intersect_triangle's. Edge lanes
// are not compared: the kernel hands them to the scalar test, which decides them (the
// accelerator's conformance tests cover that path); they are counted, so that a caller can require
// that the path was taken, and a lane in both masks is a mismatch.
LaneComparison compare_lanes(const ch07::PacketKernel& kernel, const std::vector<ch06::TriangleVertices>& vertices,
                             const std::vector<Ray>& rays) {
    const int width = kernel.width;
    LaneComparison result;
    std::vector<float, CacheLineAllocator<float>> coordinates(ch07::packet_floats(width));
    std::vector<std::uint32_t> lanes(width);
    std::vector<std::uint32_t> order(vertices.size());
    for (std::uint32_t i = 0; i < order.size(); ++i) order[i] = i;
    ch07::PacketHits hits;
    for (const Ray& ray : rays) {
        const RayShear shear(ray.direction);
        const ch07::PacketRay packet_ray = ch07::make_packet_ray(ray, shear);
        for (std::size_t first = 0; first < vertices.size(); first += width) {
            const int count = static_cast<int>(std::min<std::size_t>(width, vertices.size() - first));
            ch07::pack_triangles(vertices, order.data() + first, count, width, coordinates.data(), lanes.data());
            kernel.test(packet_ray, coordinates.data(), ch07::first_lanes(static_cast<std::uint32_t>(count)), hits);
            // Padded lanes repeat a real triangle, so a ray through it would hit them: they
            // must be in neither mask.
            if ((hits.hit_lanes | hits.edge_lanes) >> count) {
                ++result.mismatches;
                if (result.first_mismatch.empty()) result.first_mismatch = "a padded lane was reported, ray " + describe_ray(ray);
            }
            for (int lane = 0; lane < count; ++lane) {
                ++result.lanes_tested;
                const ch06::TriangleVertices& v = vertices[lanes[lane]];
                const auto scalar = intersect_triangle(ray, shear, v.p0, v.p1, v.p2);
                const bool on_edge = (hits.edge_lanes >> lane) & 1u;
                const bool hit = (hits.hit_lanes >> lane) & 1u;
                if (on_edge) {
                    ++result.edge_lanes;
                    if (hit) {
                        ++result.mismatches;
                        if (result.first_mismatch.empty()) result.first_mismatch = "a lane in both masks";
                    }
                    continue;
                }
                bool agree = hit == scalar.has_value();
                if (agree && hit)
                    agree = same_bits(hits.t[lane], scalar->t) && same_bits(hits.b0[lane], scalar->b0) &&
                            same_bits(hits.b1[lane], scalar->b1) && same_bits(hits.b2[lane], scalar->b2);
                if (!agree) {
                    ++result.mismatches;
                    if (result.first_mismatch.empty())
                        result.first_mismatch = "triangle " + std::to_string(lanes[lane]) + ", ray " + describe_ray(ray) +
                                                (scalar ? ", scalar hit" : ", scalar miss") + (hit ? ", kernel hit" : ", kernel miss");
                }
                result.hits += hit ? 1 : 0;
            }
        }
    }
    return result;
}

}  // namespace

TEST_CASE("kdtree-simd: every kernel answers lane by lane as the scalar test, to the bit", "[unit][kdtree][ch07]") {
    // Closed, shared-edge, tiny and random geometry, with rays aimed at vertices and edges and
    // along the axes (mixed_rays), so that the double-precision edge lanes are exercised too.
    std::vector<TriangleMesh> meshes{icosphere(1), random_soup(60, 0.3f, 11), planar_grid(4, 0.25f)};
    // Triangles of 1 ulp: a sliver whose vertices differ in the last bit of one coordinate.
    const float one = 1.0f, next = std::nextafter(1.0f, 2.0f);
    meshes.push_back(make_mesh({{one, 0.5f, 0.5f}, {next, 0.5f, 0.5f}, {one, std::nextafter(0.5f, 1.0f), 0.5f}}, {{0, 1, 2}}));
    const std::vector<ch06::TriangleVertices> vertices = vertices_of(meshes);
    const std::vector<Ray> rays = mixed_rays(meshes, box(Vec3(-2.0f), Vec3(2.0f)), 3000, 21);
    for (const ch07::PacketKernel& kernel : runnable_kernels()) {
        const LaneComparison c = compare_lanes(kernel, vertices, rays);
        INFO(kernel.instructions << " (width " << kernel.width << "): " << c.mismatches << " of " << c.lanes_tested
                                 << " lanes differ; first: " << c.first_mismatch);
        CHECK(c.lanes_tested == rays.size() * vertices.size());
        CHECK(c.mismatches == 0);
        // The comparison means something only if there were hits and edge lanes to compare.
        CHECK(c.hits > 1000);
        CHECK(c.edge_lanes > 10);
    }
}

TEST_CASE("kdtree-simd: leaves of 1, W-1, W and W+1 triangles agree with brute force at every width", "[unit][kdtree][ch07]") {
    // n copies of one triangle cannot be split: one leaf of n triangles, whose hits tie and go to
    // the lowest index; a second, tilted triangle beside them makes a second leaf of one.
    for (const ch07::PacketKernel& kernel : runnable_kernels()) {
        const int w = kernel.width;
        for (const int n : {1, w - 1, w, w + 1, 2 * w + 1}) {
            if (n < 1) continue;
            std::vector<Vec3> positions;
            std::vector<std::array<std::uint32_t, 3>> triangles;
            for (int i = 0; i < n; ++i) {
                const auto base = static_cast<std::uint32_t>(positions.size());
                positions.insert(positions.end(), {{-1, -1, 0}, {1, -1, 0}, {0, 1, 0}});
                triangles.push_back({base, base + 1, base + 2});
            }
            const std::vector<TriangleMesh> meshes{make_mesh(positions, triangles),
                                                   make_mesh({{3, -1, -1}, {4, -1, 1}, {3.5f, 1, 0}}, {{0, 1, 2}})};
            const AcceleratorUnderTest simd{"kdtree-simd (width " + std::to_string(w) + ")", "kdtree-simd",
                                            nlohmann::json{{"simd_width", w}}};
            const Conformance c =
                compare_with_brute_force(simd, meshes, mixed_rays(meshes, box(Vec3(-5.0f), Vec3(5.0f)), 4000, 31 + n), 7);
            INFO(simd.label << ", " << n << " copies: " << c.mismatches << " differ\n" << c.report);
            CHECK(c.mismatches == 0);

            // The packets are as many as the leaves' triangles need, padded.
            ch07::KdTreeSimdSettings settings;
            settings.simd_width = w;
            ch07::KdTreeSimdAccelerator accelerator(settings);
            accelerator.build(meshes);
            std::size_t expected_packets = 0;
            for (const ch06::KdTreeNode& node : accelerator.packets().tree().nodes)
                if (node.is_leaf()) expected_packets += (node.triangle_count() + w - 1) / w;
            CHECK(accelerator.packets().packet_count() == expected_packets);
            CHECK(accelerator.packets().triangle_count() >= static_cast<std::size_t>(n + 1));
        }
    }
}

TEST_CASE("kdtree-simd: images are those of kdtree, bit for bit, at every width", "[unit][kdtree][ch07]") {
    TestRender request;
    request.scene = scene_path("cornell-box/scene.json");
    request.integrator = "pt-mis";
    request.samples_per_pixel = 4;
    request.width = 48;
    request.height = 48;
    request.accelerator = "kdtree";
    const RenderResult expected = render(request);
    for (const ch07::PacketKernel& kernel : runnable_kernels()) {
        INFO(kernel.instructions << " (width " << kernel.width << ")");
        request.accelerator = "kdtree-simd";
        request.accelerator_settings = {{"simd_width", kernel.width}};
        const RenderResult found = render(request);
        CHECK(bit_identical(found.image, expected.image));
    }
}

TEST_CASE("kdtree-simd: a width the processor cannot run is refused with the widths it can", "[unit][kdtree][ch07]") {
    const nlohmann::json json{{"simd_width", 3}};
    const Parameters parameters(json, "scene.json", "/accelerator", ".");
    try {
        ch07::read_kdtree_simd_settings(parameters);
        FAIL("a width of 3 was accepted");
    } catch (const InputError& e) {
        INFO(e.what());
        CHECK(std::string(e.what()).find("/accelerator/simd_width") != std::string::npos);
        CHECK(std::string(e.what()).find("no kernel of width 3") != std::string::npos);
    }
    for (const ch07::PacketKernel& k : ch07::built_kernels()) {
        if (ch07::cpu_runs(k)) continue;
        const Parameters lacking(nlohmann::json{{"simd_width", k.width}}, "scene.json", "/accelerator", ".");
        CHECK_THROWS_WITH(ch07::read_kdtree_simd_settings(lacking), Catch::Contains(std::string("needs ") + k.instructions));
    }
    // describe() says which width was chosen.
    ch07::KdTreeSimdAccelerator accelerator;
    accelerator.build({icosphere(1)});
    bool has_width = false;
    for (const auto& [key, value] : accelerator.describe())
        if (key == "simd width") has_width = value.find(std::to_string(ch07::widest_kernel().width)) == 0;
    CHECK(has_width);
}

TEST_CASE("kdtree-simd: with chapter 06's leaf cost, the walk is kdtree's and a leaf's tests are its packets", "[unit][kdtree][ch07]") {
    // The same tree (--simd-leaf-cost triangles) visits the same nodes and leaves for every ray;
    // where kdtree tests n triangles in a leaf, kdtree-simd tests ceil(n / W) packets.
    const std::vector<TriangleMesh> meshes{icosphere(2), random_soup(300, 0.2f, 5)};
    const std::vector<Ray> rays = mixed_rays(meshes, box(Vec3(-2.0f), Vec3(2.0f)), 3000, 41);
    ch06::KdTreeAccelerator tree;
    tree.build(meshes);
    for (const ch07::PacketKernel& kernel : runnable_kernels()) {
        ch07::KdTreeSimdSettings settings;
        settings.simd_width = kernel.width;
        settings.packet_leaf_cost = false;
        ch07::KdTreeSimdAccelerator simd(settings);
        simd.build(meshes);
        REQUIRE(simd.packets().tree().nodes.size() == tree.tree().nodes.size());
        std::size_t fewer_tests = 0, more_tests = 0;
        for (const Ray& ray : rays) {
            const ch06::TraversalCounts a = tree.count_traversal(ray), b = simd.count_traversal(ray);
            INFO(kernel.instructions << ", ray " << describe_ray(ray));
            REQUIRE(a.interior_nodes == b.interior_nodes);
            REQUIRE(a.leaves == b.leaves);
            fewer_tests += b.triangle_tests < a.triangle_tests ? 1 : 0;
            more_tests += b.triangle_tests > a.triangle_tests ? 1 : 0;
        }
        INFO(kernel.instructions);
        CHECK(more_tests == 0);
        if (kernel.width > 1) CHECK(fewer_tests > 0);
        else CHECK(fewer_tests == 0);  // one lane: a packet is a triangle
    }
}

TEST_CASE("kdtree-simd: the automatic depth limit counts packets, round(8 + 1.3 log2(N / W))", "[unit][kdtree][ch07]") {
    // Sponza's 262,266 triangles: 31 for one triangle per test (chapter 06, pbrt-v3's rule), and
    // the same rule for N / W: 26 at W = 16, 28 at 8, 29 at 4. Fewer triangles than a packet: 8.
    ch06::KdTreeSettings settings;
    CHECK(ch06::effective_max_depth(settings, 262266) == 31);
    const std::pair<int, int> expected[] = {{4, 29}, {8, 28}, {16, 26}};
    for (const auto& [width, depth] : expected) {
        settings.triangles_per_test = width;
        INFO("W = " << width);
        CHECK(ch06::effective_max_depth(settings, 262266) == depth);
        CHECK(ch06::effective_max_depth(settings, 3) == 8);
    }
    settings.max_depth = 20;  // an explicit depth is kept
    CHECK(ch06::effective_max_depth(settings, 262266) == 20);
}
