// Chapter 10's light BVH, alone and in its defensive mixture with uniform choice (`bvh`): the
// probability each reports for a choice is the one probability() gives (bit for bit), the
// probabilities of all lights sum to one, the choices follow them (chi-square), a light gets
// probability 0 only where it sends no light at all, the mixture keeps every light at least its
// uniform share, and the cone and bounds the tree builds contain what they bound. Six statistical
// tests (the chi-square tests over lights, three per sampler, at unit_test_alpha each;
// tests/STATISTICS.md counts them); the rest is deterministic.
#include "freezeray/ch03/area_light.hpp"
#include "freezeray/ch03/directional_light.hpp"
#include "freezeray/ch03/environment_light.hpp"
#include "freezeray/ch03/point_light.hpp"
#include "freezeray/ch03/spot_light.hpp"
#include "freezeray/ch10/bvh_light_sampler.hpp"
#include "freezeray/ch10/defensive_light_sampler.hpp"
#include "freezeray/ch10/light_bounds.hpp"
#include "freezeray/random.hpp"

#include "chi_square.hpp"
#include "statistics.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

using namespace freezeray;
using namespace freezeray::ch10;

namespace {

Vec3 uniform_in_box(PCG32& random, const Vec3& low, const Vec3& high) {
    return low + (high - low) * Vec3(random.next_float(), random.next_float(), random.next_float());
}

Vec3 uniform_direction(PCG32& random) {
    const float z = 1.0f - 2.0f * random.next_float(), phi = 2.0f * Pi * random.next_float();
    const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
    return Vec3(r * std::cos(phi), r * std::sin(phi), z);
}

// A scene's worth of lights: `triangles` small emissive triangles spread over a 20 x 4 x 20 box
// facing every way, with radiances over three orders of magnitude, point and spot lights, one
// dark light and, when asked, a directional and a constant environment light.
struct ManyLights {
    TriangleMesh mesh;
    std::vector<std::unique_ptr<Light>> lights;

    ManyLights(int triangles, bool infinite, std::uint64_t seed) {
        PCG32 random(seed, 7);
        for (int i = 0; i < triangles; ++i) {
            const Vec3 c = uniform_in_box(random, Vec3(-10.0f, 0.0f, -10.0f), Vec3(10.0f, 4.0f, 10.0f));
            const auto base = static_cast<std::uint32_t>(mesh.positions.size());
            for (int k = 0; k < 3; ++k) mesh.positions.push_back(c + 0.3f * uniform_direction(random));
            mesh.triangles.push_back({base, base + 1, base + 2});
        }
        for (int i = 0; i < triangles; ++i) {
            const float radiance = std::pow(10.0f, 3.0f * random.next_float());
            lights.push_back(std::make_unique<ch03::TriangleLight>(mesh, static_cast<std::uint32_t>(i), Spectrum(radiance)));
        }
        for (int i = 0; i < 8; ++i)
            lights.push_back(std::make_unique<ch03::PointLight>(uniform_in_box(random, Vec3(-10.0f), Vec3(10.0f)),
                                                                Spectrum(1.0f + 50.0f * random.next_float())));
        for (int i = 0; i < 4; ++i)
            lights.push_back(std::make_unique<ch03::SpotLight>(uniform_in_box(random, Vec3(-10.0f), Vec3(10.0f)), uniform_direction(random),
                                                               Spectrum(30.0f), std::cos(0.5f), std::cos(0.3f)));
        lights.push_back(std::make_unique<ch03::PointLight>(Vec3(0.0f), Spectrum(0.0f)));  // dark
        if (infinite) {
            lights.push_back(std::make_unique<ch03::DirectionalLight>(glm::normalize(Vec3(1.0f, -2.0f, 0.5f)), Spectrum(3.0f)));
            lights.push_back(std::make_unique<ch03::ConstantEnvironmentLight>(Spectrum(0.5f)));
        }
        for (std::size_t i = 0; i < lights.size(); ++i) lights[i]->index = static_cast<std::uint32_t>(i);
    }
};

// The two samplers chapter 10 registers: the tree alone (`bvh-tree`) and the tree with its
// defensive share of uniform choices (`bvh`).
struct NamedSampler {
    const char* name;
    std::unique_ptr<LightSampler> sampler;
};

std::vector<NamedSampler> chapter10_samplers(const std::vector<std::unique_ptr<Light>>& lights) {
    std::vector<NamedSampler> samplers;
    samplers.push_back({"bvh-tree", std::make_unique<BvhLightSampler>(lights)});
    samplers.push_back({"bvh", std::make_unique<DefensiveLightSampler>(std::make_unique<BvhLightSampler>(lights), lights, DefensiveShare)});
    return samplers;
}

ShadingPoint random_point(PCG32& random) {
    ShadingPoint p;
    p.position = uniform_in_box(random, Vec3(-14.0f, -4.0f, -14.0f), Vec3(14.0f, 8.0f, 14.0f));
    if (random.next_float() < 0.8f) p.normal = uniform_direction(random);  // else a point without a surface
    if (p.normal != Vec3(0.0f) && random.next_float() < 0.4f) {
        // A glossy lobe, from nearly a mirror (alpha 0.001, where D falls to alpha^4 = 1e-12 of its
        // peak away from the axis) to very rough.
        p.lobe_axis = uniform_direction(random);
        p.lobe_alpha = std::pow(10.0f, -3.0f + 3.0f * random.next_float());
    }
    return p;
}

}  // namespace

