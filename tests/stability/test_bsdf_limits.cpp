// Every chapter 02 BSDF queried where its formulas are weakest: directions at grazing angles (cos
// theta from 0.7 down to 1e-30 and 0, on both sides), at the normal, roughness at and just above
// the smooth threshold, indices of refraction of 1 and below 1, k = 0. Deterministic: sample,
// eval and pdf must give finite, non-negative numbers and unit directions, whatever the input.
// The scenes of scenes/hard/ show the same cases in renders; these queries find the exact input.
#include "stability_support.hpp"

#include "test_scenes.hpp"

#include "freezeray/material.hpp"
#include "freezeray/random.hpp"
#include "freezeray/registry.hpp"
#include "freezeray/ch01/warps.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <sstream>

using namespace freezeray;
using namespace freezeray::ch01;
using json = nlohmann::json;

namespace {

std::unique_ptr<Material> make(const json& description) {
    const Parameters p(description, "test", "/materials/m", ".");
    const Registry& registry = testing::full_registry();
    return registry.materials.make(description.at("type").get<std::string>(), p.where("type"), p,
                                   MaterialContext{registry, registry.texture_layouts.default_name()});
}

// The materials queried: every type of chapter 02, at the limits of its parameters.
const std::vector<json>& limit_materials() {
    static const std::vector<json> materials = {
        {{"type", "diffuse"}, {"albedo", 1}},
        {{"type", "mirror"}},
        {{"type", "conductor"}, {"material", "gold"}},
        {{"type", "conductor"}, {"eta", 0.5}, {"k", 0}},
        {{"type", "conductor"}, {"eta", 1}, {"k", 0}},
        {{"type", "conductor"}, {"eta", 1.5}, {"k", 0}},
        {{"type", "conductor"}, {"specular_reflectance", 0}},
        {{"type", "conductor"}, {"specular_reflectance", 1}},
        {{"type", "roughconductor"}, {"material", "gold"}, {"roughness", 1e-4}},
        {{"type", "roughconductor"}, {"material", "gold"}, {"roughness", 0.0317}},
        {{"type", "roughconductor"}, {"material", "gold"}, {"roughness", 0.3}},
        {{"type", "roughconductor"}, {"material", "gold"}, {"roughness", 1}},
        {{"type", "roughconductor"}, {"eta", 1}, {"k", 0}, {"roughness", 0.3}},
        {{"type", "roughconductor"}, {"material", "silver"}, {"roughness_u", 0.0317}, {"roughness_v", 0}},
        {{"type", "roughconductor"}, {"material", "silver"}, {"roughness_u", 1}, {"roughness_v", 0.0317}},
        {{"type", "dielectric"}, {"ior", 1.5}},
        {{"type", "dielectric"}, {"ior", 1}},
        {{"type", "dielectric"}, {"ior", 0.67}},
        {{"type", "dielectric"}, {"ior", 10}},
        {{"type", "roughdielectric"}, {"ior", 1.5}, {"roughness", 0.0317}},
        {{"type", "roughdielectric"}, {"ior", 1.5}, {"roughness", 0.3}},
        {{"type", "roughdielectric"}, {"ior", 1.5}, {"roughness", 1}},
        {{"type", "roughdielectric"}, {"ior", 1}, {"roughness", 0.3}},
        {{"type", "roughdielectric"}, {"ior", 1.0001}, {"roughness", 0.3}},
        {{"type", "roughdielectric"}, {"ior", 0.67}, {"roughness", 0.3}},
        {{"type", "roughdielectric"}, {"ior", 1.5}, {"roughness_u", 0.0317}, {"roughness_v", 0}},
        {{"type", "plastic"}, {"albedo", 1}, {"ior", 1.5}},
        {{"type", "plastic"}, {"albedo", 1}, {"ior", 1}},
        {{"type", "roughplastic"}, {"albedo", 1}, {"ior", 1.5}, {"roughness", 0.0317}},
        {{"type", "roughplastic"}, {"albedo", 1}, {"ior", 1.5}, {"roughness", 1}},
        {{"type", "mix"},
         {"first", {{"type", "diffuse"}, {"albedo", 1}}},
         {"second", {{"type", "roughconductor"}, {"material", "gold"}, {"roughness", 0.0317}}},
         {"weight", 0.5}},
    };
    return materials;
}

// Directions towards the viewer: cos theta from 1 down to 0, on both sides, at a few azimuths.
std::vector<Vec3> limit_directions() {
    const float cosines[] = {1.0f, 0.7f, 0.1f, 1e-2f, 1e-3f, 1e-4f, 1e-5f, 1e-6f, 1e-7f, 1e-8f, 1e-30f, 0.0f};
    const float azimuths[] = {0.0f, 0.3f, 1.0f, 2.5f};
    std::vector<Vec3> directions;
    for (const float c : cosines) {
        for (const float phi : azimuths) {
            const float s = std::sqrt(std::max(0.0f, 1.0f - c * c));
            directions.push_back(Vec3(s * std::cos(phi), s * std::sin(phi), c));
            directions.push_back(Vec3(s * std::cos(phi), s * std::sin(phi), -c));
        }
    }
    return directions;
}

bool is_unit(const Vec3& w) {
    return std::isfinite(w.x) && std::isfinite(w.y) && std::isfinite(w.z) && std::abs(glm::length(w) - 1.0f) < 1e-3f;
}

bool is_valid_density(float pdf) { return std::isfinite(pdf) && pdf >= 0.0f; }

std::string describe(const Vec3& w) {
    std::ostringstream text;
    text.precision(9);
    text << "(" << w.x << ", " << w.y << ", " << w.z << ")";
    return text.str();
}

}  // namespace

