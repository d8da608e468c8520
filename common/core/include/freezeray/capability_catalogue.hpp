// A catalogue: the capabilities of one kind (integrators, samplers, ...) by name, each with the
// factory that makes it. Every kind is one Catalogue of the registry (registry.hpp); what all kinds
// do alike (adding, replacing, defaults, listing, refusing an unknown name with the chapter that
// introduces it) is written once, here.
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace freezeray {

// The kinds of things the registry names.
enum class CapabilityKind { Integrator, Material, Accelerator, Light, TextureLayout, Sampler, LightSampler, Camera };
// Every kind, in the order above: a loop over the registry's contents uses this list, so a new
// kind cannot be forgotten there.
inline constexpr CapabilityKind all_capability_kinds[] = {CapabilityKind::Integrator,   CapabilityKind::Material,
                                                         CapabilityKind::Accelerator,  CapabilityKind::Light,
                                                         CapabilityKind::TextureLayout, CapabilityKind::Sampler,
                                                         CapabilityKind::LightSampler, CapabilityKind::Camera};

// What a kind declares once: its name, and how a render chooses one of it: the command line's
// selector, else the key in the scene file's block that names it, else the catalogue's default.
// Kinds that a scene lists many of (materials, lights) have no selector: each entry names its
// type. The command line offers every selector of a renderer from one loop over these
// descriptions (cli.cpp), and the scene builder and the run plan choose every kind alike
// (capability_choice.hpp).
struct KindDescription {
    CapabilityKind kind;
    const char* name;         // in messages and listings: "light sampler"
    const char* selector;     // the command-line flag: "--light-sampler"; "" for none
    const char* scene_block;  // the scene file's block that names it: "render"; "" for none
    const char* scene_key;    // the key in that block: "light_sampler"
    const char* purpose;      // what choosing one decides, for --help: "how lights are chosen ..."
    // Chosen per run (a comparison's runs may each name their own: INTEGRATOR@NAME), rather than
    // once for the scene (the accelerator, the texture layout, the camera).
    bool per_run = false;
};
const KindDescription& kind_description(CapabilityKind kind);
const char* capability_kind_name(CapabilityKind kind);

// One line of a course's table of contents: the chapter that introduces a named capability.
struct CatalogueEntry {
    CapabilityKind kind;
    const char* name;
    int chapter;
};

// Which renderer the catalogues belong to, for messages about names they lack: the program, its
// last chapter and the course's table of contents (which chapter introduces each name). Shared
// by the registry and its catalogues, so that a registry can be moved.
struct RendererIdentity {
    std::string program;
    int chapter = 0;
    const std::vector<CatalogueEntry>* table_of_contents = nullptr;
    // The chapter that introduces `name` of `kind` in the table of contents; 0 when unknown.
    int chapter_introducing(CapabilityKind kind, const std::string& name) const;
};

// A registered capability, as listings show it.
struct CapabilityEntry {
    std::string name;
    int chapter;          // the chapter whose implementation this is
    std::string summary;
    int introduced_in;    // the chapter that first registered the name
};

// What every catalogue answers, whatever its factories make.
class CatalogueBase {
public:
    CatalogueBase(CapabilityKind kind, std::shared_ptr<const RendererIdentity> renderer)
        : kind_(kind), renderer_(std::move(renderer)) {}
    virtual ~CatalogueBase() = default;

    CapabilityKind kind() const { return kind_; }
    const KindDescription& description() const { return kind_description(kind_); }
    bool has(const std::string& name) const { return entries_.count(name) > 0; }
    // Everything registered, in name order, for `--help` and `info`.
    std::vector<CapabilityEntry> list() const;
    // The one used when neither the scene nor the command line names one: the first registered,
    // until a chapter says otherwise (chapter 06 makes its KD-tree the default accelerator).
    const std::string& default_name() const { return default_; }
    void set_default(const std::string& name);  // std::logic_error unless `name` is registered
    // Throws the InputError of an unknown name at `where` unless the catalogue has it: the
    // chapter that introduces the name, or the nearest registered name when no chapter does.
    void require(const std::string& name, const std::string& where) const;
    [[noreturn]] void unknown(const std::string& name, const std::string& where) const;

protected:
    // Adds or replaces `name`; a replacement keeps the chapter that introduced the name (chapter
    // 02's cosine-sampled "diffuse" replaces chapter 01's, which introduced it).
    void add_entry(const std::string& name, int chapter, const std::string& summary);

private:
    CapabilityKind kind_;
    std::shared_ptr<const RendererIdentity> renderer_;
    std::map<std::string, CapabilityEntry> entries_;
    std::string default_;
};

// The catalogue of a kind whose capabilities `Factory` (a std::function) makes.
template <typename Factory>
class Catalogue final : public CatalogueBase {
public:
    using CatalogueBase::CatalogueBase;

    // Adding a name that exists replaces it: a later chapter may supersede an earlier one's
    // implementation.
    void add(const std::string& name, int chapter, const std::string& summary, Factory factory) {
        add_entry(name, chapter, summary);
        factories_[name] = std::move(factory);
    }
    // The factory registered under `name`; null when there is none (for a capability made of
    // others, such as chapter 05's `auto`).
    const Factory* find(const std::string& name) const {
        const auto it = factories_.find(name);
        return it != factories_.end() ? &it->second : nullptr;
    }
    // Makes `name` from the factory's `arguments`; an unknown name is an InputError at `where`.
    template <typename... Arguments>
    auto make(const std::string& name, const std::string& where, Arguments&&... arguments) const {
        const Factory* factory = find(name);
        if (factory == nullptr) unknown(name, where);
        return (*factory)(std::forward<Arguments>(arguments)...);
    }

private:
    std::map<std::string, Factory> factories_;
};

// The name among `candidates` closest to `name` by edit distance (for "did you mean").
std::string nearest_name(const std::string& name, const std::vector<std::string>& candidates);

}  // namespace freezeray
