// The `merge` command: one image from renders of the same scene made from disjoint samples
// (different seeds, or different --sample-offset ranges of one seed), on one machine or many.
#include "commands.hpp"

#include "freezeray/error.hpp"
#include "freezeray/image.hpp"
#include "freezeray/render_state.hpp"

#include <iostream>

namespace freezeray {

namespace {

// A render to merge: a state file (exact) or an image whose metadata gives its sample count.
struct MergeInput {
    Film film;
    std::string scene, integrator;
};

MergeInput read_merge_input(const std::string& path) {
    if (path.size() > 6 && path.compare(path.size() - 6, 6, ".state") == 0) {
        const RenderState state = read_render_state(path);
        return {state.film->clone(), state.info.scene, state.info.integrator};
    }
    const Image image = read_image(path);
    const auto spp = image.metadata.find("freezeray:samples_per_pixel");
    if (spp == image.metadata.end())
        throw InputError(path, "has no sample count (merge needs EXR files written by render, or .state files)");
    std::uint64_t samples = 0;
    try {
        samples = std::stoull(spp->second);
    } catch (const std::exception&) {
        throw InputError(path, "its sample count '" + spp->second + "' is not a number");
    }
    if (samples == 0) throw InputError(path, "has no samples");
    auto field = [&](const char* key) {
        const auto it = image.metadata.find(key);
        return it == image.metadata.end() ? std::string() : it->second;
    };
    return {Film::from_images(image, Image(), samples), field("freezeray:scene"), field("freezeray:integrator")};
}

}  // namespace

// BOOK(merge)
int run_merge(const std::string& out, const std::vector<std::string>& inputs, bool quiet) {
    if (inputs.size() < 2) throw InputError("merge", "give at least two renders to merge");
    check_image_writable(out);
    MergeInput merged = read_merge_input(inputs[0]);
    for (std::size_t i = 1; i < inputs.size(); ++i) {
        MergeInput next = read_merge_input(inputs[i]);
        if (next.scene != merged.scene || next.integrator != merged.integrator)
            throw InputError(inputs[i], "is a render of " + next.scene + " by " + next.integrator + ", not of " +
                                            merged.scene + " by " + merged.integrator);
        // Means weighted by sample counts; variances combined exactly (Chan et al. 1979).
        merged.film = merge_films(merged.film, next.film);
    }
    Image image = merged.film.mean();
    image.metadata["freezeray:scene"] = merged.scene;
    image.metadata["freezeray:integrator"] = merged.integrator;
    image.metadata["freezeray:samples_per_pixel"] = std::to_string(merged.film.minimum_sample_count());
    image.metadata["freezeray:merged_from"] = std::to_string(inputs.size());
    write_image(out, image);
    if (!quiet)
        std::cerr << "merged " << inputs.size() << " renders: " << merged.film.minimum_sample_count()
                  << " spp in every pixel\n";
    std::cout << out << "\n";
    return 0;
}
// END BOOK

}  // namespace freezeray
