// The registry: every capability the renderer has, by name, in one catalogue per kind
// (capability_catalogue.hpp). Each chapter library adds its own with an explicit
// register_chapterNN(Registry&) call (never static self-registration: static libraries would
// drop such objects). A new kind of capability is one CapabilityKind, one line of
// kind_description and one catalogue here.
#pragma once

#include "freezeray/accelerator.hpp"
#include "freezeray/camera.hpp"
#include "freezeray/capability_catalogue.hpp"
#include "freezeray/integrator.hpp"
#include "freezeray/integrator_advice.hpp"
#include "freezeray/light.hpp"
#include "freezeray/light_sampler.hpp"
#include "freezeray/material.hpp"
#include "freezeray/mesh.hpp"
#include "freezeray/options.hpp"
#include "freezeray/parameters.hpp"
#include "freezeray/sampler.hpp"
#include "freezeray/texture_storage.hpp"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace freezeray {

class Registry;

// What a material's factory needs besides its own parameters: the registry (to make texture
// storage), the layout the scene stores its image textures in and that layout's settings.
struct MaterialContext {
    const Registry& registry;
    std::string texture_layout;  // a registered texture layout ("linear"; chapter 08 adds "tiled")
    // The scene's "textures" block with the command line's texture options over it; null: the
    // layouts' defaults.
    const Parameters* texture_settings = nullptr;
    // Where each image texture the materials load is noted once (Scene::textures); may be null.
    std::vector<std::shared_ptr<const TextureStorage>>* loaded_textures = nullptr;
};

// Each factory gets its capability's settings as Parameters: the scene's block (integrators: the
// "render" block, accelerators: the "accelerator" block) with the command-line values of the
// options its chapter declared given over it (Parameters::none() for the defaults). A factory
// reads them into its settings struct, whose defaults are written once, and checks them (errors
// name the JSON path or the flag).
// An integrator's factory carries what the integrator is (integrator.hpp's IntegratorTraits).
struct IntegratorFactory {
    IntegratorTraits traits;
    std::function<std::unique_ptr<Integrator>(const RenderSettings&, const Parameters& options)> make;
    std::unique_ptr<Integrator> operator()(const RenderSettings& settings, const Parameters& options) const {
        return make(settings, options);
    }
};
using MaterialFactory = std::function<std::unique_ptr<Material>(const Parameters&, const MaterialContext&)>;
using AcceleratorFactory = std::function<std::unique_ptr<Accelerator>(const Parameters& options)>;
// A texture layout reads its settings (chapter 08's filter and texel format) once, and gives back
// what stores each decoded image in that layout, and how its lookups learn a pixel's footprint
// (TextureLookup's derivatives): Scene::intersect computes footprints only where one is given.
struct TextureStorageMaker {
    std::function<std::shared_ptr<const TextureStorage>(const Image& image)> make;
    TextureFootprint footprint = nullptr;  // chapter 08's trilinear filter; chapter 02's layout looks up at the point
    std::shared_ptr<const TextureStorage> operator()(const Image& image) const { return make(image); }
};
using TextureLayoutFactory = std::function<TextureStorageMaker(const Parameters& settings)>;
// Lights described in the scene's "lights" array, by type.
using LightFactory = std::function<std::unique_ptr<Light>(const Parameters&)>;
// A sampler (chapter 09) with its settings: the scene's "render" block under the command line's.
using SamplerFactory = std::function<std::unique_ptr<Sampler>(const Parameters& options)>;
// A camera from what every camera states (position, view, field of view, image size) and the
// scene's "camera" block, whose keys of its own it reads and checks.
using CameraFactory = std::function<std::unique_ptr<Camera>(const CameraDescription&, const Parameters& block)>;
// An area light for one emissive triangle of a mesh (world space) with the given emitted radiance.
using AreaLightFactory =
    std::function<std::unique_ptr<Light>(const TriangleMesh& mesh, std::uint32_t triangle, const Spectrum& emission)>;

class Registry {
    // Which renderer this is, shared with the catalogues (declared first: they are made with it).
    std::shared_ptr<RendererIdentity> renderer_;

public:
    using Entry = CapabilityEntry;

