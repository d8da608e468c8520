// Chapter 02's materials: each registered type builds from JSON with the right lobes, textured
// parameters vary over the surface, bad parameters are refused at their JSON path, and MTL
// materials map onto them.
#include "freezeray/ch01/register_chapter01.hpp"
#include "freezeray/ch02/cosine_lambertian.hpp"
#include "freezeray/ch02/fresnel.hpp"
#include "freezeray/ch02/material_parameters.hpp"
#include "freezeray/ch02/materials.hpp"
#include "freezeray/ch02/register_chapter02.hpp"
#include "freezeray/ch02/rough_conductor.hpp"
#include "freezeray/ch02/specular_conductor.hpp"
#include "freezeray/error.hpp"
#include "freezeray/image.hpp"
#include "freezeray/material_from_mtl.hpp"
#include "freezeray/scene.hpp"
#include "freezeray/scene_loader.hpp"

#include "test_scenes.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>

using namespace freezeray;
using namespace freezeray::ch02;
using freezeray::testing::TemporaryFolder;
using nlohmann::json;

namespace {

// What the chapter 02 renderer registers.
const Registry& chapter02_registry() {
    static const Registry registry = [] {
        Registry r("ch02", 2);
        register_chapter02(r);
        return r;
    }();
    return registry;
}

// The material a scene's "/materials/m" block describes; files are relative to `folder`.
std::unique_ptr<Material> make(const json& description, const std::string& folder = ".") {
    const Parameters p(description, "scene.json", "/materials/m", folder);
    const Registry& registry = chapter02_registry();
    return registry.materials.make(description.at("type").get<std::string>(), p.where("type"), p,
                                   MaterialContext{registry, registry.texture_layouts.default_name()});
}

// The message of the InputError that making the material throws.
std::string error_of(const json& description, const std::string& folder = ".") {
    try {
        make(description, folder);
    } catch (const InputError& e) {
        return e.what();
    }
    return "(no error)";
}

Hit hit_at(const Vec2& uv) {
    Hit hit;
    hit.uv = uv;
    hit.geometric_normal = hit.shading_normal = Vec3(0, 0, 1);
    return hit;
}

// The sample weight f |cos| / pdf of a delta BSDF seen straight from above.
Spectrum normal_incidence_weight(const BSDF& bsdf) {
    const std::optional<BSDFSample> s = bsdf.sample(Vec3(0, 0, 1), Vec2(0.5f), 0.5f);
    REQUIRE(s);
    return s->weight();
}

// A 2 x 1 image file: `left` in column 0, `right` in column 1.
void write_two_texels(const std::string& path, const Spectrum& left, const Spectrum& right) {
    Image image(2, 1);
    image.at(0, 0) = left;
    image.at(1, 0) = right;
    write_image(path, image);
}

}  // namespace

TEST_CASE("chapter 02 registers its materials, replacing chapter 01's diffuse", "[unit][materials]") {
    const Registry& registry = chapter02_registry();
    for (const char* name : {"diffuse", "mirror", "conductor", "roughconductor", "dielectric", "roughdielectric",
                             "plastic", "roughplastic", "mix"}) {
        INFO(name);
        CHECK(registry.has(CapabilityKind::Material, name));
    }
    for (const Registry::Entry& entry : registry.list(CapabilityKind::Material)) {
        CHECK(entry.chapter == 2);
        CHECK_FALSE(entry.summary.empty());
    }
    const auto diffuse = make({{"type", "diffuse"}, {"albedo", {0.2, 0.4, 0.6}}});
    ScratchArena arena;
    const auto* bsdf = dynamic_cast<const CosineLambertianBSDF*>(diffuse->bsdf(hit_at(Vec2(0.5f)), arena));
    REQUIRE(bsdf);
    CHECK(bsdf->albedo() == Spectrum(0.2f, 0.4f, 0.6f));
}

