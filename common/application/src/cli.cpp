// The command line shared by every chapter's renderer.
#include "freezeray/cli.hpp"

#include "commands.hpp"

#include "freezeray/agreement.hpp"
#include "freezeray/chapter_options_cli.hpp"
#include "freezeray/comparison.hpp"
#include "freezeray/error.hpp"
#include "freezeray/image.hpp"
#include "freezeray/progress.hpp"
#include "freezeray/scene.hpp"
#include "freezeray/scene_loader.hpp"
#include "freezeray/integrator_advice.hpp"
#include "freezeray/run_plan.hpp"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <iomanip>
#include <map>
#include <cstdio>
#include <set>
#include <filesystem>
#include <iostream>

namespace freezeray {

namespace {

// The command-line selectors of every kind that has one (KindDescription::selector), offered from
// one loop over the kinds: a kind appears once this renderer registers one of it. The integrator
// is the command's own choice (render's --integrator, compare's --integrators), not a selector.
class Selectors {
public:
    // `runs`: the command renders several runs, each of which may name its own per-run kinds.
    void declare(CLI::App& command, const Registry& registry, bool runs) {
        for (CapabilityKind kind : all_capability_kinds) {
            const KindDescription& d = kind_description(kind);
            const CatalogueBase& catalogue = registry.catalogue(kind);
            if (*d.selector == '\0' || kind == CapabilityKind::Integrator || catalogue.list().empty()) continue;
            std::string names;
            for (const CapabilityEntry& e : catalogue.list()) names += (names.empty() ? "" : ", ") + e.name;
            std::string own;  // "a run may name its own: INTEGRATOR@LIGHT_SAMPLER; "
            if (runs && d.per_run) {
                std::string upper = d.name;
                for (char& c : upper) c = c == ' ' ? '_' : static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
                own = "a run may name its own: INTEGRATOR@" + upper + "; ";
            }
            options_.push_back({kind, command.add_option(d.selector, values_[kind],
                                                         std::string(d.purpose) + ", one of: " + names + " (" + own +
                                                             "default: the scene's, else " + catalogue.default_name() + ")")});
        }
    }
    // The selectors given, by kind.
    Selections values() const {
        Selections given;
        for (const auto& [kind, option] : options_)
            if (option->count() > 0 && !values_.at(kind).empty()) given[kind] = values_.at(kind);
        return given;
    }

private:
    std::map<CapabilityKind, std::string> values_;  // a map: CLI11 keeps pointers to its values
    std::vector<std::pair<CapabilityKind, CLI::Option*>> options_;
};

std::string two_digit(int chapter) { return (chapter < 10 ? "0" : "") + std::to_string(chapter); }

void print_warnings(const Scene& scene) {
    for (const std::string& w : scene.warnings) std::cerr << "warning: " << w << "\n";
}

int run_info(const std::string& scene_path, const Registry& registry) {
    // The accelerator is built only when the suggestion's rules trace rays (chapter 05's probe).
    SceneLoadOptions load;
    load.build_accelerator = false;
    Scene scene = load_scene(scene_path, registry, load);
    print_warnings(scene);
    const CameraDescription& c = scene.camera_description;
    std::cout << "scene:      " << scene_path << "\n"
              << "meshes:     " << scene.meshes.size() << " (" << scene.triangle_count() << " triangles)\n"
              << "emitters:   " << scene.emissive_triangles.size() << " emissive triangles\n"
              << "camera:     " << scene.camera_type << " at (" << c.position.x << ", " << c.position.y << ", " << c.position.z
              << "), vertical fov " << c.fov_vertical_degrees << " degrees, " << c.width << "x" << c.height << "\n"
              << "bounds:     (" << scene.bounds.min.x << ", " << scene.bounds.min.y << ", " << scene.bounds.min.z
              << ") to (" << scene.bounds.max.x << ", " << scene.bounds.max.y << ", " << scene.bounds.max.z << ")\n"
              << "materials:\n";
    for (const auto& m : scene.materials) {
        std::cout << "  " << m->name << ": " << m->type;
        if (m->is_emissive())
            std::cout << ", emits (" << m->emission.r << ", " << m->emission.g << ", " << m->emission.b << ")";
        std::cout << "\n";
    }
    std::size_t area_lights = 0;
    for (const auto& light : scene.lights) area_lights += light->type() == LightType::Area ? 1 : 0;
    std::cout << "lights:     " << scene.lights.size() << " (" << area_lights << " area, "
              << scene.lights.size() - area_lights << " from the \"lights\" array";
    if (scene.environment != nullptr) std::cout << ", one of them the environment";
    std::cout << ")";
    // Before chapter 03 nothing samples lights: emissive triangles are lit only by the paths
    // that happen to hit them, so they are emitters but not (sampled) area lights.
    if (area_lights == 0 && !scene.emissive_triangles.empty())
        std::cout << "; the " << scene.emissive_triangles.size()
                  << " emissive triangles become area lights from chapter 03 on, which samples them";
    std::cout << "\n";
    // How the integrators that sample lights choose them here (chapters 03 and 10), built as a
    // render builds it.
    const CapabilityChoice light_sampler = scene_light_sampler(scene, registry);
    std::unique_ptr<LightSampler> sampler;
    if (!light_sampler.name.empty() && !scene.lights.empty()) {
        sampler = registry.light_samplers.make(light_sampler.name, light_sampler.where, scene.lights, Parameters::none());
        std::cout << "light sampler: " << light_sampler.name << "\n";
        for (const std::string& line : sampler->description()) std::cout << "  " << line << "\n";
    }
    const bool traced = std::any_of(registry.advice_rules().begin(), registry.advice_rules().end(),
                                    [](const AdviceRule& rule) { return rule.traces_rays; });
    if (traced) build_accelerator(scene);
    std::cout << "accelerator: " << scene.accelerator_name;
    if (!scene.accelerator_built) {
        std::cout << " (not built: `render` builds it)\n";
    } else {
        char built[64];
        std::snprintf(built, sizeof built, " (built in %.1f ms for the suggestion's probe)\n", 1e3 * scene.accelerator_build_seconds);
        std::cout << built;
        for (const auto& [name, value] : scene.accelerator->describe()) std::cout << "  " << name << ": " << value << "\n";
    }
    std::cout << "effects:\n" << scene.effects.describe();
    std::cout << "work per ray ([ ] left out: the scene does not call for it):\n" << describe_work_per_ray(scene);
    // The best suited integrator this renderer has, and what its chapters measured to say so.
    std::vector<std::string> notes;
    const IntegratorAdvice suggestion = advise_integrator(scene, registry, AdviceRequest{true, sampler.get(), &notes});
    for (const std::string& note : notes) std::cout << note << "\n";
    std::cout << "suggested:  " << (suggestion.name.empty() ? "none: " + suggestion.reason
                                                             : suggestion.name + " (" + suggestion.reason + ")")
              << "\n";
    if (!scene.texture_layout.empty()) {
        const std::size_t bytes = scene.texture_memory_bytes();
        std::cout << "textures:   stored in the " << scene.texture_layout << " layout: " << scene.textures.size()
                  << (scene.textures.size() == 1 ? " image, " : " images, ") << std::fixed << std::setprecision(1)
                  << static_cast<double>(bytes) / (1024.0 * 1024.0) << " MiB\n";
        std::cout.unsetf(std::ios::fixed);
        std::map<std::string, int> kinds;  // how many images are stored each way
        for (const auto& texture : scene.textures) ++kinds[texture->description()];
        for (const auto& [description, count] : kinds)
            std::cout << "  " << count << (count == 1 ? " image: " : " images: ") << description << "\n";
    }
    return 0;
}

// Parses "x,y,width,height".
CropRegion parse_crop(const std::string& text) {
    CropRegion crop;
    char extra = 0;
    if (std::sscanf(text.c_str(), "%d,%d,%d,%d%c", &crop.x, &crop.y, &crop.width, &crop.height, &extra) != 4)
        throw InputError("--crop", "'" + text + "' is not x,y,width,height");
    crop.reason = "chosen by the user";
    return crop;
}

int run_compare(CompareRequest request, const std::vector<std::string>& crops, const Registry& registry) {
    for (const std::string& c : crops) request.crops.push_back(parse_crop(c));
    const Comparison comparison = run_comparison(request, registry);
    write_comparison_report(comparison, request.out_folder);
    int name_width = 12;  // the runs' names in one column, however long ("INTEGRATOR@SAMPLER")
    for (const IntegratorRun& run : comparison.runs) name_width = std::max(name_width, static_cast<int>(run.integrator.size()));
    const std::optional<std::size_t> unconverged = odd_one_out(comparison.agreements, comparison.runs.size());
    for (const IntegratorRun& run : comparison.runs) {
        char slope[48] = "no fit";
        if (run.fit.has_interval())
            std::snprintf(slope, sizeof slope, "slope %.2f (%.2f to %.2f)", run.fit.slope, run.fit.slope_low, run.fit.slope_high);
        else if (run.fit.points > 0)
            std::snprintf(slope, sizeof slope, "slope %.2f (no interval)", run.fit.slope);
        char error[32] = "none";  // no reference and no per-pixel variance: no estimate, not -1
        if (run.relative_mse >= 0.0) std::snprintf(error, sizeof error, "%.4g", run.relative_mse);
        std::fprintf(stderr, "%-*s %8llu spp %8.2f s  relMSE %-10s%s  %s\n", name_width, run.integrator.c_str(),
                     static_cast<unsigned long long>(run.result.samples_per_pixel), run.result.seconds, error,
                     run.error_is_estimated && run.relative_mse >= 0.0 ? " (estimated)" : "", slope);
        for (const std::string& w : run.result.warnings) std::fprintf(stderr, "warning: %s: %s\n", run.integrator.c_str(), w.c_str());
        if (unconverged && &comparison.runs[*unconverged] == &run)
            std::fprintf(stderr, "%s has not converged: its image disagrees with every other run's far beyond their "
                                 "noise, so its relMSE above is not its error (the report leaves it unranked)\n",
                         run.integrator.c_str());
    }
    std::cout << request.out_folder << "/report.html\n";
    return 0;
}

}  // namespace

// The chapters whose capabilities this renderer holds, as "01 to 06 and 09": a chapter not
// written yet leaves a gap.
std::string chapters_contained(const Registry& registry) {
    std::set<int> chapters;
    for (CapabilityKind kind : all_capability_kinds)
        for (const Registry::Entry& e : registry.list(kind))
            if (e.chapter >= 1 && e.chapter <= registry.chapter()) chapters.insert(e.chapter);
    std::vector<std::string> runs;  // "01 to 06", "09"
    for (auto it = chapters.begin(); it != chapters.end();) {
        const int first = *it;
        int last = first;
        while (++it != chapters.end() && *it == last + 1) last = *it;
        if (last == first) runs.push_back(two_digit(first));
        else if (last == first + 1) runs.push_back(two_digit(first) + " and " + two_digit(last));
        else runs.push_back(two_digit(first) + " to " + two_digit(last));
    }
    std::string text;
    for (std::size_t i = 0; i < runs.size(); ++i)
        text += (i == 0 ? "" : i + 1 == runs.size() ? " and " : ", ") + runs[i];
    return text;
}

int run_command_line(int argc, char** argv, const Registry& registry) {
    const std::string chapters = chapters_contained(registry);
    CLI::App app{"FreezeRay " + registry.program() + ": the renderer of chapter" +
                 (chapters.size() > 2 ? "s " : " ") + chapters + " of the course"};
    app.require_subcommand(1);
    app.set_version_flag("--version", "FreezeRay " + registry.program() + " " + FREEZERAY_VERSION + " (chapter" +
                                          (chapters.size() > 2 ? "s " : " ") + chapters + ")");

    RenderOptions render;
    std::string integrators;
    for (const auto& e : registry.list(CapabilityKind::Integrator)) integrators += (integrators.empty() ? "" : ", ") + e.name;
    CLI::App* render_command = app.add_subcommand("render", "render a scene to an image");
    render_command->add_option("scene", render.scene, "the scene's JSON file")->required();
    render_command->add_option("--integrator", render.integrator, "one of: " + integrators);
    auto* spp = render_command->add_option("--spp", render.spp, "samples per pixel (default: the scene's)");
    auto* time = render_command->add_option("--time", render.time_seconds, "render for this many seconds");
    render_command->add_option("--target-error", render.target_error,
                               "stop when the estimated relMSE falls below this (with --spp as a cap)");
    time->excludes(spp);
    Selectors render_selectors;
    render_selectors.declare(*render_command, registry, false);
    render_command->add_option("--threads", render.threads, "threads (default: every core)");
    render_command->add_option("--seed", render.seed, "random seed (default: the scene's)");
    render_command->add_option("--max-depth", render.max_depth, "maximum path length in segments");
    render_command->add_option("--width", render.width, "image width (default: the scene's)");
    render_command->add_option("--height", render.height, "image height (default: the scene's)");
    render_command->add_option("--out", render.out, "output image: .exr, .pfm, .hdr or .png (default: out/SCENE-INTEGRATOR.png)");
    render_command->add_option("--exposure", render.exposure, "exposure in stops, for PNG output");
    render_command->add_option("--sample-offset", render.sample_offset,
                               "first sample index (to split one seed's samples over several renders; see merge)");
    render_command->add_option("--checkpoint", render.checkpoint_seconds,
                               "write the image and OUT.state atomically every this many seconds");
    render_command->add_option("--resume", render.resume, "continue the render saved in this .state file");
    render_command->add_flag("--quiet", render.quiet, "no progress line");
    ChapterOptions chapter_options;
    chapter_options.declare(*render_command, registry.options());

    std::string info_scene;
    CLI::App* info_command = app.add_subcommand("info", "what a scene contains and which effects it calls for");
    info_command->add_option("scene", info_scene, "the scene's JSON file")->required();

    std::string merge_out;
    std::vector<std::string> merge_inputs;
    bool merge_quiet = false;
    CLI::App* merge_command = app.add_subcommand(
        "merge", "combine renders of one scene made from disjoint samples (other seeds or --sample-offset ranges)");
    merge_command->add_option("out", merge_out, "the merged image")->required();
    merge_command->add_option("inputs", merge_inputs, "renders: EXR files written by render, or .state files")->required();
    merge_command->add_flag("--quiet", merge_quiet, "no summary line");

    CompareRequest compare;
    std::string compare_integrators;
    std::vector<std::string> compare_crops;
    CLI::App* compare_command =
        app.add_subcommand("compare", "render a scene with several integrators at equal time or samples; write a report");
    compare_command->add_option("scene", compare.scene, "the scene's JSON file")->required();
    compare_command->add_option("--integrators", compare_integrators, "comma-separated: " + integrators)->required();
    auto* compare_time = compare_command->add_option("--time", compare.time_seconds, "seconds per integrator");
    auto* compare_spp = compare_command->add_option("--spp", compare.samples_per_pixel, "samples per pixel per integrator");
    compare_time->excludes(compare_spp);
    compare_command->add_option("--reference", compare.reference, "reference image (EXR, PFM, HDR)");
    compare_command->add_option("--out", compare.out_folder,
                                "folder for report.html, report.md, convergence.csv, time_to_accuracy.csv");
    std::string make_reference;
    double reference_target_error = 0.0;
    compare_command->add_option("--make-reference", make_reference,
                                "instead of comparing, render a reference for this comparison to FILE.exr, with the one "
                                "integrator of --integrators, under a seed other than the comparison's");
    compare_command
        ->add_option("--target-error", reference_target_error,
                     "with --make-reference: stop when the reference's estimated relMSE falls below this (--time, --spp cap it)")
        ->check(CLI::PositiveNumber);
    Selectors compare_selectors;
    compare_selectors.declare(*compare_command, registry, true);
    compare_command->add_option("--threads", compare.threads, "threads (default: every core)");
    compare_command->add_option("--seed", compare.seed,
                                "random seed of the runs (default 0); a reference made with --make-reference gets another");
    compare_command->add_option("--max-depth", compare.max_depth, "maximum path length in segments");
    compare_command->add_option("--width", compare.width, "image width (default: the scene's)");
    compare_command->add_option("--height", compare.height, "image height (default: the scene's)");
    compare_command->add_option("--crop", compare_crops, "a region x,y,width,height to show magnified (repeatable)");
    compare_command->add_flag("--quiet", compare.quiet, "no progress lines");
    ChapterOptions compare_options;
    compare_options.declare(*compare_command, registry.options());

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        const int status = app.exit(e);  // prints the help, the version, or what is wrong
        return status == 0 ? 0 : 1;       // --help and --version succeed; every usage error is exit status 1
    }

