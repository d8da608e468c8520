// The `render` command: load, render, write; and the guarantees of a long render: a signal
// writes what was done, checkpoints are atomic, and a resumed render equals the uninterrupted one.
#include "commands.hpp"

#include "freezeray/comparison.hpp"
#include "freezeray/error.hpp"
#include "freezeray/image.hpp"
#include "freezeray/progress.hpp"
#include "freezeray/render_state.hpp"
#include "freezeray/scene.hpp"
#include "freezeray/scene_loader.hpp"
#include "freezeray/run_plan.hpp"

#include <atomic>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <unistd.h>

namespace freezeray {

namespace {

// Set by the first SIGINT or SIGTERM: the render stops after its current tiles and writes what
// it has. A second signal ends the process at once (the conventional 128 + signal number).
std::atomic<bool> stop_requested{false};
volatile std::sig_atomic_t received_signal = 0;

extern "C" void on_signal(int signal_number) {
    if (received_signal != 0) _exit(128 + signal_number);
    received_signal = signal_number;
    stop_requested.store(true);
}

// Installs the handlers for the duration of a render and restores the defaults after it.
struct SignalGuard {
    SignalGuard() {
        std::signal(SIGINT, on_signal);
        std::signal(SIGTERM, on_signal);
    }
    ~SignalGuard() {
        std::signal(SIGINT, SIG_DFL);
        std::signal(SIGTERM, SIG_DFL);
    }
};

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
    if (o.sample_offset < 0) throw InputError("--sample-offset", "must not be negative");
    if (o.checkpoint_seconds < 0.0) throw InputError("--checkpoint", "must be positive (seconds between checkpoints)");
}

std::string default_output_path(const std::string& scene_path, const std::string& integrator) {
    std::filesystem::path p(scene_path);
    std::string name = p.stem().string();
    if (name == "scene") name = p.parent_path().filename().string();
    std::filesystem::create_directories("out");
    return "out/" + name + "-" + integrator + ".png";
}

// The state file that goes with an output image.
std::string state_path_for(const std::string& out) { return out + ".state"; }

// The image of a film, with what it is in its metadata (EXR keeps it).
Image annotated_image(const Film& film, const RenderStateInfo& info, double seconds, bool interrupted) {
    Image image = film.mean();
    image.metadata["freezeray:integrator"] = info.integrator;
    image.metadata["freezeray:sampler"] = info.sampler;
    if (!info.light_sampler.empty()) image.metadata["freezeray:light_sampler"] = info.light_sampler;
    image.metadata["freezeray:scene"] = info.scene;
    image.metadata["freezeray:samples_per_pixel"] = std::to_string(film.minimum_sample_count());
    image.metadata["freezeray:seed"] = std::to_string(info.seed);
    image.metadata["freezeray:sample_offset"] = std::to_string(info.first_sample);
    image.metadata["freezeray:seconds"] = std::to_string(seconds);
    image.metadata["freezeray:estimated_relative_mse"] = std::to_string(film.estimated_relative_mse());
    image.metadata["freezeray:invalid_samples"] = std::to_string(film.invalid_sample_count());
    if (interrupted) image.metadata["freezeray:interrupted"] = "true";
    return image;
}

}  // namespace

void write_extra_images(const RenderResult& result, const std::string& subfolder, float exposure) {
    if (result.extra_images.empty()) return;
    // The integrator's own option chose the folder and checked it before the render.
    const std::filesystem::path folder = std::filesystem::path(result.extra_images_folder) / subfolder;
    std::error_code error;
    std::filesystem::create_directories(folder, error);
    if (error) throw InputError(folder.string(), "cannot create the folder: " + error.message());
    for (const auto& [name, image] : result.extra_images) write_image((folder / name).string(), image, {exposure});
}