TEST_CASE("every material builds from JSON with the union of its lobes", "[unit][materials]") {
    const std::uint32_t R = BSDF_Reflection, T = BSDF_Transmission, D = BSDF_Diffuse, G = BSDF_Glossy,
                        S = BSDF_Specular;
    const std::vector<std::pair<json, std::uint32_t>> cases = {
        {{{"type", "diffuse"}, {"albedo", 0.5}}, R | D},
        {{{"type", "mirror"}}, R | S},
        {{{"type", "conductor"}, {"material", "gold"}}, R | S},
        {{{"type", "conductor"}, {"eta", {0.2, 0.9, 1.1}}, {"k", {3.9, 2.4, 2.2}}}, R | S},
        {{{"type", "conductor"}, {"specular_reflectance", {0.9, 0.8, 0.7}}}, R | S},
        {{{"type", "roughconductor"}, {"material", "copper"}, {"roughness", 0.4}}, R | G},
        {{{"type", "roughconductor"}, {"material", "silver"}, {"roughness", 0.0}}, R | S},
        {{{"type", "roughconductor"}, {"material", "aluminium"}, {"roughness_u", 0.1}, {"roughness_v", 0.5}}, R | G},
        {{{"type", "dielectric"}, {"ior", 1.33}}, R | T | S},
        {{{"type", "roughdielectric"}, {"roughness", 0.2}}, R | T | G},
        {{{"type", "plastic"}, {"albedo", {0.8, 0.1, 0.1}}}, R | D | S},
        {{{"type", "roughplastic"}, {"ior", 1.6}, {"roughness", 0.3}}, R | D | G},
        {{{"type", "mix"}, {"first", {{"type", "diffuse"}}}, {"second", {{"type", "mirror"}}}, {"weight", 0.25}},
         R | D | S},
    };
    for (const auto& [description, flags] : cases) {
        INFO(description.dump());
        const auto material = make(description);
        CHECK(material->flags() == flags);
        CHECK_FALSE(material->is_textured());
        // The BSDF built at a hit has lobes the material announced, and samples finite weights.
        ScratchArena arena;
        const BSDF* bsdf = material->bsdf(hit_at(Vec2(0.3f, 0.6f)), arena);
        REQUIRE(bsdf);
        CHECK(bsdf->flags() != 0u);
        CHECK((bsdf->flags() & ~flags) == 0u);
        const Vec3 wo = glm::normalize(Vec3(0.3f, -0.2f, 0.9f));
        for (float u : {0.1f, 0.5f, 0.9f})
            if (const auto s = bsdf->sample(wo, Vec2(u, 1.0f - u), u)) CHECK(is_valid_radiance(s->weight()));
    }
}

TEST_CASE("a smooth conductor reflects its Fresnel reflectance, tinted by specular_reflectance", "[unit][materials]") {
    const ConductorPreset& gold = *find_conductor_preset("gold");
    const Spectrum fresnel = fresnel_conductor(1.0f, gold.eta, gold.k);
    ScratchArena arena;
    const Hit hit = hit_at(Vec2(0.5f));
    const Spectrum plain = normal_incidence_weight(*make({{"type", "conductor"}, {"material", "gold"}})->bsdf(hit, arena));
    const Spectrum tinted = normal_incidence_weight(
        *make({{"type", "conductor"}, {"material", "gold"}, {"specular_reflectance", 0.5}})->bsdf(hit, arena));
    for (int c = 0; c < 3; ++c) {
        CHECK(plain[c] == Approx(fresnel[c]));
        CHECK(tinted[c] == Approx(0.5f * fresnel[c]));
    }
}

