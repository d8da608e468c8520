// The registry: every capability the renderer has, by name. Each chapter library adds its own
// with an explicit register_chapterNN(Registry&) call from main (never static self-registration:
// static libraries would drop such objects).
#pragma once

#include "freezeray/accelerator.hpp"
#include "freezeray/integrator.hpp"
#include "freezeray/light.hpp"
#include "freezeray/material.hpp"
#include "freezeray/mesh.hpp"
#include "freezeray/parameters.hpp"

#include <functional>
#include <map>
#include <optional>
#include <memory>
#include <string>
#include <vector>

namespace freezeray {

using IntegratorFactory = std::function<std::unique_ptr<Integrator>(const RenderSettings&)>;
using MaterialFactory = std::function<std::unique_ptr<Material>(const Parameters&)>;
using AcceleratorFactory = std::function<std::unique_ptr<Accelerator>()>;
using LightFactory = std::function<std::unique_ptr<Light>(const Parameters&)>;
// An area light for one emissive triangle of a mesh (world space) with the given emitted radiance.
using AreaLightFactory =
    std::function<std::unique_ptr<Light>(const TriangleMesh& mesh, std::uint32_t triangle, const Spectrum& emission)>;

// The kinds of things the registry names. Texture layouts join in a later chapter.
enum class CapabilityKind { Integrator, Material, Accelerator, Light, TextureLayout };
const char* capability_kind_name(CapabilityKind kind);

class Registry {
public:
    // program: the executable's name ("ch01", "freezeray"); chapter: the last chapter it
    // registers. The constructor registers what lives in common/ (diffuse, bruteforce).
    Registry(std::string program, int chapter);

    const std::string& program() const { return program_; }
    int chapter() const { return chapter_; }

    // Adding a name that exists replaces it: a later chapter may supersede an earlier one's
    // implementation (the replaced entry's chapter is kept for messages).
    void add_integrator(const std::string& name, int chapter, const std::string& summary, IntegratorFactory factory);
    void add_material(const std::string& name, int chapter, const std::string& summary, MaterialFactory factory);
    void add_accelerator(const std::string& name, int chapter, const std::string& summary, AcceleratorFactory factory);
    // Lights described in the scene's "lights" array, by type.
    void add_light(const std::string& name, int chapter, const std::string& summary, LightFactory factory);
    // The light made for every emissive triangle (registered as light "area"). Without it (a
    // renderer before chapter 03) emissive triangles are found only by hitting them.
    void add_area_light(int chapter, const std::string& summary, AreaLightFactory factory);

    // Creators. An unknown name is an InputError at `where` that names the chapter introducing
    // it, or the nearest registered name when no chapter does.
    std::unique_ptr<Integrator> make_integrator(const std::string& name, const RenderSettings& settings,
                                                const std::string& where) const;
    std::unique_ptr<Material> make_material(const std::string& type, const Parameters& parameters) const;
    std::unique_ptr<Accelerator> make_accelerator(const std::string& name, const std::string& where) const;
    std::unique_ptr<Light> make_light(const std::string& type, const Parameters& parameters) const;
    // Null when no chapter registered area lights.
    std::unique_ptr<Light> make_area_light(const TriangleMesh& mesh, std::uint32_t triangle, const Spectrum& emission) const;

    bool has(CapabilityKind kind, const std::string& name) const;

    struct Entry {
        std::string name;
        int chapter;
        std::string summary;
    };
    // Everything of a kind, in name order, for `--help` and `info`.
    std::vector<Entry> list(CapabilityKind kind) const;

private:
    [[noreturn]] void unknown(CapabilityKind kind, const std::string& name, const std::string& where) const;

    std::string program_;
    int chapter_;
    std::map<std::string, std::pair<Entry, IntegratorFactory>> integrators_;
    std::map<std::string, std::pair<Entry, MaterialFactory>> materials_;
    std::map<std::string, std::pair<Entry, AcceleratorFactory>> accelerators_;
    std::map<std::string, std::pair<Entry, LightFactory>> lights_;
    std::optional<std::pair<Entry, AreaLightFactory>> area_light_;
};

// The course's catalogue: which chapter introduces each named capability, including those of
// chapters this renderer was built without. Used only for error messages.
int chapter_introducing(CapabilityKind kind, const std::string& name);  // 0 when unknown

// The name among `candidates` closest to `name` by edit distance (for "did you mean").
std::string nearest_name(const std::string& name, const std::vector<std::string>& candidates);

}  // namespace freezeray
