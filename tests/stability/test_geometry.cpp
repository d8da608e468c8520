// Hard geometry (scenes/hard/): grazing incidence, shared edges and vertices of a fan, a camera
// inside a closed mesh, degenerate triangles dropped at load, a triangle smaller than float
// epsilon of its coordinates.
#include "stability_support.hpp"

#include "freezeray/triangle_intersection.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace freezeray;
using namespace freezeray::stability;

namespace {

// Every pixel in `pixels` is exactly `value` in every sample: its mean is `value` to float
// rounding and its variance is zero to rounding.
void check_exact(const RenderResult& result, const std::vector<std::size_t>& pixels, float value,
                 const std::string& what) {
    std::size_t wrong = 0;
    std::string first;
    for (const std::size_t i : pixels) {
        const Spectrum& mean = result.image[i];
        const Spectrum& variance = result.variance[i];
        const bool exact = glm::all(glm::lessThanEqual(glm::abs(mean - Spectrum(value)), Spectrum(1e-5f * std::max(value, 1e-3f)))) &&
                           max_component(variance) <= 1e-10f * std::max(value * value, 1e-6f);
        if (!exact && wrong++ == 0)
            first = "pixel " + std::to_string(i) + ": mean (" + std::to_string(mean.r) + ", " + std::to_string(mean.g) +
                    ", " + std::to_string(mean.b) + "), variance " + std::to_string(max_component(variance));
    }
    INFO(what << ": " << wrong << " of " << pixels.size() << " pixels are not exactly " << value << "; the first: " << first);
    CHECK(wrong == 0u);
}

// How many triangles of the scene the ray meets in (0, tmax): the watertight test must report a
// ray through a shared edge or vertex on exactly one of the triangles sharing it.
int count_triangle_hits(const Scene& scene, const Ray& ray) {
    const RayShear shear(ray.direction);
    int hits = 0;
    for (const TriangleMesh& mesh : scene.meshes)
        for (const auto& t : mesh.triangles)
            if (intersect_triangle(ray, shear, mesh.positions[t[0]], mesh.positions[t[1]], mesh.positions[t[2]])) ++hits;
    return hits;
}

}  // namespace

TEST_CASE("grazing incidence: camera and light at cos theta 1e-4 to a plane of every material give valid samples",
          "[stability][geometry]") {
    for (const std::string& integrator : all_integrators()) {
        HardRender request;
        request.scene = "grazing/scene.json";
        request.integrator = integrator;
        request.samples_per_pixel = 64;
        request.seed = 41;
        const RenderResult result = render(request);
        check_valid(result, "grazing with " + integrator);
        // The wall and the plane's diffuse wedge are in view: the image is not all black.
        double sum = 0.0;
        for (const Spectrum& p : result.image.pixels()) sum += luminance(p);
        CHECK(sum > 0.0);
    }
}

TEST_CASE("the grazing camera rays really meet the plane at cos theta between 5e-5 and 3e-4", "[stability][geometry]") {
    // Guards the scene: the case stresses grazing angles only if its rays are grazing.
    const Scene scene = load("grazing/scene.json");
    const Camera& camera = *scene.camera;
    float smallest = 1.0f, largest = 0.0f;
    int plane_hits = 0;
    for (int y = 0; y < camera.height(); ++y) {
        for (int x = 0; x < camera.width(); ++x) {
            const Ray ray = camera.generate_ray(Vec2(x + 0.5f, y + 0.5f));
            const std::optional<Hit> hit = scene.intersect(ray);
            if (!hit || hit->geometric_normal.y < 0.5f) continue;  // the wall
            const float c = std::abs(glm::dot(ray.direction, hit->geometric_normal));
            smallest = std::min(smallest, c);
            largest = std::max(largest, c);
            ++plane_hits;
        }
    }
    INFO("cos theta from " << smallest << " to " << largest << " over " << plane_hits << " pixels");
    CHECK(plane_hits > 256);
    CHECK(smallest > 4e-5f);
    CHECK(largest < 3e-4f);
}