TEST_CASE("every BSDF gives finite, non-negative values at grazing angles and limit parameters",
          "[stability][bsdf]") {
    Hit hit;
    hit.geometric_normal = hit.shading_normal = Vec3(0, 0, 1);
    hit.uv = Vec2(0.5f);
    ScratchArena arena;
    PCG32 random(2024, 7);
    const Vec2 corner_u[] = {Vec2(0.0f), Vec2(0x1.fffffep-1f), Vec2(0.5f), Vec2(0.0f, 0x1.fffffep-1f),
                             Vec2(0x1.fffffep-1f, 0.0f)};
    const float corner_lobes[] = {0.0f, 0x1.fffffep-1f};
    for (const json& description : limit_materials()) {
        const std::unique_ptr<Material> material = make(description);
        std::size_t failures = 0;
        std::string first_failure;
        auto fail = [&](const std::string& what) {
            if (failures++ == 0) first_failure = what;
        };
        for (const Vec3& wo : limit_directions()) {
            arena.reset();
            const BSDF& bsdf = *material->bsdf(hit, arena);
            const bool specular = has_flag(bsdf.flags(), BSDF_Specular) && !has_flag(bsdf.flags(), BSDF_Diffuse) &&
                                  !has_flag(bsdf.flags(), BSDF_Glossy);
            for (int i = 0; i < 64 + 10; ++i) {
                const Vec2 u = i < 10 ? corner_u[i % 5] : Vec2(random.next_float(), random.next_float());
                const float u_lobe = i < 10 ? corner_lobes[i / 5] : random.next_float();
                const std::optional<BSDFSample> s = bsdf.sample(wo, u, u_lobe);
                if (!s) continue;
                const std::string where = "wo " + describe(wo) + ", wi " + describe(s->wi);
                if (!is_unit(s->wi)) fail("sample: wi is not a unit vector, " + where);
                if (!is_valid_radiance(s->f)) fail("sample: f is not finite and non-negative, " + where);
                if (!is_valid_density(s->pdf)) fail("sample: pdf " + std::to_string(s->pdf) + ", " + where);
                if (s->pdf > 0.0f && !is_valid_radiance(s->weight())) fail("sample: weight is not finite, " + where);
                if (!has_flag(s->flags, BSDF_Specular) && !specular) {
                    if (!is_valid_radiance(bsdf.eval(wo, s->wi))) fail("eval at a sampled wi: " + where);
                    if (!is_valid_density(bsdf.pdf(wo, s->wi))) fail("pdf at a sampled wi: " + where);
                }
            }
            for (int i = 0; i < 32; ++i) {
                const Vec3 wi = sample_uniform_sphere(Vec2(random.next_float(), random.next_float()));
                const std::string where = "wo " + describe(wo) + ", wi " + describe(wi);
                if (!is_valid_radiance(bsdf.eval(wo, wi))) fail("eval: " + where);
                if (!is_valid_density(bsdf.pdf(wo, wi))) fail("pdf: " + where);
            }
            // wi = wo and wi = -wo: the half vectors of reflection and of eta = 1 refraction vanish.
            for (const Vec3& wi : {wo, -wo, Vec3(-wo.x, -wo.y, wo.z), Vec3(0, 0, 1), Vec3(0, 0, -1)}) {
                const std::string where = "wo " + describe(wo) + ", wi " + describe(wi);
                if (!is_valid_radiance(bsdf.eval(wo, wi))) fail("eval: " + where);
                if (!is_valid_density(bsdf.pdf(wo, wi))) fail("pdf: " + where);
            }
        }
        INFO(description.dump() << ": " << failures << " invalid results; the first: " << first_failure);
        CHECK(failures == 0u);
    }
}

TEST_CASE("an index-matched dielectric passes every direction straight through, at grazing angles too",
          "[stability][bsdf]") {
    // eta = 1 is no interface: nothing is reflected and nothing bends. Fresnel's 1 - cos^2 theta
    // rounds to 1 below cos theta = 2.4e-4, where a careless formula sees total internal reflection.
    Hit hit;
    hit.geometric_normal = hit.shading_normal = Vec3(0, 0, 1);
    ScratchArena arena;
    for (const json& description : {json{{"type", "dielectric"}, {"ior", 1}},
                                    json{{"type", "roughdielectric"}, {"ior", 1}, {"roughness", 0.5}}}) {
        const std::unique_ptr<Material> material = make(description);
        std::size_t failures = 0;
        std::string first_failure;
        for (const Vec3& wo : limit_directions()) {
            if (wo.z == 0.0f) continue;
            arena.reset();
            const BSDF& bsdf = *material->bsdf(hit, arena);
            for (const float u_lobe : {0.0f, 0.5f, 0x1.fffffep-1f}) {
                const std::optional<BSDFSample> s = bsdf.sample(wo, Vec2(0.3f, 0.6f), u_lobe);
                const bool straight = s && has_flag(s->flags, BSDF_Transmission) &&
                                      glm::length(s->wi + wo) < 1e-5f && std::abs(s->weight().x - 1.0f) < 1e-5f;
                if (!straight && failures++ == 0)
                    first_failure = "wo " + describe(wo) + (s ? ": wi " + describe(s->wi) + ", weight " +
                                                                    std::to_string(s->weight().x)
                                                              : std::string(": no sample"));
            }
        }
        INFO(description.dump() << ": " << failures << " samples not straight through with weight 1; the first: "
                                << first_failure);
        CHECK(failures == 0u);
    }
}