TEST_CASE("the light BVH reports the probability of each choice exactly as probability() gives it", "[unit][ch10]") {
    for (bool infinite : {false, true}) {
        const ManyLights scene(150, infinite, 11);
        for (const auto& [name, sampler] : chapter10_samplers(scene.lights)) {
            PCG32 random(3, 5);
            int chosen = 0;
            for (int k = 0; k < 2000; ++k) {
                const ShadingPoint point = random_point(random);
                for (int j = 0; j < 20; ++j) {
                    const float u = random.next_float();
                    const std::optional<LightChoice> choice = sampler->sample(point, u);
                    if (!choice) continue;
                    ++chosen;
                    INFO(name << ": point (" << point.position.x << ", " << point.position.y << ", " << point.position.z << "), u " << u);
                    REQUIRE(choice->probability > 0.0f);
                    REQUIRE(choice->probability == sampler->probability(point, *choice->light));  // bit for bit
                }
            }
            INFO(name);
            CHECK(chosen > 30000);
        }
    }
}

TEST_CASE("the light BVH's probabilities of all lights at a point sum to at most one", "[unit][ch10]") {
    // Less than one where the walk can end at a node whose two children both send nothing to the
    // point, though their union's looser bounds did not exclude it: sample() then chooses nothing
    // (the chi-square test below counts how often). Each probability is a product of up to
    // depth + 1 ratios, each rounded once in float: with a depth of 16 here the relative error of
    // each is below 40 ulp, 2.4e-6; allowed 1e-5.
    for (bool infinite : {false, true}) {
        const ManyLights scene(300, infinite, 12);
        const BvhLightSampler sampler(scene.lights);
        PCG32 random(4, 5);
        double total = 0.0;
        for (int k = 0; k < 500; ++k) {
            const ShadingPoint point = random_point(random);
            double sum = 0.0;
            for (const auto& light : scene.lights) sum += sampler.probability(point, *light);
            INFO("point (" << point.position.x << ", " << point.position.y << ", " << point.position.z << ")");
            CHECK(sum <= 1.0 + 1e-5);
            total += sum;
        }
        // Most walks reach a light: a tree that often chose nothing would waste its samples.
        INFO("mean sum " << total / 500.0);
        CHECK(total / 500.0 > 0.8);
        CHECK(sampler.probability(random_point(random), *scene.lights[300 + 12]) == 0.0f);  // the dark light
    }
}