TEST_CASE("a fan's shared edges and vertex: every covered pixel is exactly 1, every ray hits exactly one triangle",
          "[stability][geometry]") {
    const Scene scene = load("fan/scene.json");
    const std::vector<std::size_t> disc = pixels_where(pixel_coverage(scene), 0);
    REQUIRE(disc.size() > 400u);
    for (const std::string& integrator : all_integrators()) {
        HardRender request;
        request.scene = "fan/scene.json";
        request.integrator = integrator;
        request.samples_per_pixel = 64;
        request.seed = 42;
        const RenderResult result = render(request);
        check_valid(result, "fan with " + integrator);
        check_exact(result, disc, 1.0f, "fan with " + integrator);
    }

    // Rays from several points in front of the disc through its centre vertex (shared by all 64
    // triangles) and through points along each of its 64 shared edges.
    const TriangleMesh& fan = scene.meshes[0];
    const Vec3 centre = fan.positions[fan.triangles[0][0]];
    REQUIRE(centre == Vec3(0.0f));
    std::vector<Vec3> targets = {centre};
    for (const auto& t : fan.triangles)
        for (const float s : {1e-6f, 1e-3f, 0.25f, 0.5f, 0.999f}) targets.push_back(s * fan.positions[t[1]]);
    const Vec3 origins[] = {Vec3(0, 0, -2), Vec3(0.5f, -0.25f, -2), Vec3(-3, 1, -0.5f), Vec3(0.1f, 0.1f, -1e-3f)};
    int wrong = 0;
    std::string first;
    for (const Vec3& origin : origins) {
        for (const Vec3& target : targets) {
            const Ray ray{origin, glm::normalize(target - origin)};
            const int hits = count_triangle_hits(scene, ray);
            if (hits != 1 && wrong++ == 0)
                first = "ray to (" + std::to_string(target.x) + ", " + std::to_string(target.y) + ") from (" +
                        std::to_string(origin.x) + ", " + std::to_string(origin.y) + ", " + std::to_string(origin.z) +
                        ") hits " + std::to_string(hits) + " triangles";
        }
    }
    INFO(wrong << " rays through shared edges or the centre vertex do not hit exactly one triangle; the first: " << first);
    CHECK(wrong == 0);

    // Rays lying in the disc's plane, along its shared edges, meet no triangle (they are parallel
    // to all of them) and give no hit rather than a NaN.
    for (const auto& t : fan.triangles) {
        const Vec3 rim = fan.positions[t[1]];
        const Ray along{-2.0f * rim, glm::normalize(rim)};
        CHECK_FALSE(scene.intersect(along).has_value());
    }
}

TEST_CASE("a camera inside a closed mesh looking into a corner sees exactly 1 at every pixel", "[stability][geometry]") {
    const Scene scene = load("inside-closed-mesh/scene.json");
    const std::vector<int> coverage = pixel_coverage(scene);
    const std::vector<std::size_t> everything = pixels_where(coverage, 0);
    REQUIRE(everything.size() == coverage.size());  // no pixel sees outside the cube
    for (const std::string& integrator : all_integrators()) {
        HardRender request;
        request.scene = "inside-closed-mesh/scene.json";
        request.integrator = integrator;
        request.samples_per_pixel = 64;
        request.seed = 43;
        const RenderResult result = render(request);
        check_valid(result, "inside-closed-mesh with " + integrator);
        check_exact(result, everything, 1.0f, "inside-closed-mesh with " + integrator);
    }
}

