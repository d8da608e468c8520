// The commands of the command line (cli.cpp parses, these run). Private to the application and the laboratory.
#pragma once

#include "freezeray/capability_choice.hpp"
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
    Selections selections;    // --accel, --sampler, ...: what is not given is the scene's, else the default
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

// Writes the images an integrator made besides the estimate (RenderResult::extra_images) into the
// folder its option named, or into `subfolder` of it (compare: one per run).
void write_extra_images(const RenderResult& result, const std::string& subfolder, float exposure);

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

}  // namespace freezeray