TEST_CASE("the light BVH chooses each light as often as the probability it reports (chi-square over lights)", "[unit][ch10]") {
    // Four shading points (inside the cloud of lights, below it, beside it with the infinite
    // lights, below it with a glossy lobe), 400,000 choices each, for the tree and for its defensive mixture: one chi-square
    // test each at unit_test_alpha, a cell per light and one for the walks that choose nothing
    // (expected N (1 - the probabilities' sum)), cells expecting fewer than 5 choices pooled.
    const ManyLights scene(200, true, 13);
    const ShadingPoint points[] = {{Vec3(1.0f, 2.0f, -3.0f), glm::normalize(Vec3(0.2f, 1.0f, 0.1f))},
                                   {Vec3(0.0f, -3.0f, 4.0f), Vec3(0.0f, 1.0f, 0.0f)},
                                   {Vec3(13.0f, 1.0f, 0.0f), Vec3(0.0f)},
                                   {Vec3(0.0f, -3.0f, 4.0f), Vec3(0.0f, 1.0f, 0.0f), glm::normalize(Vec3(0.3f, 1.0f, -0.4f)), 0.05f}};
    constexpr int choices = 400000;
    std::uint64_t seed = 1001;
    for (const auto& [name, sampler] : chapter10_samplers(scene.lights)) {
        for (const ShadingPoint& point : points) {
            PCG32 random(seed++, 3);
            const std::size_t none = scene.lights.size();  // the cell of walks that choose nothing
            std::vector<double> observed(none + 1, 0.0), expected(none + 1, 0.0);
            for (int k = 0; k < choices; ++k) {
                const std::optional<LightChoice> choice = sampler->sample(point, random.next_float());
                observed[choice ? choice->light->index : none] += 1.0;
            }
            double sum = 0.0;
            for (const auto& light : scene.lights) {
                expected[light->index] = choices * static_cast<double>(sampler->probability(point, *light));
                sum += sampler->probability(point, *light);
            }
            // A sum that is 1 but for rounding expects well under one walk there: the cell is pooled.
            expected[none] = choices * std::max(0.0, 1.0 - sum);
            std::uint64_t in_empty_cells = 0;  // chosen where its probability is 0
            const auto [statistic, cells] = stats::pooled_statistic(observed, expected, 5.0, in_empty_cells);
            INFO(name << ": point (" << point.position.x << ", " << point.position.y << ", " << point.position.z
                      << "), sum of probabilities " << sum);
            REQUIRE(in_empty_cells == 0u);
            REQUIRE(cells > 50);
            const double p_value = stats::chi_square_survival(statistic, cells - 1);
            INFO("chi^2 = " << statistic << " over " << cells << " cells, p = " << p_value);
            CHECK(p_value > stats::unit_test_alpha);
        }
    }
}

TEST_CASE("the defensive mixture keeps every light at least its uniform share", "[unit][ch10]") {
    // p = (1 - share) p_tree + share / N for every light, wherever the tree leaves it out (seen
    // from behind, outside a spot's cone, the dark light); the probabilities sum to the tree's
    // sum mixed with 1; share 0 gives the tree's probabilities to the bit; a share outside [0, 1)
    // is refused.
    const ManyLights scene(120, true, 15);
    const BvhLightSampler tree(scene.lights);
    const DefensiveLightSampler mixture(std::make_unique<BvhLightSampler>(scene.lights), scene.lights, DefensiveShare);
    const DefensiveLightSampler none(std::make_unique<BvhLightSampler>(scene.lights), scene.lights, 0.0f);
    const float uniform = 1.0f / static_cast<float>(scene.lights.size());
    PCG32 random(21, 3);
    int left_out_by_tree = 0;
    for (int k = 0; k < 500; ++k) {
        const ShadingPoint point = random_point(random);
        double tree_sum = 0.0, mixture_sum = 0.0;
        for (const auto& light : scene.lights) {
            const float p_tree = tree.probability(point, *light), p = mixture.probability(point, *light);
            INFO("light " << light->index << " at point (" << point.position.x << ", " << point.position.y << ", "
                          << point.position.z << ")");
            REQUIRE(p == (1.0f - DefensiveShare) * p_tree + DefensiveShare * uniform);
            REQUIRE(p >= DefensiveShare * uniform);
            REQUIRE(none.probability(point, *light) == p_tree);
            left_out_by_tree += p_tree == 0.0f ? 1 : 0;
            tree_sum += p_tree;
            mixture_sum += p;
        }
        CHECK(mixture_sum == Approx((1.0 - DefensiveShare) * tree_sum + DefensiveShare).epsilon(1e-5));
    }
    CHECK(left_out_by_tree > 1000);  // the case happens
    CHECK_THROWS(DefensiveLightSampler(std::make_unique<BvhLightSampler>(scene.lights), scene.lights, 1.0f));
    CHECK_THROWS(DefensiveLightSampler(std::make_unique<BvhLightSampler>(scene.lights), scene.lights, -0.1f));
}