TEST_CASE("a conductor given only specular_reflectance (MTL Ks) reflects it at normal incidence", "[unit][materials]") {
    const Spectrum ks(0.9f, 0.5f, 0.05f);
    ScratchArena arena;
    const auto metal = make({{"type", "conductor"}, {"specular_reflectance", {ks.r, ks.g, ks.b}}});
    const Spectrum reflected = normal_incidence_weight(*metal->bsdf(hit_at(Vec2(0.5f)), arena));
    for (int c = 0; c < 3; ++c) CHECK(reflected[c] == Approx(ks[c]).margin(1e-5));
    // The derived index: no reflection for R0 = 0, almost all of it for R0 = 1, rising towards grazing.
    CHECK(fresnel_conductor(1.0f, index_for_normal_reflectance(Spectrum(0.0f)), Spectrum(0.0f)).r == Approx(0.0f));
    CHECK(fresnel_conductor(1.0f, index_for_normal_reflectance(Spectrum(1.0f)), Spectrum(0.0f)).r > 0.99f);
    const Spectrum eta = index_for_normal_reflectance(ks);
    CHECK(fresnel_conductor(0.05f, eta, Spectrum(0.0f)).b > ks.b);
}

TEST_CASE("rough materials fall back to the smooth BSDF where the roughness is (nearly) zero", "[unit][materials]") {
    ScratchArena arena;
    const Hit hit = hit_at(Vec2(0.5f));
    const auto smooth = make({{"type", "roughconductor"}, {"material", "gold"}, {"roughness", 0.01}});
    const auto rough = make({{"type", "roughconductor"}, {"material", "gold"}, {"roughness", 0.5}});
    CHECK(dynamic_cast<const SpecularConductorBSDF*>(smooth->bsdf(hit, arena)));
    CHECK(dynamic_cast<const RoughConductorBSDF*>(rough->bsdf(hit, arena)));
}

TEST_CASE("anisotropy stretches alpha along u and keeps alpha_u alpha_v = roughness^4", "[unit][materials]") {
    const json description = {{"roughness", 0.5}, {"anisotropy", 1.0}};
    const Parameters p(description, "scene.json", "/materials/m", ".");
    const TrowbridgeReitz distribution = read_microfacet_roughness(p, MaterialContext{chapter02_registry(), "linear"}, DefaultRoughness).distribution(TextureLookup{Vec2(0.5f)});
    CHECK(distribution.alpha_x() == Approx(0.25f / std::sqrt(0.1f)));
    CHECK(distribution.alpha_y() == Approx(0.25f * std::sqrt(0.1f)));
    CHECK(distribution.alpha_x() * distribution.alpha_y() == Approx(0.0625f));
}

TEST_CASE("a textured albedo varies with uv and makes the material textured", "[unit][materials]") {
    const TemporaryFolder folder;
    write_two_texels(folder.file("halves.png"), Spectrum(0.0f), Spectrum(1.0f));
    const auto material = make({{"type", "diffuse"}, {"albedo", 0.5}, {"albedo_texture", "halves.png"}}, folder.path());
    CHECK(material->is_textured());
    ScratchArena arena;
    auto albedo_at = [&](const Vec2& uv) {
        const auto* bsdf = dynamic_cast<const CosineLambertianBSDF*>(material->bsdf(hit_at(uv), arena));
        REQUIRE(bsdf);
        return bsdf->albedo();
    };
    CHECK(albedo_at(Vec2(0.25f, 0.5f)) == Spectrum(0.0f));
    CHECK(albedo_at(Vec2(0.75f, 0.5f)) == Spectrum(1.0f));
    CHECK(albedo_at(Vec2(1.25f, 0.5f)) == Spectrum(0.0f));  // repeats by default

    SECTION("a texture object chooses the wrap mode") {
        const auto clamped = make({{"type", "diffuse"}, {"albedo_texture", {{"file", "halves.png"}, {"wrap", "clamp"}}}},
                                  folder.path());
        const auto* bsdf = dynamic_cast<const CosineLambertianBSDF*>(clamped->bsdf(hit_at(Vec2(1.25f, 0.5f)), arena));
        REQUIRE(bsdf);
        CHECK(bsdf->albedo() == Spectrum(1.0f));
    }
}