int run_render(const RenderOptions& options, const Registry& registry) {
    check_render_options(options);
    SceneLoadOptions load;
    load.selections = options.selections;
    load.options = options.chapter_options;
    load.width = options.width;
    load.height = options.height;
    Scene scene = load_scene(options.scene, registry, load);
    for (const std::string& w : scene.warnings) std::cerr << "warning: " << w << "\n";
    if (!options.quiet) {
        std::string accelerator;  // one line: "accelerator: build 12.3 ms, ...; nodes ..."
        for (const auto& [name, value] : scene.accelerator->describe())
            accelerator += (accelerator.empty() ? "" : "; ") + name + " " + value;
        std::cerr << "accelerator: " << scene.accelerator_name << (accelerator.empty() ? "" : ": " + accelerator) << "\n";
        if (!scene.textures.empty()) {
            char memory[32];
            std::snprintf(memory, sizeof memory, "%.1f MiB", static_cast<double>(scene.texture_memory_bytes()) / (1024.0 * 1024.0));
            std::cerr << "textures: " << scene.textures.size() << (scene.textures.size() == 1 ? " image" : " images")
                      << " in the " << scene.texture_layout << " layout, " << memory << "\n";
        }
    }

    RunRequest request;
    request.run = options.integrator;
    request.where = "--integrator";
    request.selections = options.selections;
    request.options = options.chapter_options;
    request.samples_per_pixel = options.spp_given ? static_cast<std::uint64_t>(options.spp) : 0;
    request.time_seconds = options.time_seconds;
    request.target_error = options.target_error;
    request.threads = options.threads;
    if (options.seed >= 0) request.seed = static_cast<std::uint64_t>(options.seed);
    request.first_sample = static_cast<std::uint64_t>(options.sample_offset);
    request.max_depth = options.max_depth;
    RunPlan plan = plan_run(request, scene, registry);
    RenderSettings& settings = plan.settings;
    const std::string& integrator_name = plan.integrator_name;
    const IntegratorTraits& traits = plan.traits;
    for (const std::string& w : plan.warnings) std::cerr << "warning: " << w << "\n";
    if (!options.quiet && settings.light_sampler) {
        std::string lines;
        for (const std::string& line : settings.light_sampler->description()) lines += (lines.empty() ? ": " : "; ") + line;
        std::cerr << "light sampler: " << plan.light_sampler_name << lines << "\n";
    }

    const std::string out = options.out.empty() ? default_output_path(options.scene, integrator_name) : options.out;
    check_image_writable(out);  // before hours of rendering, not after
    RenderStateInfo info{options.scene,     integrator_name,       plan.sampler_name,
                               settings.seed,     settings.first_sample, settings.max_depth,
                               scene.camera->width(), scene.camera->height(), plan.light_sampler_name};
    if (!options.resume.empty()) {
        if (!traits.resumable)
            throw InputError("--resume", integrator_name + " cannot be resumed exactly (its film is not a per-pixel sample count that "
                                         "a pass can go on from); render "
                                         "more samples with another --seed or --sample-offset and `merge` the renders");
        const RenderState saved = read_render_state(options.resume);
        check_resumable(saved.info, info);
        const std::uint64_t saved_samples = saved.film->minimum_sample_count();
        const bool counted = settings.time_seconds <= 0.0 && settings.target_error <= 0.0;
        if (counted && saved_samples >= settings.samples_per_pixel)
            throw InputError(options.spp_given ? "--spp" : "--resume",
                             "the saved render already has " + std::to_string(saved_samples) +
                                 " samples in every pixel and this one asks for " +
                                 std::to_string(settings.samples_per_pixel) + ": nothing to add (ask for more with --spp)");
        settings.resume = saved.film;
        info.seconds = saved.info.seconds;  // the time already spent; this run's is added to it
    }

    // BOOK(checkpoints)
    // Checkpoints: between passes (kept no longer than the interval), the image and the exact
    // state are written, each atomically.
    auto last_checkpoint = std::chrono::steady_clock::now();
    if (options.checkpoint_seconds > 0.0) {
        settings.max_pass_seconds = options.checkpoint_seconds;
        settings.on_pass = [&](const Film& film, std::uint64_t, double seconds) {
            const auto now = std::chrono::steady_clock::now();
            if (std::chrono::duration<double>(now - last_checkpoint).count() < options.checkpoint_seconds) return;
            RenderStateInfo so_far = info;
            so_far.seconds += seconds;
            write_render_state(state_path_for(out), so_far, film);
            write_image(out, annotated_image(film, so_far, so_far.seconds, false), {options.exposure});
            last_checkpoint = now;
        };
    }
    // END BOOK

    stop_requested.store(false);
    received_signal = 0;
    settings.stop_requested = &stop_requested;
    Progress progress(options.quiet, integrator_name);
    RenderResult result;
    {
        const SignalGuard guard;
        result = plan.integrator->render(scene, settings, progress);
    }

    // An integrator that handed the render to another (auto) names the one that made the image.
    RenderStateInfo made_by = info;
    if (!result.integrator.empty()) made_by.integrator = result.integrator;
    made_by.seconds += result.seconds;
    Image final_image = annotated_image(*result.film, made_by, made_by.seconds, result.interrupted);
    if (!result.integrator_choice.empty()) final_image.metadata["freezeray:integrator_choice"] = result.integrator_choice;
    write_image(out, final_image, {options.exposure});
    write_extra_images(result, "", options.exposure);
    if (result.interrupted || options.checkpoint_seconds > 0.0) write_render_state(state_path_for(out), made_by, *result.film);
    for (const std::string& w : result.warnings) std::cerr << "warning: " << w << "\n";
    if (!options.quiet)
        for (const std::string& n : result.notes) std::cerr << n << "\n";
    if (result.invalid_samples > 0)
        std::cerr << "warning: " << result.invalid_samples
                  << " samples were NaN, infinite or negative and were counted as zero; this is a bug in the "
                     "integrator or a material, please report it with the scene\n";
    if (result.interrupted) {
        const std::string& made_with = made_by.integrator;
        if (traits.resumable)
            std::cerr << "interrupted: wrote " << out << " (" << result.samples_per_pixel << " spp in every pixel) and "
                      << state_path_for(out) << "; continue with the same command and --resume " << state_path_for(out)
                      << "\n";
        else if (!result.integrator.empty())  // auto: what it chose goes on, not auto again
            std::cerr << "interrupted: wrote " << out << " (" << result.samples_per_pixel << " spp, by " << made_with
                      << ") and " << state_path_for(out) << "; continue with --integrator " << made_with
                      << " and --resume " << state_path_for(out) << ", or, if " << made_with
                      << " cannot resume, with --sample-offset " << result.samples_per_pixel << " and `merge`\n";
        else
            std::cerr << "interrupted: wrote " << out << " (" << result.samples_per_pixel << " spp) and "
                      << state_path_for(out) << "; " << made_with
                      << " cannot be resumed: render the rest with --sample-offset " << result.samples_per_pixel
                      << " and `merge` the two\n";
        std::cout << out << "\n";
        return 128 + static_cast<int>(received_signal);
    }
    if (!options.quiet) {
        // The estimate comes from the per-pixel variance, which assumes independent samples; an
        // image that is no estimate of light (chapter 06's traversal work) has none.
        std::string estimate = "no error estimate";
        if (result.estimated_relative_mse >= 0.0) {
            char text[64];
            std::snprintf(text, sizeof text, "estimated relMSE %.4g", result.estimated_relative_mse);
            estimate = text;
            // auto names the integrator it chose: the sampler reached the image only if that one draws from it.
            const bool drew_from_sampler = result.integrator.empty()
                                               ? traits.draws_from_sampler
                                               : registry.integrator_traits(result.integrator, "--integrator").draws_from_sampler;
            if (plan.sampler_name != "independent" && drew_from_sampler)
                estimate += " (as if independent: " + plan.sampler_name + "'s is lower)";
        }
        std::fprintf(stderr, "%s: %dx%d, %llu spp, %s, %s\n", made_by.integrator.c_str(), result.image.width(),
                     result.image.height(), static_cast<unsigned long long>(result.samples_per_pixel),
                     format_duration(result.seconds).c_str(), estimate.c_str());
    }
    std::cout << out << "\n";
    return 0;
}

}  // namespace freezeray
