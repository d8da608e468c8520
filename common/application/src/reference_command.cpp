// `compare --make-reference FILE`: renders the reference a comparison is measured against. A
// reference is a render like any other, with noise of its own; it is fit for the job when that
// noise is independent of the runs' (another seed) and small beside the errors it measures
// (ReferenceMargin times smaller, comparison.hpp). This command takes care of the first and
// reports the second, so that the reader of a report can check both.
#include "commands.hpp"

#include "freezeray/comparison.hpp"
#include "freezeray/error.hpp"
#include "freezeray/image.hpp"

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <limits>

namespace freezeray {

std::uint64_t reference_seed(std::uint64_t comparison_seed) {
    // Any constant changes the low bits; clearing the top bit keeps the seed a valid --seed. The
    // result differs from comparison_seed for every comparison_seed: below 2^63 the low bits
    // differ, from 2^63 on the top bit does.
    constexpr std::uint64_t Mix = 0x1e3779b97f4a7c15ull;
    return (comparison_seed ^ Mix) & static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max());
}

int run_make_reference(const CompareRequest& request, double target_error, const std::string& out, const Registry& registry) {
    if (request.integrators.size() != 1)
        throw InputError("--integrators", "--make-reference renders with one integrator; " +
                                              std::to_string(request.integrators.size()) +
                                              " are named (choose an unbiased one that handles the scene's light paths well)");
    if (request.time_seconds <= 0.0 && request.samples_per_pixel == 0 && target_error <= 0.0)
        throw InputError("--time/--spp/--target-error",
                         "give the reference a budget: --time, --spp, or --target-error (its estimated relMSE)");
    if (!request.reference.empty())
        throw InputError("--reference", "--make-reference makes a reference; it does not take one");
    if (!request.out_folder.empty())
        throw InputError("--out", "--make-reference writes only the reference image (give it as --make-reference FILE)");
    if (!request.crops.empty()) throw InputError("--crop", "crops belong to a comparison, not to --make-reference");
    // Only EXR keeps the header (seed, samples, estimated relMSE) by which compare checks it.
    const std::string extension = std::filesystem::path(out).extension().string();
    if (extension != ".exr")
        throw InputError(out, "a reference must be an OpenEXR file (.exr): only its header keeps the seed and the "
                              "estimated relMSE that compare checks");

    RenderOptions render;
    render.scene = request.scene;
    // A reference's samples must be independent: compare checks its estimated relMSE (from the
    // per-pixel variance, which assumes them) and subtracts it from the runs' errors.
    const RunName run = parse_run_name(request.integrators.front(), registry);
    const auto own_sampler = run.named.find(CapabilityKind::Sampler);
    const auto given_sampler = request.selections.find(CapabilityKind::Sampler);
    const std::string named_sampler = own_sampler != run.named.end()        ? own_sampler->second
                                      : given_sampler != request.selections.end() ? given_sampler->second
                                                                                  : "";
    if (!named_sampler.empty() && named_sampler != "independent")
        throw InputError(own_sampler != run.named.end() ? "--integrators" : "--sampler",
                         "a reference is rendered with independent samples: its estimated relMSE, which compare checks "
                         "and subtracts from the runs' errors, assumes them (the " + named_sampler + " sampler's are not)");
    render.integrator = run.integrator;
    render.selections = request.selections;
    for (const auto& [kind, name] : run.named) render.selections[kind] = name;  // the run's own, over the command line's
    render.selections[CapabilityKind::Sampler] = "independent";
    render.chapter_options = request.options;
    render.time_seconds = request.time_seconds;
    render.spp = static_cast<long long>(request.samples_per_pixel);
    render.spp_given = request.samples_per_pixel > 0;
    render.target_error = target_error;
    render.threads = request.threads;
    render.seed = static_cast<long long>(reference_seed(request.seed));
    render.max_depth = request.max_depth > 0 ? request.max_depth : -1;
    render.width = request.width;
    render.height = request.height;
    render.out = out;
    render.quiet = request.quiet;
    const int status = run_render(render, registry);
    if (status != 0) return status;

    // What the reference is good for, from its own header.
    const double own = header_number(read_image(out), "freezeray:estimated_relative_mse");
    if (own > 0.0) {
        std::fprintf(stderr,
                     "reference: %s, seed %llu (the comparison's is %llu), estimated relMSE %.3g: it measures errors "
                     "down to %.3g; use it with compare --reference %s%s\n",
                     out.c_str(), static_cast<unsigned long long>(render.seed), static_cast<unsigned long long>(request.seed),
                     own, reference_floor(own), out.c_str(),
                     request.seed != 0 ? (" --seed " + std::to_string(request.seed)).c_str() : "");
    } else {
        std::fprintf(stderr,
                     "warning: %s has no estimated relMSE (%s keeps no per-pixel variance): compare cannot tell how "
                     "small an error it can measure; render the reference with a per-pixel integrator\n",
                     out.c_str(), render.integrator.c_str());
    }
    return 0;
}

}  // namespace freezeray