TEST_CASE("a roughness map is read as data and can make a surface both smooth and rough", "[unit][materials]") {
    const TemporaryFolder folder;
    write_two_texels(folder.file("roughness.png"), Spectrum(0.0f), Spectrum(1.0f));
    const auto metal = make({{"type", "roughconductor"}, {"material", "gold"}, {"roughness_texture", "roughness.png"}},
                            folder.path());
    CHECK(metal->is_textured());
    CHECK(metal->flags() == (BSDF_Reflection | BSDF_Glossy | BSDF_Specular));
    ScratchArena arena;
    CHECK(dynamic_cast<const SpecularConductorBSDF*>(metal->bsdf(hit_at(Vec2(0.25f, 0.5f)), arena)));
    CHECK(dynamic_cast<const RoughConductorBSDF*>(metal->bsdf(hit_at(Vec2(0.75f, 0.5f)), arena)));

    const auto mix = make({{"type", "mix"},
                           {"first", {{"type", "diffuse"}}},
                           {"second", {{"type", "dielectric"}}},
                           {"weight_texture", "roughness.png"}},
                          folder.path());
    CHECK(mix->is_textured());
    CHECK(mix->flags() == (BSDF_Reflection | BSDF_Transmission | BSDF_Diffuse | BSDF_Specular));
}

TEST_CASE("bad material parameters are InputErrors naming the JSON path", "[unit][materials]") {
    const TemporaryFolder folder;
    write_two_texels(folder.file("tex.png"), Spectrum(0.2f), Spectrum(0.4f));
    write_two_texels(folder.file("bright.pfm"), Spectrum(0.5f), Spectrum(2.0f));
    struct Case {
        json description;
        std::string where;  // the JSON path after /materials/m
        std::string says;   // part of the message
    };
    const std::vector<Case> cases = {
        {{{"type", "diffuse"}, {"albedo", {1.5, 0, 0}}}, "/albedo", "outside [0"},
        {{{"type", "diffuse"}, {"albedo", "red"}}, "/albedo", "expected an array"},
        {{{"type", "diffuse"}, {"albedo_texture", "missing.png"}}, "/albedo_texture", "does not exist"},
        {{{"type", "diffuse"}, {"albedo_texture", 5}}, "/albedo_texture", "expected an image file name"},
        {{{"type", "diffuse"}, {"albedo_texture", "bright.pfm"}}, "/albedo_texture", "texel values from 0.5 to 2"},
        {{{"type", "diffuse"}, {"albedo_texture", {{"file", "tex.png"}, {"wrap", "wrapped"}}}}, "/albedo_texture/wrap",
         "did you mean"},
        {{{"type", "diffuse"}, {"albedo_texture", {{"file", "tex.png"}, {"encoding", "gamma"}}}},
         "/albedo_texture/encoding", "srgb, linear"},
        {{{"type", "diffuse"}, {"albedo_texture", {{"file", "tex.png"}, {"wrpa", "clamp"}}}}, "/albedo_texture/wrpa",
         "unknown key 'wrpa' (did you mean 'wrap'?)"},
        {{{"type", "mirror"}, {"reflectance", -0.1}}, "/reflectance", "outside"},
        {{{"type", "roughconductor"}, {"material", "gold"}, {"roughness", 1.5}}, "/roughness", "outside [0"},
        {{{"type", "roughconductor"}, {"material", "gold"}, {"roughness", 0.2}, {"roughness_u", 0.1}}, "/roughness",
         "not both"},
        {{{"type", "roughconductor"}, {"material", "gold"}, {"roughness_u", 0.1}}, "/roughness_v", "is required"},
        {{{"type", "roughconductor"}, {"material", "gold"}, {"anisotropy", 2}}, "/anisotropy", "outside"},
        {{{"type", "conductor"}, {"material", "gld"}}, "/material", "did you mean 'gold'"},
        {{{"type", "conductor"}}, "/material", "a conductor needs"},
        {{{"type", "conductor"}, {"eta", 0.2}}, "/k", "come together"},
        {{{"type", "conductor"}, {"eta", -1}, {"k", 1}}, "/eta", "outside (0, 10]"},
        {{{"type", "conductor"}, {"material", "gold"}, {"k", 1}}, "/material", "not both"},
        {{{"type", "dielectric"}, {"ior", 0}}, "/ior", "outside (0, 10]"},
        {{{"type", "roughdielectric"}, {"ior", 11}}, "/ior", "outside (0, 10]"},
        {{{"type", "plastic"}, {"ior", "glass"}}, "/ior", "expected a number"},
        {{{"type", "mix"}, {"first", {{"type", "diffuse"}}}}, "/second", "is required"},
        {{{"type", "mix"}, {"first", {{"type", "diffuse"}, {"albedo", 2}}}, {"second", {{"type", "mirror"}}}},
         "/first/albedo", "outside"},
        {{{"type", "mix"}, {"first", {{"type", "difuse"}}}, {"second", {{"type", "mirror"}}}}, "/first/type",
         "did you mean 'diffuse'"},
        {{{"type", "mix"}, {"first", {{"type", "diffuse"}, {"emission", 1}}}, {"second", {{"type", "mirror"}}}},
         "/first/emission", "unknown key"},
        {{{"type", "mix"}, {"first", {{"type", "diffuse"}}}, {"second", {{"type", "mirror"}}}, {"weight", 2}}, "/weight",
         "outside"},
        {{{"type", "mix"}, {"materials", {"a", "b"}}}, "/materials", "inline"},
    };
    for (const Case& c : cases) {
        INFO(c.description.dump());
        const std::string message = error_of(c.description, folder.path());
        CHECK_THAT(message, Catch::Contains("scene.json: /materials/m" + c.where + ":") && Catch::Contains(c.says));
    }
}

