// The command line shared by every chapter's renderer.
#include "freezeray/cli.hpp"

#include "freezeray/comparison.hpp"
#include "freezeray/error.hpp"
#include "freezeray/image.hpp"
#include "freezeray/progress.hpp"
#include "freezeray/scene.hpp"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <filesystem>
#include <iostream>

namespace freezeray {

namespace {

// Options of `render`, as typed (strings where we want our own checks and messages).
struct RenderOptions {
    std::string scene;
    std::string integrator;
    long long spp = 0;
    bool spp_given = false;
    double time_seconds = 0.0;
    double target_error = 0.0;
    std::string accelerator = "bruteforce";
    int threads = 0;
    long long seed = -1;
    int max_depth = -1;
    int width = 0;
    int height = 0;
    std::string out;
    float exposure = 0.0f;
    bool quiet = false;
};

std::string two_digit(int chapter) { return (chapter < 10 ? "0" : "") + std::to_string(chapter); }

// Checks the options that CLI11 cannot check alone; throws InputError naming the option.
void check_render_options(const RenderOptions& o) {
    if (o.spp_given && o.spp < 1)
        throw InputError("--spp", "the sample count must be at least 1 (got " + std::to_string(o.spp) + ")");
    if (o.spp > (1LL << 40)) throw InputError("--spp", "the sample count " + std::to_string(o.spp) + " is absurd");
    if (o.time_seconds < 0.0) throw InputError("--time", "must be positive");
    if (o.target_error < 0.0) throw InputError("--target-error", "must be positive");
    if (o.threads < 0 || o.threads > 1024) throw InputError("--threads", "must be between 1 and 1024 (0: every core)");
    if (o.max_depth < -1) throw InputError("--max-depth", "must not be negative");
    if (o.width < 0 || o.height < 0 || o.width > 65536 || o.height > 65536 ||
        static_cast<long long>(o.width) * o.height > (1LL << 26))
        throw InputError("--width/--height", "resolution must be between 1x1 and 65536x65536, at most 2^26 pixels");
    if (o.seed < -1) throw InputError("--seed", "must not be negative");
}

std::string default_output_path(const std::string& scene_path, const std::string& integrator) {
    std::filesystem::path p(scene_path);
    std::string name = p.stem().string();
    if (name == "scene") name = p.parent_path().filename().string();
    std::filesystem::create_directories("out");
    return "out/" + name + "-" + integrator + ".png";
}

void print_warnings(const Scene& scene) {
    for (const std::string& w : scene.warnings) std::cerr << "warning: " << w << "\n";
}

int run_render(const RenderOptions& options, const Registry& registry) {
    check_render_options(options);
    SceneLoadOptions load;
    load.accelerator = options.accelerator;
    load.width = options.width;
    load.height = options.height;
    Scene scene = load_scene(options.scene, registry, load);
    print_warnings(scene);

    RenderSettings settings;
    settings.samples_per_pixel = options.spp_given ? static_cast<std::uint64_t>(options.spp) : scene.defaults.samples_per_pixel;
    settings.time_seconds = options.time_seconds;
    settings.target_error = options.target_error;
    if (options.target_error > 0.0 && !options.spp_given) settings.samples_per_pixel = UINT64_MAX;  // error decides
    settings.threads = options.threads;
    settings.seed = options.seed >= 0 ? static_cast<std::uint64_t>(options.seed) : scene.defaults.seed;
    settings.max_depth = options.max_depth >= 0 ? options.max_depth : scene.defaults.max_depth;

    std::string integrator_name = options.integrator;
    if (integrator_name.empty()) integrator_name = scene.defaults.integrator;
    if (integrator_name.empty()) integrator_name = registry.list(CapabilityKind::Integrator).front().name;
    const auto integrator = registry.make_integrator(integrator_name, settings, "--integrator");

    const std::string out = options.out.empty() ? default_output_path(options.scene, integrator_name) : options.out;
    check_image_writable(out);  // before hours of rendering, not after

    Progress progress(options.quiet);
    RenderResult result = integrator->render(scene, settings, progress);

    result.image.metadata["freezeray:integrator"] = integrator_name;
    result.image.metadata["freezeray:scene"] = options.scene;
    result.image.metadata["freezeray:samples_per_pixel"] = std::to_string(result.samples_per_pixel);
    result.image.metadata["freezeray:seed"] = std::to_string(settings.seed);
    result.image.metadata["freezeray:seconds"] = std::to_string(result.seconds);
    result.image.metadata["freezeray:estimated_relative_mse"] = std::to_string(result.estimated_relative_mse);
    result.image.metadata["freezeray:invalid_samples"] = std::to_string(result.invalid_samples);
    ImageWriteOptions write_options;
    write_options.exposure_stops = options.exposure;
    write_image(out, result.image, write_options);

    if (result.invalid_samples > 0)
        std::cerr << "warning: " << result.invalid_samples
                  << " samples were NaN, infinite or negative and were counted as zero; this is a bug in the "
                     "integrator or a material, please report it with the scene\n";
    if (!options.quiet) {
        std::fprintf(stderr, "%s: %dx%d, %llu spp, %s, estimated relMSE %.4g\n", integrator_name.c_str(),
                     result.image.width(), result.image.height(), static_cast<unsigned long long>(result.samples_per_pixel),
                     format_duration(result.seconds).c_str(), result.estimated_relative_mse);
    }
    std::cout << out << "\n";
    return 0;
}

int run_info(const std::string& scene_path, const Registry& registry) {
    Scene scene = load_scene(scene_path, registry);
    print_warnings(scene);
    const CameraDescription& c = scene.camera_description;
    std::cout << "scene:      " << scene_path << "\n"
              << "meshes:     " << scene.meshes.size() << " (" << scene.triangle_count() << " triangles)\n"
              << "emitters:   " << scene.emissive_triangles.size() << " emissive triangles\n"
              << "camera:     pinhole at (" << c.position.x << ", " << c.position.y << ", " << c.position.z
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
    std::cout << "effects:\n" << scene.effects.describe();
    std::cout << "suggested:  " << scene.effects.suggested_integrator(registry.chapter()) << "\n";
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
    for (const IntegratorRun& run : comparison.runs) {
        std::fprintf(stderr, "%-12s %8llu spp %8.2f s  relMSE %-10.4g%s  slope %.2f\n", run.integrator.c_str(),
                     static_cast<unsigned long long>(run.result.samples_per_pixel), run.result.seconds, run.relative_mse,
                     run.error_is_estimated ? " (estimated)" : "", run.fit.slope);
    }
    std::cout << request.out_folder << "/report.html\n";
    return 0;
}

}  // namespace

int run_command_line(int argc, char** argv, const Registry& registry) {
    CLI::App app{"FreezeRay " + registry.program() + ": the renderer of chapters 01 to " + two_digit(registry.chapter()) +
                 " of the course"};
    app.require_subcommand(1);

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
    render_command->add_option("--accel", render.accelerator, "ray-intersection accelerator");
    render_command->add_option("--threads", render.threads, "threads (default: every core)");
    render_command->add_option("--seed", render.seed, "random seed (default: the scene's)");
    render_command->add_option("--max-depth", render.max_depth, "maximum path length in segments");
    render_command->add_option("--width", render.width, "image width (default: the scene's)");
    render_command->add_option("--height", render.height, "image height (default: the scene's)");
    render_command->add_option("--out", render.out, "output image: .exr, .pfm, .hdr or .png (default: out/SCENE-INTEGRATOR.png)");
    render_command->add_option("--exposure", render.exposure, "exposure in stops, for PNG output");
    render_command->add_flag("--quiet", render.quiet, "no progress line");

    std::string info_scene;
    CLI::App* info_command = app.add_subcommand("info", "what a scene contains and which effects it calls for");
    info_command->add_option("scene", info_scene, "the scene's JSON file")->required();

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
    compare_command->add_option("--out", compare.out_folder, "folder for report.html, report.md, convergence.csv")->required();
    compare_command->add_option("--threads", compare.threads, "threads (default: every core)");
    compare_command->add_option("--seed", compare.seed, "random seed");
    compare_command->add_option("--max-depth", compare.max_depth, "maximum path length in segments");
    compare_command->add_option("--width", compare.width, "image width (default: the scene's)");
    compare_command->add_option("--height", compare.height, "image height (default: the scene's)");
    compare_command->add_option("--crop", compare_crops, "a region x,y,width,height to show magnified (repeatable)");
    compare_command->add_flag("--quiet", compare.quiet, "no progress lines");

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e);
    }

    try {
        render.spp_given = spp->count() > 0;
        if (*render_command) return run_render(render, registry);
        if (*info_command) return run_info(info_scene, registry);
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
