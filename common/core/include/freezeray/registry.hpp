// The registry: every capability the renderer has, by name. Each chapter library adds its own
// with an explicit register_chapterNN(Registry&) call from main (never static self-registration:
// static libraries would drop such objects).
#pragma once

#include "freezeray/accelerator.hpp"
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
#include <map>
#include <optional>
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
// options its chapter declared given over it. A factory reads them into its settings struct,
// whose defaults are written once, and checks them (errors name the JSON path or the flag).
using IntegratorFactory = std::function<std::unique_ptr<Integrator>(const RenderSettings&, const Parameters& options)>;
using MaterialFactory = std::function<std::unique_ptr<Material>(const Parameters&, const MaterialContext&)>;
using AcceleratorFactory = std::function<std::unique_ptr<Accelerator>(const Parameters& options)>;
// A texture layout reads its settings (chapter 08's filter and texel format) once, and gives back
// what stores each decoded image in that layout, and whether its lookups read a pixel's
// footprint (TextureLookup's derivatives): Scene::intersect computes footprints only then.
struct TextureStorageMaker {
    std::function<std::shared_ptr<const TextureStorage>(const Image& image)> make;
    bool uses_footprint = false;  // chapter 08's trilinear filter; chapter 02's layout looks up at the point
    std::shared_ptr<const TextureStorage> operator()(const Image& image) const { return make(image); }
};
using TextureLayoutFactory = std::function<TextureStorageMaker(const Parameters& settings)>;
using LightFactory = std::function<std::unique_ptr<Light>(const Parameters&)>;
// A sampler (chapter 09) with its settings: the scene's "render" block under the command line's.
using SamplerFactory = std::function<std::unique_ptr<Sampler>(const Parameters& options)>;
// An area light for one emissive triangle of a mesh (world space) with the given emitted radiance.
using AreaLightFactory =
    std::function<std::unique_ptr<Light>(const TriangleMesh& mesh, std::uint32_t triangle, const Spectrum& emission)>;

// The kinds of things the registry names.
enum class CapabilityKind { Integrator, Material, Accelerator, Light, TextureLayout, Sampler, LightSampler };
// Every kind, in the order above: a loop over the registry's contents uses this list, so a new
// kind cannot be forgotten there.
inline constexpr CapabilityKind all_capability_kinds[] = {CapabilityKind::Integrator,   CapabilityKind::Material,
                                                         CapabilityKind::Accelerator,  CapabilityKind::Light,
                                                         CapabilityKind::TextureLayout, CapabilityKind::Sampler,
                                                         CapabilityKind::LightSampler};
const char* capability_kind_name(CapabilityKind kind);

// One line of a course's table of contents: the chapter that introduces a named capability.
struct CatalogueEntry {
    CapabilityKind kind;
    const char* name;
    int chapter;
};

class Registry {
public:
    // program: the executable's name ("ch01", "freezeray"); chapter: the last chapter it
    // registers. The constructor registers what lives in common/: the bruteforce accelerator and
    // the independent sampler.
    Registry(std::string program, int chapter);

    const std::string& program() const { return program_; }
    int chapter() const { return chapter_; }

    // Adding a name that exists replaces it: a later chapter may supersede an earlier one's
    // implementation (Entry::introduced_in keeps the chapter that introduced the name).
    void add_integrator(const std::string& name, int chapter, const std::string& summary, IntegratorFactory factory);
    void add_material(const std::string& name, int chapter, const std::string& summary, MaterialFactory factory);
    void add_accelerator(const std::string& name, int chapter, const std::string& summary, AcceleratorFactory factory);
    // Lights described in the scene's "lights" array, by type.
    void add_light(const std::string& name, int chapter, const std::string& summary, LightFactory factory);
    // The light made for every emissive triangle (registered as light "area"). Without it (a
    // renderer before chapter 03) emissive triangles are found only by hitting them.
    void add_area_light(int chapter, const std::string& summary, AreaLightFactory factory);
    void add_texture_layout(const std::string& name, int chapter, const std::string& summary,
                            TextureLayoutFactory factory);
    void add_sampler(const std::string& name, int chapter, const std::string& summary, SamplerFactory factory);
    // How the light-sampling integrators choose a light at a shading point (chapter 03's power
    // and uniform, chapter 10's bvh). The first one registered is the default until a chapter
    // says otherwise.
    void add_light_sampler(const std::string& name, int chapter, const std::string& summary, LightSamplerFactory factory);
    // A chapter's rule for when its integrator suits a scene (integrator_advice.hpp); the rules
    // of later chapters are asked first.
    void add_advice(AdviceRule rule) { advice_rules_.push_back(std::move(rule)); }
    const std::vector<AdviceRule>& advice_rules() const { return advice_rules_; }
    // A command-line option of a chapter's capability (options.hpp). Its flag must be new.
    void add_option(OptionDeclaration option);
    // A later chapter's capability that reads an option declared before it (chapter 07's
    // kdtree-simd reads the kdtree's settings): `capability` joins the option's used_by.
    void add_option_user(const std::string& flag, const std::string& capability);