TEST_CASE("an MTL metal's colour is its Kd, or its Ks when Kd is black (the classic illum 3 metal with Pm)", "[unit][materials]") {
    MtlMaterial pbr;  // the PBR extension: base colour in Kd
    pbr.kd = Spectrum(0.9f, 0.6f, 0.2f);
    pbr.ks = Spectrum(0.5f);
    pbr.pm = 1.0f;
    CHECK(material_from_mtl(pbr)["specular_reflectance"] == nlohmann::json({0.9f, 0.6f, 0.2f}));
    MtlMaterial classic;  // Kd 0, Ks = reflectance, Pm 1, illum 3 (staircase2.mtl's "Metal")
    classic.ks = Spectrum(0.928047f, 0.917804f, 0.918909f);
    classic.pm = 1.0f;
    classic.illum = 3;
    classic.pr = 0.316228f;
    const nlohmann::json j = material_from_mtl(classic);
    CHECK(j["type"] == "roughconductor");
    CHECK(j["specular_reflectance"] == nlohmann::json({0.928047f, 0.917804f, 0.918909f}));
}

TEST_CASE("MTL alpha masks become cut-outs; bump maps, which the renderer does not read, are named in a warning", "[unit][materials][scene]") {
    const TemporaryFolder folder;
    write_two_texels(folder.file("mask.png"), Spectrum(0.0f), Spectrum(1.0f));
    std::ofstream(folder.file("plants.mtl")) << "newmtl leaf\nKd 0.5 0.5 0.5\nmap_d mask.png\nmap_bump mask.png\n\n"
                                                "newmtl vine\nKd 0.5 0.5 0.5\nbump mask.png\n\n"
                                                "newmtl stone\nKd 0.5 0.5 0.5\n";
    std::ofstream(folder.file("plants.obj")) << "mtllib plants.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\n"
                                                "usemtl leaf\nf 1/1 2/2 3/3\nusemtl vine\nf 1/1 2/2 3/3\nusemtl stone\nf 1/1 2/2 3/3\n";
    std::ofstream(folder.file("scene.json"))
        << R"({"camera": {"position": [0, 0, 5], "look_at": [0, 0, 0], "fov_vertical_degrees": 40, "resolution": [4, 4]},
              "meshes": [{"file": "plants.obj"}]})";
    const Scene scene = load_scene(folder.file("scene.json"), chapter02_registry());
    REQUIRE(scene.warnings.size() == 1u);
    CHECK_THAT(scene.warnings[0], Catch::Contains("plants.mtl: 2 materials (leaf, vine) name a bump or normal map"));
    CHECK(scene.has_alpha_masks);
    REQUIRE(scene.materials.size() == 3u);
    CHECK(scene.materials[0]->alpha_mask != nullptr);  // leaf
    CHECK(scene.materials[1]->alpha_mask == nullptr);
    // Chapter 01 has no image textures: the mask is an unused key, and said to be.
    Registry chapter01("ch01", 1);
    register_chapter01(chapter01);
    const Scene solid = load_scene(folder.file("scene.json"), chapter01);
    CHECK_FALSE(solid.has_alpha_masks);
    CHECK(std::any_of(solid.warnings.begin(), solid.warnings.end(),
                      [](const std::string& w) { return w.find("alpha_texture") != std::string::npos; }));
}