    try {
        render.spp_given = spp->count() > 0;
        render.chapter_options = chapter_options.values();
        render.selections = render_selectors.values();
        compare.selections = compare_selectors.values();
        compare.options = compare_options.values();
        if (*render_command) return run_render(render, registry);
        if (*info_command) return run_info(info_scene, registry);
        if (*merge_command) return run_merge(merge_out, merge_inputs, merge_quiet);
        if (*compare_command) {
            std::string name;
            for (char ch : compare_integrators + ",") {
                if (ch != ',') {
                    name += ch;
                } else if (!name.empty()) {
                    compare.integrators.push_back(name);
                    name.clear();
                }
            }
            if (!make_reference.empty()) {
                for (const std::string& c : compare_crops) compare.crops.push_back(parse_crop(c));
                return run_make_reference(compare, reference_target_error, make_reference, registry);
            }
            if (reference_target_error > 0.0)
                throw InputError("--target-error", "only --make-reference stops at an error; a comparison runs its budget");
            return run_compare(compare, compare_crops, registry);
        }
    } catch (const InputError& e) {
        std::cerr << "error: " << e.what() << "\n";
        return 1;
    } catch (const std::bad_alloc&) {
        std::cerr << "error: out of memory\n";
        return 1;
    } catch (const std::exception& e) {
        std::cerr << "error: " << e.what() << "\n";
        return 1;
    }
    return 0;
}

}  // namespace freezeray
