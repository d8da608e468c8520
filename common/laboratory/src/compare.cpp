// The `compare` command: render one scene with several integrators under the same budget and
// measure each one's error as it converges.
#include "freezeray/comparison.hpp"

#include "commands.hpp"

#include "freezeray/error.hpp"
#include "freezeray/metrics.hpp"
#include "freezeray/progress.hpp"
#include "freezeray/registry.hpp"
#include "freezeray/render_state.hpp"
#include "freezeray/scene.hpp"
#include "freezeray/scene_loader.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>
#include <string>

namespace freezeray {

double header_number(const Image& image, const std::string& key) {
    const auto it = image.metadata.find(key);
    if (it == image.metadata.end()) return -1.0;
    try {
        return std::stod(it->second);
    } catch (const std::exception&) {
        return -1.0;
    }
}

namespace {

// How far past an equal-time budget a run may go before the report mentions it.
constexpr double OvershootTolerance = 1.05;

// The output folder must be creatable: its parent exists and is a folder.
void check_output_folder(const std::string& folder) {
    if (folder.empty()) throw InputError("--out", "an output folder is required");
    std::error_code error;
    const std::filesystem::path path = std::filesystem::absolute(folder, error);
    if (std::filesystem::exists(path, error) && !std::filesystem::is_directory(path, error))
        throw InputError(folder, "exists and is not a folder");
    const std::filesystem::path parent = path.parent_path();
    if (!std::filesystem::is_directory(parent, error))
        throw InputError(folder, "the folder '" + parent.string() + "' that would hold it does not exist");
}

std::string describe_reference(const std::string& path, const Image& reference) {
    std::string text = path;
    const auto spp = reference.metadata.find("freezeray:samples_per_pixel");
    const auto integrator = reference.metadata.find("freezeray:integrator");
    if (spp != reference.metadata.end()) {
        text += " (" + spp->second + " spp";
        if (integrator != reference.metadata.end()) text += ", " + integrator->second;
        text += ")";
    }
    return text;
}

// A reference rendered from the runs' own random numbers (same seed, overlapping sample
// indices) shares their noise: errors against it come out too small. Refused when its header
// shows it; a warning when the header does not say.
void check_reference_independent(const CompareRequest& request, const Image& reference, bool quiet) {
    // The seed as the integer it is (a double would round seeds above 2^53).
    std::optional<std::uint64_t> seed;
    if (const auto it = reference.metadata.find("freezeray:seed"); it != reference.metadata.end()) {
        try {
            seed = std::stoull(it->second);
        } catch (const std::exception&) {
        }
    }
    if (!seed) {
        if (!quiet)
            std::cerr << "warning: " << request.reference << " does not say which seed it was rendered with: "
                      << "make sure it is not " << request.seed << ", this comparison's, or its errors come out too small\n";
        return;
    }
    const double offset = std::max(0.0, header_number(reference, "freezeray:sample_offset"));
    if (*seed != request.seed) return;
    // The runs draw samples 0, 1, 2, ... of their seed; the reference from `offset` on.
    const bool overlaps = request.time_seconds > 0.0 || offset < static_cast<double>(request.samples_per_pixel);
    if (overlaps)
        throw InputError(request.reference, "was rendered with seed " + std::to_string(request.seed) +
                                                ", this comparison's, from sample " + std::to_string(static_cast<std::uint64_t>(offset)) +
                                                " on: its noise is the runs' own, so errors against it are too small "
                                                "(render it with another --seed, or give compare another --seed)");
}

}  // namespace

Comparison run_comparison(const CompareRequest& request, const Registry& registry) {
    // Everything that can be wrong is checked before the first sample.
    if (request.integrators.empty()) throw InputError("--integrators", "name at least one integrator");
    if (request.time_seconds <= 0.0 && request.samples_per_pixel == 0)
        throw InputError("--time/--spp", "give a time budget (--time) or a sample count (--spp)");
    check_output_folder(request.out_folder);
    SceneLoadOptions load;
    load.selections = request.selections;
    load.options = request.options;
    load.width = request.width;
    load.height = request.height;
    const Scene scene = load_scene(request.scene, registry, load);
    for (const std::string& w : scene.warnings)
        if (!request.quiet) std::cerr << "warning: " << w << "\n";

    // Every run is planned (its names and options checked) before the first renders.
    std::vector<RunRequest> requests;
    for (const std::string& run_name : request.integrators) {
        RunRequest run;
        run.run = run_name;
        run.where = "--integrators";
        run.selections = request.selections;
        run.options = request.options;
        run.time_seconds = request.time_seconds;
        run.samples_per_pixel = request.time_seconds > 0.0 ? 0 : request.samples_per_pixel;
        run.threads = request.threads;
        run.seed = request.seed;
        run.max_depth = request.max_depth > 0 ? request.max_depth : -1;
        requests.push_back(std::move(run));
    }
    std::vector<RunPlan> plans = plan_runs(requests, scene, registry);
    for (const RunPlan& plan : plans)
        for (const std::string& w : plan.warnings)
            if (!request.quiet) std::cerr << "warning: " << w << "\n";

    Comparison comparison;
    comparison.scene = request.scene;
    comparison.renderer = registry.program();
    char budget[128];
    if (request.time_seconds > 0.0)
        std::snprintf(budget, sizeof budget, "equal time: %g s each", request.time_seconds);
    else
        std::snprintf(budget, sizeof budget, "equal samples: %llu spp each",
                      static_cast<unsigned long long>(request.samples_per_pixel));
    comparison.budget = budget;
    comparison.equal_time = request.time_seconds > 0.0;
    if (!request.reference.empty()) {
        Image reference = read_image(request.reference);
        if (reference.width() != scene.camera->width() || reference.height() != scene.camera->height())
            throw InputError(request.reference, "is " + std::to_string(reference.width()) + "x" +
                                                    std::to_string(reference.height()) + " but the scene renders " +
                                                    std::to_string(scene.camera->width()) + "x" +
                                                    std::to_string(scene.camera->height()));
        comparison.reference_description = describe_reference(request.reference, reference);
        check_reference_independent(request, reference, request.quiet);
        comparison.reference_relative_mse = header_number(reference, "freezeray:estimated_relative_mse");
        comparison.reference = std::move(reference);
    } else {
        comparison.reference_description = "none: errors are estimated from each render's per-pixel variance";
    }
    for (const CropRegion& crop : request.crops) {
        if (crop.x < 0 || crop.y < 0 || crop.width < 1 || crop.height < 1 || crop.x + crop.width > scene.camera->width() ||
            crop.y + crop.height > scene.camera->height())
            throw InputError("--crop", "region " + std::to_string(crop.x) + "," + std::to_string(crop.y) + "," +
                                           std::to_string(crop.width) + "," + std::to_string(crop.height) +
                                           " is not inside the image");
    }

    // BOOK(compare-run)
    for (RunPlan& plan : plans) {
        IntegratorRun run;
        run.integrator = plan.name;
        RenderSettings& run_settings = plan.settings;
        // At every pass boundary (1, 2, 4, ... spp) record the error so far, and that of the
        // pass's own samples (the film less the previous checkpoint's); this time is not counted
        // as render time.
        std::optional<Film> previous;
        run_settings.on_pass = [&](const Film& film, std::uint64_t spp, double seconds) {
            Checkpoint c;
            c.seconds = seconds;
            c.samples_per_pixel = spp;
            c.estimated_relative_mse = film.estimated_relative_mse();
            if (comparison.reference) {
                const Image image = film.mean();
                c.mse = mse(image, *comparison.reference);
                c.relative_mse = relative_mse(image, *comparison.reference);
            }
            if (previous && !run.checkpoints.empty() && spp > run.checkpoints.back().samples_per_pixel) {
                const Film pass = samples_added(film, *previous);
                c.pass_seconds = seconds - run.checkpoints.back().seconds;
                c.pass_samples_per_pixel = spp - run.checkpoints.back().samples_per_pixel;
                c.pass_estimated_relative_mse = pass.estimated_relative_mse();
                if (comparison.reference) c.pass_relative_mse = relative_mse(pass.mean(), *comparison.reference);
            }
            previous = film.clone();
            run.checkpoints.push_back(c);
        };
        Progress progress(request.quiet, run.integrator);
        run.result = plan.integrator->render(scene, run_settings, progress);
        write_extra_images(run.result, run.integrator, 0.0f);  // a run's own images (--bdpt-strategies), one folder each
        // A pass that cannot be cut (one sample per pixel, a batch of splatted paths) can run past
        // the budget: then the comparison is not quite at equal time, and the report says so.
        if (comparison.equal_time && run.result.seconds > OvershootTolerance * request.time_seconds) {
            char text[160];
            std::snprintf(text, sizeof text, "ran %.2f s of its %g s budget (%+.0f%%): its errors are for that time",
                          run.result.seconds, request.time_seconds, 100.0 * (run.result.seconds / request.time_seconds - 1.0));
            run.result.warnings.push_back(text);
        }
        if (comparison.reference) {
            run.mse = mse(run.result.image, *comparison.reference);
            run.raw_relative_mse = relative_mse(run.result.image, *comparison.reference);
            run.relative_mse = less_reference_noise(run.raw_relative_mse, comparison.reference_relative_mse);
            run.ssim = ssim(run.result.image, *comparison.reference);
            run.mape = mape(run.result.image, *comparison.reference);
        } else {
            if (plan.sampler_name != "independent")
                run.result.warnings.push_back("its error is estimated from the per-pixel variance, which assumes independent "
                                              "samples; the " + plan.sampler_name +
                                              " sampler's are not, and its true error is usually lower: compare against a "
                                              "--reference to see it");
            run.relative_mse = run.result.estimated_relative_mse;
            run.error_is_estimated = true;
        }
        if (run.relative_mse > 0.0 && run.result.seconds > 0.0) run.efficiency = 1.0 / (run.relative_mse * run.result.seconds);
        // The final image is the last checkpoint: a time budget ends between pass boundaries.
        if (run.checkpoints.empty() || run.checkpoints.back().samples_per_pixel != run.result.samples_per_pixel) {
            Checkpoint last;
            last.seconds = run.result.seconds;
            last.samples_per_pixel = run.result.samples_per_pixel;
            last.estimated_relative_mse = run.result.estimated_relative_mse;
            if (comparison.reference) {
                last.mse = run.mse;
                last.relative_mse = run.raw_relative_mse;
            }
            if (previous && run.result.film && !run.checkpoints.empty() &&
                last.samples_per_pixel > run.checkpoints.back().samples_per_pixel) {
                const Film pass = samples_added(*run.result.film, *previous);
                last.pass_seconds = last.seconds - run.checkpoints.back().seconds;
                last.pass_samples_per_pixel = last.samples_per_pixel - run.checkpoints.back().samples_per_pixel;
                last.pass_estimated_relative_mse = pass.estimated_relative_mse();
                if (comparison.reference) last.pass_relative_mse = relative_mse(pass.mean(), *comparison.reference);
            }
            run.checkpoints.push_back(last);
        }
        run.fit = fit_convergence(run.checkpoints, comparison.reference_relative_mse);
        run.time_to_accuracy = times_to_accuracy(run.checkpoints, {1e-2, 1e-3}, comparison.reference_relative_mse);
        if (run.result.invalid_samples > 0 && !request.quiet)
            std::cerr << "warning: " << run.integrator << " produced " << run.result.invalid_samples
                      << " invalid (NaN, infinite or negative) samples\n";
        comparison.runs.push_back(std::move(run));
    }
    // END BOOK

    comparison.agreements = pairwise_agreements(comparison.runs);
    comparison.crops = request.crops;
    const int size = std::max(8, std::min(scene.camera->width(), scene.camera->height()) / 8);
    if (comparison.reference) {
        for (CropRegion& region : highest_error_regions(comparison.runs, *comparison.reference, size, 2))
            comparison.crops.push_back(region);
    } else if (comparison.runs.size() >= 2) {
        // Without a reference, where the runs differ most from their own mean: where at least one
        // of them is furthest from converged.
        Image mean(scene.camera->width(), scene.camera->height());
        for (const IntegratorRun& run : comparison.runs)
            for (std::size_t p = 0; p < mean.pixel_count(); ++p)
                mean[p] += run.result.image[p] / static_cast<float>(comparison.runs.size());
        for (CropRegion& region : highest_error_regions(comparison.runs, mean, size, 2)) {
            region.reason = "highest disagreement between the runs";
            comparison.crops.push_back(region);
        }
    }
    return comparison;
}

}  // namespace freezeray