namespace {

// A 2 x 2 quad in the plane z = 1 (texture u from 0 at x = -1 to 1 at x = 1) in front of an opaque
// wall at z = 2, the quad's material given by `quad`. Rays go along +z from z = 0.
std::string write_cutout_scene(const TemporaryFolder& folder, const std::string& quad) {
    std::ofstream(folder.file("quad.obj")) << "v -1 -1 1\nv 1 -1 1\nv 1 1 1\nv -1 1 1\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
                                              "f 1/1 2/2 3/3\nf 1/1 3/3 4/4\n";
    std::ofstream(folder.file("wall.obj")) << "v -5 -5 2\nv 5 -5 2\nv 5 5 2\nv -5 5 2\nf 1 2 3\nf 1 3 4\n";
    std::ofstream(folder.file("scene.json"))
        << R"({"camera": {"position": [0, 0, -1], "look_at": [0, 0, 1], "fov_vertical_degrees": 40, "resolution": [4, 4]},
              "materials": {"leaf": )" << quad << R"(, "stone": {"type": "diffuse", "albedo": 0.5}},
              "meshes": [{"file": "quad.obj", "material": "leaf"}, {"file": "wall.obj", "material": "stone"}]})";
    return folder.file("scene.json");
}

}  // namespace

TEST_CASE("rays pass through the holes of an alpha mask and stop at its solid parts", "[unit][materials][scene]") {
    const TemporaryFolder folder;
    // Left texel a hole, right texel solid: bilinear filtering crosses one half at u = 1/2, x = 0.
    write_two_texels(folder.file("mask.png"), Spectrum(0.0f), Spectrum(1.0f));
    const Scene scene = load_scene(
        write_cutout_scene(folder, R"({"type": "diffuse", "albedo": 0.5, "alpha_texture": {"file": "mask.png", "wrap": "clamp"}})"),
        chapter02_registry());
    REQUIRE(scene.has_alpha_masks);
    const Vec3 forward(0.0f, 0.0f, 1.0f);
    for (const float x : {-0.9f, -0.6f, -0.3f}) {  // the hole: straight on to the wall, t from the ray's own origin
        INFO("x = " << x);
        const std::optional<Hit> hit = scene.intersect(Ray{Vec3(x, 0.3f, 0.0f), forward});
        REQUIRE(hit);
        CHECK(hit->material == 1u);
        CHECK(hit->t == Approx(2.0f).epsilon(1e-5));
        CHECK(hit->position.z == Approx(2.0f));
        CHECK_FALSE(scene.occluded(Ray{Vec3(x, 0.3f, 0.0f), forward, 1.5f}));  // only the hole before z = 1.5
        CHECK(scene.occluded(Ray{Vec3(x, 0.3f, 0.0f), forward, 3.0f}));        // the wall
        CHECK_FALSE(scene.intersect(Ray{Vec3(x, 0.3f, 0.0f), forward, 1.5f}));
    }
    for (const float x : {0.3f, 0.6f, 0.9f}) {  // solid
        INFO("x = " << x);
        const std::optional<Hit> hit = scene.intersect(Ray{Vec3(x, 0.3f, 0.0f), forward});
        REQUIRE(hit);
        CHECK(hit->material == 0u);
        CHECK(hit->t == Approx(1.0f));
        CHECK(scene.occluded(Ray{Vec3(x, 0.3f, 0.0f), forward, 1.5f}));
    }
    // From behind, the same holes.
    const std::optional<Hit> back = scene.intersect(Ray{Vec3(-0.6f, 0.3f, 1.9f), -forward});
    CHECK_FALSE(back);
}

