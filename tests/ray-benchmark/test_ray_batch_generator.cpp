// Making ray batches from a camera (chapters/06-kd-tree/benchmark/ray_batch_generator.cpp), on
// the Cornell box's mesh: primary rays through pixel centres hit it, diffuse rays leave into the
// hemisphere of the normal with a cosine distribution, shadow rays end at a point of the bounds.
#include "benchmark_mesh.hpp"
#include "ray_batch_generator.hpp"

#include "freezeray/accelerator.hpp"
#include "test_scenes.hpp"

#include <catch2/catch.hpp>

#include <bit>
#include <cmath>

using namespace freezeray;
using namespace freezeray::benchmark;

namespace {

// The camera of scenes/cornell-box/scene.json at a small resolution, with a field of view of 36
// degrees instead of 39.3: at 39.3 the outermost pixels look past the box's front edges.
CameraDescription cornell_camera(int size) {
    CameraDescription camera;
    camera.position = Vec3(278.0f, 273.0f, -800.0f);
    camera.look_at = Vec3(278.0f, 273.0f, 0.0f);
    camera.fov_vertical_degrees = 36.0f;
    camera.width = size;
    camera.height = size;
    return camera;
}

struct CornellBox {
    std::vector<TriangleMesh> meshes{load_benchmark_mesh(testing::scene_path("cornell-box/cornell-box.obj"))};
    BruteForceAccelerator accelerator;
    Bounds3 bounds = meshes.front().bounds();
    CornellBox() { accelerator.build(meshes); }

    RayBatches generate(int size, std::uint64_t seed = 1, std::size_t limit = std::numeric_limits<std::size_t>::max()) const {
        RayGenerationSettings settings;
        settings.camera = cornell_camera(size);
        settings.seed = seed;
        settings.limit = limit;
        return generate_ray_batches(accelerator, bounds, settings);
    }
};

bool same_bits(const Ray& a, const Ray& b) {
    auto bits = [](float x) { return std::bit_cast<std::uint32_t>(x); };
    for (int i = 0; i < 3; ++i)
        if (bits(a.origin[i]) != bits(b.origin[i]) || bits(a.direction[i]) != bits(b.direction[i])) return false;
    return bits(a.tmax) == bits(b.tmax);
}

}  // namespace

TEST_CASE("generated primary rays go through the pixel centres in scanline order and all hit the Cornell box",
          "[unit][ray-benchmark]") {
    const CornellBox box;
    const RayBatches batches = box.generate(32);
    const std::vector<Ray>& primary = batches.of(RayKind::Primary);
    REQUIRE(primary.size() == 32 * 32);
    const PinholeCamera camera(cornell_camera(32));
    for (std::size_t i = 0; i < primary.size(); ++i) {
        INFO("pixel " << i);
        const Ray expected = camera.generate_ray(Vec2(static_cast<float>(i % 32) + 0.5f, static_cast<float>(i / 32) + 0.5f));
        CHECK(same_bits(primary[i], expected));
        CHECK(std::isinf(primary[i].tmax));
        CHECK(box.accelerator.intersect(primary[i]).has_value());
    }
    // Row 0 is at the top (+y), and image right is forward x up (-x when looking along +z).
    CHECK(primary.front().direction.y > 0.0f);
    CHECK(primary.front().direction.x > 0.0f);
    CHECK(primary.back().direction.y < 0.0f);
    CHECK(primary.back().direction.x < 0.0f);
}

TEST_CASE("generated diffuse rays leave each primary hit, offset along its normal, into its hemisphere, by cosine",
          "[unit][ray-benchmark]") {
    const CornellBox box;
    const RayBatches batches = box.generate(32);
    const std::vector<Ray>& primary = batches.of(RayKind::Primary);
    const std::vector<Ray>& diffuse = batches.of(RayKind::Diffuse);
    REQUIRE(diffuse.size() == primary.size());  // every primary ray hits the box
    const float offset = 1e-4f * glm::length(box.bounds.diagonal());
    double cosine_sum = 0.0;
    for (std::size_t i = 0; i < diffuse.size(); ++i) {
        INFO("ray " << i);
        const std::optional<Hit> hit = box.accelerator.intersect(primary[i]);
        REQUIRE(hit);
        const Vec3 normal = facing_normal(*hit, primary[i].direction);
        CHECK(glm::dot(normal, primary[i].direction) < 0.0f);
        CHECK(glm::length(diffuse[i].origin - (hit->position + offset * normal)) <= 1e-3f * offset);
        CHECK(std::abs(glm::length(diffuse[i].direction) - 1.0f) < 1e-5f);
        const float cosine = glm::dot(diffuse[i].direction, normal);
        CHECK(cosine > 0.0f);
        cosine_sum += cosine;
        CHECK(std::isinf(diffuse[i].tmax));
    }
    // Cosine-weighted directions have E[cos] = 2/3 and Var[cos] = 1/2 - 4/9 = 1/18; uniform ones
    // would have E[cos] = 1/2. Five standard errors: a false failure has probability < 1e-6.
    const double mean = cosine_sum / static_cast<double>(diffuse.size());
    const double standard_error = std::sqrt(1.0 / 18.0 / static_cast<double>(diffuse.size()));
    INFO("mean cosine " << mean);
    CHECK(std::abs(mean - 2.0 / 3.0) < 5.0 * standard_error);
}