TEST_CASE("the light BVH gives a light probability 0 only where it sends no light at all", "[unit][ch10]") {
    // Where a light's probability is 0, it must send nothing: a one-sided triangle has the point
    // behind its plane (every sample_li fails), a spot light has it outside its cone. Points on
    // the lights' planes and at grazing angles to the point's surface keep a probability.
    const ManyLights scene(120, false, 14);
    const BvhLightSampler sampler(scene.lights);
    PCG32 random(8, 9);
    int zero = 0, checked = 0;
    for (int k = 0; k < 3000; ++k) {
        const ShadingPoint point = random_point(random);
        for (const auto& light : scene.lights) {
            if (sampler.probability(point, *light) > 0.0f) continue;
            if (light->power() == Spectrum(0.0f)) continue;  // the dark light: nothing to send
            ++zero;
            for (int j = 0; j < 16; ++j) {
                const Vec2 u(random.next_float(), random.next_float());
                const std::optional<LightSample> s = light->sample_li(point.position, u);
                INFO("light " << light->index << " at point (" << point.position.x << ", " << point.position.y << ", "
                              << point.position.z << ")");
                REQUIRE((!s || is_black(s->radiance)));
                ++checked;
            }
        }
    }
    CHECK(zero > 1000);  // the case happens (one-sided triangles seen from behind)

    // A triangle seen exactly edge-on, and a point light exactly in the plane of the point's
    // surface: both keep a probability.
    TriangleMesh mesh;
    mesh.positions = {Vec3(-1.0f, 0.0f, -1.0f), Vec3(1.0f, 0.0f, -1.0f), Vec3(0.0f, 0.0f, 1.0f)};  // faces -y or +y
    mesh.triangles = {{0u, 1u, 2u}};
    std::vector<std::unique_ptr<Light>> two;
    two.push_back(std::make_unique<ch03::TriangleLight>(mesh, 0, Spectrum(1.0f)));
    two.push_back(std::make_unique<ch03::PointLight>(Vec3(5.0f, 3.0f, 0.0f), Spectrum(1.0f)));
    for (std::size_t i = 0; i < two.size(); ++i) two[i]->index = static_cast<std::uint32_t>(i);
    const BvhLightSampler pair(two);
    const ShadingPoint in_plane{Vec3(5.0f, 0.0f, 0.0f), Vec3(0.0f, 1.0f, 0.0f)};  // the triangle's plane; the point light above
    CHECK(pair.probability(in_plane, *two[0]) > 0.0f);
    const ShadingPoint grazing{Vec3(0.0f, 3.0f, 0.0f), Vec3(0.0f, 1.0f, 0.0f)};  // the point light in its tangent plane
    CHECK(pair.probability(grazing, *two[1]) > 0.0f);
}

