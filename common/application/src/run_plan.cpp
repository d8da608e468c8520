// One rule for assembling a run (run_plan.hpp).
#include "freezeray/run_plan.hpp"

#include "freezeray/error.hpp"
#include "freezeray/integrator_advice.hpp"
#include "freezeray/scene.hpp"
#include "freezeray/scene_loader.hpp"

#include <algorithm>

namespace freezeray {

namespace {

// The kinds a run may name after an @, in the order a run name lists them.
std::vector<CapabilityKind> per_run_kinds() {
    std::vector<CapabilityKind> kinds;
    for (CapabilityKind kind : all_capability_kinds)
        if (kind_description(kind).per_run) kinds.push_back(kind);
    return kinds;
}

// What the scene's "render" block names for a per-run kind ("" for none), and where.
std::string scene_named(const Scene& scene, CapabilityKind kind) {
    const auto it = scene.defaults.named.find(kind);
    return it != scene.defaults.named.end() ? it->second : "";
}
std::string scene_place(const Scene& scene, CapabilityKind kind) {
    const KindDescription& d = kind_description(kind);
    return scene.file + ": /" + d.scene_block + "/" + d.scene_key;
}

// A per-run kind's choice: the run's own @ name (given at `where`), else the command line's
// selector, else the scene's, else the default.
CapabilityChoice choose_for_run(CapabilityKind kind, const RunName& run, const std::string& where, const Selections& selections,
                                const Scene& scene, const Registry& registry) {
    const CatalogueBase& catalogue = registry.catalogue(kind);
    if (const auto it = run.named.find(kind); it != run.named.end()) return {it->second, where, true};
    return choose_capability(catalogue, selections, scene_named(scene, kind), scene_place(scene, kind));
}

// The integrator for a render that names none: the scene's, else the registered one the scene's
// effects call for, else the first registered.
std::string default_integrator(const Scene& scene, const Registry& registry) {
    if (!scene.defaults.integrator.empty()) return scene.defaults.integrator;
    const IntegratorAdvice suggestion = advise_integrator(scene, registry);
    return !suggestion.name.empty() ? suggestion.name : registry.integrators.list().front().name;
}

// A warning for an integrator that cannot find the scene's point, spot and directional lights
// (no ray can hit them), or an empty string.
std::string unreachable_lights_warning(const Scene& scene, const IntegratorTraits& integrator, const std::string& name) {
    if (!scene.effects.delta_lights || integrator.samples_lights) return "";
    return name + " finds light only by hitting it; the scene's point, spot and directional lights cannot be hit "
                  "and stay black (an integrator that samples lights renders them: `info` suggests one)";
}

// The sampler: an integrator that does not draw from one refuses a named sampler other than
// independent; without a name it gets independent, which is what its own streams are.
void plan_sampler(RunPlan& plan, const CapabilityChoice& choice, const Registry& registry) {
    std::string name = choice.name;
    if (!plan.traits.draws_from_sampler && name != "independent") {
        if (choice.named)
            throw InputError(choice.where, plan.integrator_name +
                                               " draws its numbers from its own streams (light paths, Markov chains), "
                                               "not from a sampler: only the integrators whose samples belong to pixels "
                                               "take --sampler " + name);
        name = "independent";
    }
    plan.sampler_name = name;
    plan.settings.sampler = registry.samplers.make(name, choice.where, Parameters::none());
}

// The light sampler, built over the scene's lights, for the integrators that choose lights at
// shading points; the others refuse a name given for the run (a scene's applies to those that
// read it).
void plan_light_sampler(RunPlan& plan, const CapabilityChoice& choice, bool given_for_run, const Scene& scene,
                        const Registry& registry) {
    if (!plan.traits.chooses_lights_per_point) {
        if (given_for_run)
            throw InputError(choice.where, plan.integrator_name +
                                               " does not choose lights through a light sampler (only the integrators "
                                               "that sample a light at each shading point do; light paths and "
                                               "bidirectional strategies choose by power everywhere)");
        return;
    }
    if (choice.name.empty()) return;  // before chapter 03: no light samplers
    plan.light_sampler_name = choice.name;
    plan.settings.light_sampler = registry.light_samplers.make(choice.name, choice.where, scene.lights, Parameters::none());
}

}  // namespace

RunName parse_run_name(const std::string& run, const Registry& registry, const std::string& where) {
    const std::vector<CapabilityKind> kinds = per_run_kinds();
    std::string forms = "INTEGRATOR";  // "INTEGRATOR, INTEGRATOR@SAMPLER, ..."
    std::string all = "INTEGRATOR";
    for (CapabilityKind kind : kinds) {
        std::string upper = kind_description(kind).name;
        std::transform(upper.begin(), upper.end(), upper.begin(), [](char c) { return c == ' ' ? '_' : static_cast<char>(std::toupper(c)); });
        forms += ", INTEGRATOR@" + upper;
        all += "@" + upper;
    }
    const std::string usage = "'" + run + "': write " + forms + " or " + all;
    RunName name;
    std::size_t at = run.find('@');
    name.integrator = run.substr(0, at);
    if (name.integrator.empty()) throw InputError(where, usage);
    while (at != std::string::npos) {
        const std::size_t next = run.find('@', at + 1);
        const std::string part = run.substr(at + 1, next == std::string::npos ? std::string::npos : next - at - 1);
        if (part.empty()) throw InputError(where, usage);
        // The first kind that has the name and is not named yet takes it.
        bool known = false, placed = false;
        for (CapabilityKind kind : kinds) {
            if (!registry.has(kind, part)) continue;
            known = true;
            if (name.named.emplace(kind, part).second) {
                placed = true;
                break;
            }
        }
        // An unknown name: the chapter that introduces it, or the nearest name of the first kind.
        if (!known) registry.require(kinds.front(), part, where);
        if (!placed) throw InputError(where, usage + ": a run names at most one of each");
        at = next;
    }
    return name;
}

CapabilityChoice scene_light_sampler(const Scene& scene, const Registry& registry) {
    return choose_capability(registry.light_samplers, {}, scene_named(scene, CapabilityKind::LightSampler),
                             scene_place(scene, CapabilityKind::LightSampler));
}

std::vector<RunPlan> plan_runs(const std::vector<RunRequest>& requests, const Scene& scene, const Registry& registry) {
    // Names first: an unknown integrator is reported before an option that it would not read.
    std::vector<RunName> names;
    std::vector<std::string> integrators;
    for (const RunRequest& request : requests) {
        RunName name = request.run.empty() ? RunName{} : parse_run_name(request.run, registry, request.where);
        if (name.integrator.empty()) name.integrator = default_integrator(scene, registry);
        registry.require(CapabilityKind::Integrator, name.integrator, request.where);
        integrators.push_back(name.integrator);
        names.push_back(std::move(name));
    }
    for (const RunRequest& request : requests)
        check_options_apply(request.options, registry.options(), OptionTarget::Integrator, integrators,
                            requests.size() == 1 ? "this render's integrator" : "the integrators compared");

    std::vector<RunPlan> plans;
    for (std::size_t i = 0; i < requests.size(); ++i) {
        const RunRequest& request = requests[i];
        const RunName& name = names[i];
        RunPlan plan;
        plan.name = request.run.empty() ? name.integrator : request.run;
        plan.integrator_name = name.integrator;
        plan.traits = registry.integrator_traits(name.integrator, request.where);

        RenderSettings& settings = plan.settings;
        settings.time_seconds = request.time_seconds;
        settings.target_error = request.target_error;
        settings.samples_per_pixel = request.samples_per_pixel > 0 ? request.samples_per_pixel
                                     : request.time_seconds > 0.0 || request.target_error > 0.0
                                         ? UINT64_MAX  // the time or the error decides
                                         : scene.defaults.samples_per_pixel;
        settings.threads = request.threads;
        settings.seed = request.seed ? *request.seed : scene.defaults.seed;
        settings.first_sample = request.first_sample;
        settings.max_depth = request.max_depth >= 0 ? request.max_depth : scene.defaults.max_depth;

        plan.options = integrator_options(scene, request.options, registry);
        plan.integrator = registry.integrators.make(name.integrator, request.where, settings, plan.options->parameters());
        if (std::string w = unreachable_lights_warning(scene, plan.traits, name.integrator); !w.empty())
            plan.warnings.push_back(std::move(w));
        plan_sampler(plan, choose_for_run(CapabilityKind::Sampler, name, request.where, request.selections, scene, registry),
                     registry);
        const bool light_sampler_given =
            name.named.count(CapabilityKind::LightSampler) > 0 || request.selections.count(CapabilityKind::LightSampler) > 0;
        plan_light_sampler(plan,
                           choose_for_run(CapabilityKind::LightSampler, name, request.where, request.selections, scene, registry),
                           light_sampler_given, scene, registry);
        plans.push_back(std::move(plan));
    }
    return plans;
}

RunPlan plan_run(const RunRequest& request, const Scene& scene, const Registry& registry) {
    return std::move(plan_runs({request}, scene, registry).front());
}

}  // namespace freezeray