    // The accelerator and texture layout used when neither the scene nor the command line names
    // one: bruteforce and the first registered layout, until a chapter says otherwise (chapter 06
    // makes its KD-tree the default). The name must be registered.
    void set_default_accelerator(const std::string& name);
    void set_default_texture_layout(const std::string& name);
    // The sampler when neither the scene nor the command line names one: independent, until
    // chapter 09 says otherwise.
    void set_default_sampler(const std::string& name);
    const std::string& default_sampler() const { return default_sampler_; }
    void set_default_light_sampler(const std::string& name);
    // Empty before chapter 03 (no light is sampled).
    const std::string& default_light_sampler() const { return default_light_sampler_; }
    const std::string& default_accelerator() const { return default_accelerator_; }
    const std::string& default_texture_layout() const { return default_texture_layout_; }

    // Creators. An unknown name is an InputError at `where` that names the chapter introducing
    // it, or the nearest registered name when no chapter does.
    // `options` may be null: the integrator's defaults.
    std::unique_ptr<Integrator> make_integrator(const std::string& name, const RenderSettings& settings,
                                                const std::string& where, const Parameters* options = nullptr) const;
    // Without a context, textures are stored in the default layout.
    std::unique_ptr<Material> make_material(const std::string& type, const Parameters& parameters) const;
    std::unique_ptr<Material> make_material(const std::string& type, const Parameters& parameters,
                                            const MaterialContext& context) const;
    std::unique_ptr<Accelerator> make_accelerator(const std::string& name, const std::string& where,
                                                  const Parameters* options = nullptr) const;
    // `settings` may be null: the layout's defaults. Settings are checked here (an InputError
    // names the key), before any image is stored.
    TextureStorageMaker texture_storage_maker(const std::string& layout, const std::string& where,
                                              const Parameters* settings = nullptr) const;
    std::shared_ptr<const TextureStorage> make_texture_storage(const std::string& layout, const Image& image,
                                                               const std::string& where) const;
    // Whether some registered layout, with these settings, reads the pixel's footprint. A scene's
    // textures may each name their own layout, so a scene needs footprints when any layout may.
    bool texture_layouts_use_footprint(const Parameters* settings) const;
    std::unique_ptr<Light> make_light(const std::string& type, const Parameters& parameters) const;
    std::unique_ptr<Sampler> make_sampler(const std::string& name, const std::string& where,
                                          const Parameters* options = nullptr) const;
    // A light sampler over `lights` (which must outlive it); an unknown name is an InputError at
    // `where`. `options` may be null: its defaults.
    std::unique_ptr<LightSampler> make_light_sampler(const std::string& name, const std::vector<std::unique_ptr<Light>>& lights,
                                                     const std::string& where, const Parameters* options = nullptr) const;
    // Null when no chapter registered area lights.
    std::unique_ptr<Light> make_area_light(const TriangleMesh& mesh, std::uint32_t triangle, const Spectrum& emission) const;

    bool has(CapabilityKind kind, const std::string& name) const;
    // The factory registered under `name` (for an integrator made of others, such as `auto`);
    // null when there is none.
    IntegratorFactory integrator_factory(const std::string& name) const;

    // The course's catalogue (every capability of every chapter, including chapters this renderer
    // was built without), for "introduced in chapter N" messages; chapter 01 sets it. The
    // catalogue must outlive the registry.
    void set_catalogue(const std::vector<CatalogueEntry>& catalogue);
    int chapter_introducing(CapabilityKind kind, const std::string& name) const;  // 0 when unknown
    // Throws the InputError of an unknown name at `where` (naming the chapter that introduces
    // it) unless the registry has it.
    void require(CapabilityKind kind, const std::string& name, const std::string& where) const;

    struct Entry {
        std::string name;
        int chapter;          // the chapter whose implementation this is
        std::string summary;
        int introduced_in;    // the chapter that first registered the name (the catalogue's)
    };
    // Everything of a kind, in name order, for `--help` and `info`.
    std::vector<Entry> list(CapabilityKind kind) const;
    // Every declared option, in the order the chapters added them.
    const std::vector<OptionDeclaration>& options() const { return options_; }

private:
    [[noreturn]] void unknown(CapabilityKind kind, const std::string& name, const std::string& where) const;

    std::string program_;
    int chapter_;
    std::map<std::string, std::pair<Entry, IntegratorFactory>> integrators_;
    std::map<std::string, std::pair<Entry, MaterialFactory>> materials_;
    std::map<std::string, std::pair<Entry, AcceleratorFactory>> accelerators_;
    std::map<std::string, std::pair<Entry, LightFactory>> lights_;
    std::optional<std::pair<Entry, AreaLightFactory>> area_light_;
    std::map<std::string, std::pair<Entry, TextureLayoutFactory>> texture_layouts_;
    std::map<std::string, std::pair<Entry, SamplerFactory>> samplers_;
    std::map<std::string, std::pair<Entry, LightSamplerFactory>> light_samplers_;
    std::vector<OptionDeclaration> options_;
    std::vector<AdviceRule> advice_rules_;
    std::string default_accelerator_ = "bruteforce";
    std::string default_texture_layout_;
    std::string default_sampler_ = "independent";
    std::string default_light_sampler_;
    const std::vector<CatalogueEntry>* catalogue_ = nullptr;
};

// The name among `candidates` closest to `name` by edit distance (for "did you mean").
std::string nearest_name(const std::string& name, const std::vector<std::string>& candidates);

}  // namespace freezeray