TEST_CASE("a cluster's bounds contain its lights' and its cone every direction of theirs", "[unit][ch10]") {
    PCG32 random(21, 1);
    for (int k = 0; k < 20000; ++k) {
        const DirectionCone a{uniform_direction(random), 1.0f - 2.0f * random.next_float() * random.next_float()};
        const DirectionCone b{uniform_direction(random), 1.0f - 2.0f * random.next_float() * random.next_float()};
        const DirectionCone u = cone_union(a, b);
        // Every direction of a and b: their axes, and directions on their rims.
        for (const DirectionCone& c : {a, b}) {
            const Frame frame(c.w);
            const float sin_c = std::sqrt(std::max(0.0f, 1.0f - c.cos_theta * c.cos_theta));
            for (int j = 0; j < 16; ++j) {
                const float phi = 2.0f * Pi * static_cast<float>(j) / 16.0f;
                const Vec3 d = frame.to_world(Vec3(sin_c * std::cos(phi), sin_c * std::sin(phi), c.cos_theta));
                INFO("cone " << k << ", rim direction " << j);
                REQUIRE(glm::dot(glm::normalize(d), u.w) >= u.cos_theta - 1e-6f);
            }
        }
    }
    const ManyLights scene(64, false, 15);
    const BvhLightSampler sampler(scene.lights);
    const auto& nodes = sampler.nodes();
    const auto& bounds = sampler.node_bounds();
    REQUIRE(bounds.size() == nodes.size());
    // Every node's box holds its children's, and its power is theirs together; every node but
    // the root is the child of exactly one node, after it; every light in the tree is the child
    // of exactly one node; no node has more than LightTreeWidth children, and only a tree of one
    // light has a node of fewer than two.
    std::vector<int> parents(nodes.size(), 0), light_parents(scene.lights.size(), 0);
    int leaves = 0;
    for (std::size_t i = 0; i < nodes.size(); ++i) {
        REQUIRE(nodes[i].child_count >= 2);
        REQUIRE(nodes[i].child_count <= static_cast<std::uint32_t>(LightTreeWidth));
        double phi = 0.0;
        for (int k = 0; k < static_cast<int>(nodes[i].child_count); ++k) {
            LightBounds child_bounds;
            if (nodes[i].child_is_light(k)) {
                ++leaves;
                ++light_parents[nodes[i].child_index(k)];
                child_bounds = *bounds_of(*scene.lights[nodes[i].child_index(k)]);
            } else {
                const std::size_t child = nodes[i].child_index(k);
                REQUIRE(child > i);
                REQUIRE(child < nodes.size());
                ++parents[child];
                child_bounds = bounds[child];
            }
            for (int axis = 0; axis < 3; ++axis) {
                REQUIRE(bounds[i].box.min[axis] <= child_bounds.box.min[axis]);
                REQUIRE(bounds[i].box.max[axis] >= child_bounds.box.max[axis]);
            }
            phi += child_bounds.phi;
            REQUIRE(nodes[i].children.phi[k] == child_bounds.phi);
        }
        for (int k = static_cast<int>(nodes[i].child_count); k < LightTreeWidth; ++k) REQUIRE(nodes[i].children.phi[k] == 0.0f);
        REQUIRE(bounds[i].phi == Approx(phi).epsilon(1e-6));
    }
    CHECK(parents[0] == 0);
    for (std::size_t i = 1; i < nodes.size(); ++i) REQUIRE(parents[i] == 1);
    for (std::size_t i = 0; i < scene.lights.size(); ++i) REQUIRE(light_parents[i] == (bounds_of(*scene.lights[i])->phi > 0.0f ? 1 : 0));
    CHECK(leaves == 64 + 8 + 4);  // every light but the dark one, one per leaf
}

TEST_CASE("the light BVH with no lights, one light, and only infinite lights", "[unit][ch10]") {
    const std::vector<std::unique_ptr<Light>> none;
    const BvhLightSampler empty(none);
    CHECK_FALSE(empty.sample(ShadingPoint{}, 0.5f));

    std::vector<std::unique_ptr<Light>> one;
    one.push_back(std::make_unique<ch03::PointLight>(Vec3(0.0f, 1.0f, 0.0f), Spectrum(2.0f)));
    one[0]->index = 0;
    const BvhLightSampler single(one);
    const ShadingPoint point{Vec3(0.0f), Vec3(0.0f, 1.0f, 0.0f)};
    REQUIRE(single.sample(point, 0.7f));
    CHECK(single.sample(point, 0.7f)->probability == 1.0f);
    CHECK(single.probability(point, *one[0]) == 1.0f);

    std::vector<std::unique_ptr<Light>> sky;
    sky.push_back(std::make_unique<ch03::ConstantEnvironmentLight>(Spectrum(1.0f)));
    sky.push_back(std::make_unique<ch03::DirectionalLight>(Vec3(0.0f, -1.0f, 0.0f), Spectrum(1.0f)));
    for (std::size_t i = 0; i < sky.size(); ++i) sky[i]->index = static_cast<std::uint32_t>(i);
    const BvhLightSampler infinite(sky);
    CHECK(infinite.sample(point, 0.2f)->light == sky[0].get());
    CHECK(infinite.sample(point, 0.7f)->light == sky[1].get());
    CHECK(infinite.probability(point, *sky[1]) == 0.5f);
}

