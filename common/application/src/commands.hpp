// The commands of the command line (cli.cpp parses, these run). Private to the application and the laboratory.
#pragma once

#include "freezeray/registry.hpp"

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace freezeray {

// Options of `render`, as typed (checked in render_command.cpp, with messages naming the option).
struct RenderOptions {
    std::string scene;
    std::string integrator;
    long long spp = 0;
    bool spp_given = false;
    double time_seconds = 0.0;
    double target_error = 0.0;
    std::string accelerator;  // empty: the scene's, else the renderer's default
    std::string sampler;      // empty: the scene's, else the renderer's default
    std::string light_sampler;  // empty: the scene's, else the renderer's default
    int threads = 0;
    long long seed = -1;
    long long sample_offset = 0;
    int max_depth = -1;
    int width = 0;
    int height = 0;
    std::string out;
    float exposure = 0.0f;
    double checkpoint_seconds = 0.0;
    std::string resume;
    OptionValues chapter_options;  // the options the chapters declared (options.hpp)
    bool quiet = false;
};

// `render`: returns the exit status (0, or 128 + signal when interrupted).
int run_render(const RenderOptions& options, const Registry& registry);

// `merge OUT INPUT...`: combines renders of one scene made from disjoint samples.
int run_merge(const std::string& out, const std::vector<std::string>& inputs, bool quiet);

class Image;
// A number from an image's header, such as "freezeray:estimated_relative_mse" (negative when it is
// absent or not a number). Defined in compare.cpp.
double header_number(const Image& image, const std::string& key);

struct CompareRequest;
// `compare --make-reference OUT`: renders the reference for a comparison of request's scene, with
// its one integrator and budget (time, samples or target_error), under reference_seed(request.seed).
int run_make_reference(const CompareRequest& request, double target_error, const std::string& out, const Registry& registry);

class Scene;
class Integrator;

// The sampler of a render: `requested` (the command line's, given at `where`), else the scene's,
// else the renderer's default. A sampler that was named but that the integrator does not draw
// from is refused (InputError); the default is then replaced by independent, which is what such
// an integrator's own streams are.
struct SamplerChoice {
    std::string name;
    std::shared_ptr<const Sampler> sampler;
};
SamplerChoice choose_sampler(const std::string& requested, const std::string& where, const Scene& scene,
                             const IntegratorTraits& integrator, const std::string& integrator_name, const Registry& registry);

// The light sampler a render names: the command line's (`requested`), else the scene's, else the
// renderer's default (empty before chapter 03).
std::string light_sampler_name(const std::string& requested, const Scene& scene, const Registry& registry);

// The light sampler of a render, chosen as the sampler is and built over the scene's lights: a
// named one is refused (InputError at `where`) for an integrator that does not choose lights at
// shading points; for such an integrator, without a name, none (empty name, null sampler).
struct LightSamplerChoice {
    std::string name;
    std::shared_ptr<const LightSampler> sampler;
};
LightSamplerChoice choose_light_sampler(const std::string& requested, const std::string& where, const Scene& scene,
                                        const IntegratorTraits& integrator, const std::string& integrator_name,
                                        const Registry& registry);

// A warning for an integrator that cannot find the scene's point, spot and directional lights
// (no ray can hit them), or an empty string.
std::string unreachable_lights_warning(const Scene& scene, const IntegratorTraits& integrator, const std::string& name);

}  // namespace freezeray