TEST_CASE("degenerate triangles are dropped at load with a counted warning and the rest renders",
          "[stability][geometry]") {
    const Scene scene = load("degenerate-triangles/scene.json");
    CHECK(scene.triangle_count() == 2u);
    std::size_t naming = 0;
    for (const std::string& warning : scene.warnings)
        if (warning.find("degenerate.obj") != std::string::npos && warning.find("dropped 6 degenerate") != std::string::npos)
            ++naming;
    INFO("warnings:\n" << [&] {
        std::string all;
        for (const std::string& w : scene.warnings) all += "  " + w + "\n";
        return all;
    }());
    // Exactly one warning names the file and the count (not repeated by load_scene).
    CHECK(naming == 1u);
    for (const TriangleMesh& mesh : scene.meshes)
        for (const Vec3& p : mesh.positions) CHECK((std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z)));

    const std::vector<std::size_t> square = pixels_where(pixel_coverage(scene), 0);
    REQUIRE(square.size() > 64u);
    for (const std::string& integrator : all_integrators()) {
        HardRender request;
        request.scene = "degenerate-triangles/scene.json";
        request.integrator = integrator;
        request.samples_per_pixel = 16;
        request.seed = 44;
        const RenderResult result = render(request);
        check_valid(result, "degenerate-triangles with " + integrator);
        check_exact(result, square, 1.0f, "degenerate-triangles with " + integrator);
    }
}

TEST_CASE("a triangle smaller than float epsilon of its coordinates has a finite unit normal and renders",
          "[stability][geometry]") {
    const Scene scene = load("tiny-triangle/scene.json");
    // Both tiny triangles survive loading: they are tiny, not degenerate.
    const TriangleMesh* tiny = nullptr;
    for (const TriangleMesh& mesh : scene.meshes)
        if (mesh.triangle_count() == 2) tiny = &mesh;
    REQUIRE(tiny != nullptr);
    // Each has a right angle at its first vertex p0 with legs of one ulp along +y and +x, so its
    // inside holds no representable point: rays from one leg length in front of p0 (on -z) go to
    // its centroid and to another inner point, as the camera's rays do.
    for (const auto& t : tiny->triangles) {
        const Vec3 p0 = tiny->positions[t[0]];
        const float leg = tiny->positions[t[1]].y - p0.y;
        REQUIRE(leg > 0.0f);
        for (const Vec3& towards : {Vec3(1.0f, 1.0f, 3.0f), Vec3(1.0f, 2.0f, 4.0f)}) {
            const Ray ray{p0 - Vec3(0.0f, 0.0f, leg), glm::normalize(towards)};
            const std::optional<Hit> hit = scene.intersect(ray);
            REQUIRE(hit.has_value());
            INFO("hit at (" << hit->position.x << ", " << hit->position.y << ", " << hit->position.z << "), normal ("
                            << hit->geometric_normal.x << ", " << hit->geometric_normal.y << ", "
                            << hit->geometric_normal.z << ")");
            CHECK(hit->mesh == static_cast<std::uint32_t>(tiny - scene.meshes.data()));
            CHECK(std::abs(glm::length(hit->geometric_normal) - 1.0f) < 1e-5f);
            CHECK(std::abs(glm::length(hit->shading_normal) - 1.0f) < 1e-5f);
            CHECK(hit->geometric_normal.z == Approx(-1.0f));
        }
    }

    // The render: pixels seeing only the triangle are 0.5 (a convex white object of albedo 0.5
    // under uniform radiance 1; exact per sample for pt-is), pixels seeing only the enclosure 1.
    const std::vector<int> coverage = pixel_coverage(scene);
    const int tiny_index = static_cast<int>(tiny - scene.meshes.data());
    const std::vector<std::size_t> triangle_pixels = pixels_where(coverage, tiny_index);
    const std::vector<std::size_t> enclosure_pixels = pixels_where(coverage, 0);
    REQUIRE(triangle_pixels.size() > 16u);
    for (const std::string& integrator : all_integrators()) {
        HardRender request;
        request.scene = "tiny-triangle/scene.json";
        request.integrator = integrator;
        request.samples_per_pixel = 64;
        request.seed = 45;
        const RenderResult result = render(request);
        check_valid(result, "tiny-triangle with " + integrator);
        check_exact(result, enclosure_pixels, 1.0f, "tiny-triangle (enclosure) with " + integrator);
        if (integrator == "pt-is") check_exact(result, triangle_pixels, 0.5f, "tiny-triangle (triangle) with pt-is");
    }
}