TEST_CASE("a glossy lobe at the point weighs each cluster by the distribution's shape, and leaves none out", "[unit][ch10]") {
    // lobe_factor's value where it is known exactly: 1 for a cluster on the lobe's axis, for one
    // holding the point and for one whose bounding sphere reaches the axis; D(psi / 2) / D(0) for
    // a point light psi from it (Trowbridge-Reitz: 1 / (cos^2 + sin^2 / alpha^2)^2 of psi / 2);
    // alpha^4 straight behind.
    const float alpha = 0.1f;
    const ShadingPoint point{Vec3(0.0f), Vec3(0.0f, 1.0f, 0.0f), Vec3(0.0f, 1.0f, 0.0f), alpha};
    auto bounds_at = [](Vec3 centre, float half_size) {
        LightBounds b;
        b.box.expand(centre - Vec3(half_size));
        b.box.expand(centre + Vec3(half_size));
        b.phi = 1.0f;
        b.cos_theta_o = -1.0f;
        b.cos_theta_e = 0.0f;
        return b;
    };
    auto factor = [&](const LightBounds& b) {
        LightClusterGroup group;
        group.set(0, b);
        return lobe_factor(group, point)[0];
    };
    CHECK(factor(bounds_at(Vec3(0.0f, 5.0f, 0.0f), 0.0f)) == 1.0f);
    CHECK(factor(bounds_at(Vec3(0.2f, 0.1f, 0.0f), 1.0f)) == 1.0f);                     // holds the point
    CHECK(factor(bounds_at(Vec3(2.0f, 4.0f, 0.0f), 1.5f)) == 1.0f);                     // reaches the axis
    for (float psi_degrees : {5.0f, 20.0f, 60.0f, 120.0f}) {
        const float psi = psi_degrees * Pi / 180.0f;
        const double c = std::cos(psi / 2.0), s = std::sin(psi / 2.0);
        const double expected = 1.0 / std::pow(c * c + s * s / (alpha * alpha), 2.0);
        INFO(psi_degrees << " degrees from the axis");
        CHECK(factor(bounds_at(Vec3(3.0f * std::sin(psi), 3.0f * std::cos(psi), 0.0f), 0.0f)) == Approx(expected).epsilon(1e-4));
    }
    CHECK(factor(bounds_at(Vec3(0.0f, -3.0f, 0.0f), 0.0f)) == Approx(std::pow(alpha, 4.0f)).epsilon(1e-3));

    // Two equal point lights, one on the lobe's axis and one 90 degrees from it: the lobe moves
    // the choice towards the first, and the second keeps a probability.
    std::vector<std::unique_ptr<Light>> two;
    two.push_back(std::make_unique<ch03::PointLight>(Vec3(0.0f, 4.0f, 0.0f), Spectrum(1.0f)));
    two.push_back(std::make_unique<ch03::PointLight>(Vec3(4.0f, 0.5f, 0.0f), Spectrum(1.0f)));
    for (std::size_t i = 0; i < two.size(); ++i) two[i]->index = static_cast<std::uint32_t>(i);
    const BvhLightSampler pair(two);
    ShadingPoint without = point;
    without.lobe_alpha = 0.0f;
    CHECK(pair.probability(point, *two[0]) > pair.probability(without, *two[0]));
    CHECK(pair.probability(point, *two[0]) > 0.99f);
    CHECK(pair.probability(point, *two[1]) > 0.0f);
    // A mirror-like lobe facing away from both: they keep their probabilities, in the same order.
    const ShadingPoint away{Vec3(0.0f), Vec3(0.0f, 1.0f, 0.0f), Vec3(0.0f, -1.0f, 0.0f), 0.001f};
    CHECK(pair.probability(away, *two[0]) > 0.0f);
    CHECK(pair.probability(away, *two[1]) > 0.0f);
    CHECK(pair.probability(away, *two[0]) + pair.probability(away, *two[1]) == Approx(1.0f));
}