TEST_CASE("generated shadow rays start where the diffuse rays do and end at a point of the bounds (tmax = distance)",
          "[unit][ray-benchmark]") {
    const CornellBox box;
    const RayBatches batches = box.generate(32);
    const std::vector<Ray>& diffuse = batches.of(RayKind::Diffuse);
    const std::vector<Ray>& shadow = batches.of(RayKind::Shadow);
    REQUIRE(shadow.size() == diffuse.size());
    const float tolerance = 1e-5f * glm::length(box.bounds.diagonal());
    Vec3 target_sum(0.0f);
    for (std::size_t i = 0; i < shadow.size(); ++i) {
        INFO("ray " << i);
        CHECK(same_bits(Ray{shadow[i].origin, Vec3(0.0f), 0.0f}, Ray{diffuse[i].origin, Vec3(0.0f), 0.0f}));
        CHECK(std::isfinite(shadow[i].tmax));
        CHECK(shadow[i].tmax > 0.0f);
        CHECK(std::abs(glm::length(shadow[i].direction) - 1.0f) < 1e-5f);
        const Vec3 target = shadow[i].at(shadow[i].tmax);
        for (int axis = 0; axis < 3; ++axis) {
            CHECK(target[axis] >= box.bounds.min[axis] - tolerance);
            CHECK(target[axis] <= box.bounds.max[axis] + tolerance);
        }
        target_sum += target;
    }
    // Uniform targets: their mean is near the centre of the box (each coordinate's standard
    // error is its extent / sqrt(12 n), about 5 units here; allow 5 of them).
    const Vec3 mean = target_sum / static_cast<float>(shadow.size());
    const Vec3 centre = 0.5f * (box.bounds.min + box.bounds.max);
    const Vec3 allowed = 5.0f * box.bounds.diagonal() / std::sqrt(12.0f * static_cast<float>(shadow.size()));
    for (int axis = 0; axis < 3; ++axis) CHECK(std::abs(mean[axis] - centre[axis]) < allowed[axis]);
}

TEST_CASE("generated batches depend on the seed only, and a limit gives their first rays", "[unit][ray-benchmark]") {
    const CornellBox box;
    const RayBatches full = box.generate(24, 7);
    const RayBatches again = box.generate(24, 7);
    const RayBatches limited = box.generate(24, 7, 100);
    const RayBatches other_seed = box.generate(24, 8);
    for (RayKind kind : all_ray_kinds) {
        INFO(ray_kind_name(kind));
        REQUIRE(again.of(kind).size() == full.of(kind).size());
        for (std::size_t i = 0; i < full.of(kind).size(); ++i) CHECK(same_bits(again.of(kind)[i], full.of(kind)[i]));
        REQUIRE(limited.of(kind).size() == 100);
        for (std::size_t i = 0; i < 100; ++i) CHECK(same_bits(limited.of(kind)[i], full.of(kind)[i]));
    }
    // Primary rays do not depend on the seed; diffuse directions do.
    CHECK(same_bits(other_seed.of(RayKind::Primary)[5], full.of(RayKind::Primary)[5]));
    CHECK_FALSE(same_bits(other_seed.of(RayKind::Diffuse)[5], full.of(RayKind::Diffuse)[5]));
}

TEST_CASE("a camera that does not see the mesh gives primary rays and nothing else", "[unit][ray-benchmark]") {
    const CornellBox box;
    RayGenerationSettings settings;
    settings.camera = cornell_camera(8);
    settings.camera.look_at = Vec3(278.0f, 273.0f, -1600.0f);  // looking away from the box
    const RayBatches batches = generate_ray_batches(box.accelerator, box.bounds, settings);
    CHECK(batches.of(RayKind::Primary).size() == 64);
    CHECK(batches.of(RayKind::Diffuse).empty());
    CHECK(batches.of(RayKind::Shadow).empty());
}