TEST_CASE("an alpha mask without holes is dropped; an emissive one is refused", "[unit][materials][scene]") {
    const TemporaryFolder folder;
    write_two_texels(folder.file("opaque.png"), Spectrum(0.6f), Spectrum(1.0f));
    const Scene whole = load_scene(
        write_cutout_scene(folder, R"({"type": "diffuse", "albedo": 0.5, "alpha_texture": "opaque.png"})"), chapter02_registry());
    CHECK_FALSE(whole.has_alpha_masks);  // every opacity is at least one half: nothing to cut out
    const Scene gone = load_scene(write_cutout_scene(folder, R"({"type": "diffuse", "albedo": 0.5, "alpha": 0.2})"),
                                  chapter02_registry());
    CHECK(gone.has_alpha_masks);
    CHECK(gone.intersect(Ray{Vec3(0.5f, 0.0f, 0.0f), Vec3(0.0f, 0.0f, 1.0f)})->material == 1u);
    CHECK_THROWS_WITH(load_scene(write_cutout_scene(folder, R"({"type": "diffuse", "emission": 1, "alpha": 0.2})"),
                                 chapter02_registry()),
                      Catch::Contains("/materials/leaf/emission") && Catch::Contains("cannot have an alpha mask"));
    CHECK_THROWS_WITH(load_scene(write_cutout_scene(folder, R"({"type": "diffuse", "alpha": 1.5})"), chapter02_registry()),
                      Catch::Contains("/materials/leaf/alpha"));
}

TEST_CASE("MTL materials load as chapter 02 materials", "[unit][materials][scene]") {
    const TemporaryFolder folder;
    write_two_texels(folder.file("wood.png"), Spectrum(0.3f, 0.2f, 0.1f), Spectrum(0.5f, 0.3f, 0.2f));
    std::ofstream(folder.file("things.mtl")) << "newmtl glass\nillum 7\nNi 1.5\n\n"
                                                "newmtl metal\nillum 3\nKs 0.9 0.8 0.7\n\n"
                                                "newmtl brushed\nKs 0.9 0.9 0.9\nPm 1\nPr 0.4\n\n"
                                                "newmtl varnish\nKd 0.5 0.4 0.3\nKs 0.1 0.1 0.1\nNs 200\n\n"
                                                "newmtl wood\nKd 0.6 0.6 0.6\nmap_Kd wood.png\n";
    std::string obj = "mtllib things.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\n";
    for (const char* name : {"glass", "metal", "brushed", "varnish", "wood"})
        obj += std::string("usemtl ") + name + "\nf 1/1 2/2 3/3\n";
    std::ofstream(folder.file("things.obj")) << obj;
    std::ofstream(folder.file("scene.json"))
        << R"({"camera": {"position": [0, 0, 5], "look_at": [0, 0, 0], "fov_vertical_degrees": 40,
                         "resolution": [4, 4]},
              "meshes": [{"file": "things.obj"}]})";
    const Scene scene = load_scene(folder.file("scene.json"), chapter02_registry());
    std::map<std::string, std::string> types;
    for (const auto& m : scene.materials) types[m->name] = m->type;
    CHECK(types["glass"] == "dielectric");
    CHECK(types["metal"] == "conductor");
    CHECK(types["brushed"] == "roughconductor");
    CHECK(types["varnish"] == "roughplastic");
    CHECK(types["wood"] == "diffuse");
    CHECK(scene.effects.textures);
    CHECK(scene.effects.transmission);
    CHECK(scene.effects.glossy);
    CHECK(scene.warnings.empty());
}