    // program: the executable's name ("ch01", "freezeray"); chapter: the last chapter it
    // registers. The constructor registers what lives in common/: the bruteforce accelerator, the
    // independent sampler and the pinhole camera.
    Registry(std::string program, int chapter);

    const std::string& program() const { return renderer_->program; }
    int chapter() const { return renderer_->chapter; }

    // The catalogues, one per kind: add(name, chapter, summary, factory), make(name, where,
    // factory arguments...), find, has, require, list, default_name, set_default.
    Catalogue<IntegratorFactory> integrators;
    Catalogue<MaterialFactory> materials;
    Catalogue<AcceleratorFactory> accelerators;
    // The "area" entry is the light made for every emissive triangle (add_area_light), not one
    // the "lights" array may name.
    Catalogue<LightFactory> lights;
    Catalogue<TextureLayoutFactory> texture_layouts;
    Catalogue<SamplerFactory> samplers;
    Catalogue<LightSamplerFactory> light_samplers;
    Catalogue<CameraFactory> cameras;

    // What integrator `name` is; an unknown name is an InputError at `where`.
    const IntegratorTraits& integrator_traits(const std::string& name, const std::string& where) const {
        const IntegratorFactory* factory = integrators.find(name);
        if (factory == nullptr) integrators.unknown(name, where);
        return factory->traits;
    }

    // A kind's catalogue, for what every kind does alike.
    const CatalogueBase& catalogue(CapabilityKind kind) const;
    bool has(CapabilityKind kind, const std::string& name) const { return catalogue(kind).has(name); }
    void require(CapabilityKind kind, const std::string& name, const std::string& where) const {
        catalogue(kind).require(name, where);
    }
    std::vector<Entry> list(CapabilityKind kind) const { return catalogue(kind).list(); }

    // The light made for every emissive triangle (listed as light "area"). Without it (a renderer
    // before chapter 03) emissive triangles are found only by hitting them.
    void add_area_light(int chapter, const std::string& summary, AreaLightFactory factory);
    // Null when no chapter registered area lights.
    std::unique_ptr<Light> make_area_light(const TriangleMesh& mesh, std::uint32_t triangle, const Spectrum& emission) const;

    // A layout's maker with its settings read and checked (an InputError names the key) before any
    // image is stored; `settings` may be null: the layout's defaults.
    TextureStorageMaker texture_storage_maker(const std::string& layout, const std::string& where,
                                              const Parameters* settings = nullptr) const;
    // The footprint of the first registered layout that, with these settings, reads one; null
    // when none does. A scene's textures may each name their own layout, so a scene needs
    // footprints when any layout may.
    TextureFootprint texture_footprint(const Parameters* settings) const;

    // A chapter's rule for when its integrator suits a scene (integrator_advice.hpp); the rules
    // of later chapters are asked first.
    void add_advice(AdviceRule rule) { advice_rules_.push_back(std::move(rule)); }
    const std::vector<AdviceRule>& advice_rules() const { return advice_rules_; }

    // A command-line option of a chapter's capability (options.hpp). Its flag must be new.
    void add_option(OptionDeclaration option);
    // A later chapter's capability that reads an option declared before it (chapter 07's
    // kdtree-simd reads the kdtree's settings): `capability` joins the option's used_by.
    void add_option_user(const std::string& flag, const std::string& capability);
    // Every declared option, in the order the chapters added them.
    const std::vector<OptionDeclaration>& options() const { return options_; }

    // The course's table of contents (every capability of every chapter, including chapters this
    // renderer was built without), for "introduced in chapter N" messages; chapter 01 sets it. It
    // must outlive the registry.
    void set_catalogue(const std::vector<CatalogueEntry>& table_of_contents);
    int chapter_introducing(CapabilityKind kind, const std::string& name) const {
        return renderer_->chapter_introducing(kind, name);
    }

private:
    AreaLightFactory area_light_;
    std::vector<OptionDeclaration> options_;
    std::vector<AdviceRule> advice_rules_;
};

}  // namespace freezeray
