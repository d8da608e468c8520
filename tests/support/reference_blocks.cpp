// Comparing an assignment's renders with the solution's, block by block (reference_blocks.hpp).
#include "reference_blocks.hpp"

#include "evidence.hpp"
#include "statistics.hpp"
#include "test_scenes.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <vector>

namespace freezeray::testing {

namespace {

// The mean of each block of pixels, per channel: blocks in row order from the top left.
std::vector<Spectrum> block_means(const Image& image, int blocks_x, int blocks_y) {
    const int w = image.width() / blocks_x, h = image.height() / blocks_y;
    std::vector<Spectrum> means;
    for (int j = 0; j < blocks_y; ++j)
        for (int i = 0; i < blocks_x; ++i) {
            double sum[3] = {0.0, 0.0, 0.0};
            for (int y = j * h; y < (j + 1) * h; ++y)
                for (int x = i * w; x < (i + 1) * w; ++x)
                    for (int c = 0; c < 3; ++c) sum[c] += image.at(x, y)[c];
            const double n = static_cast<double>(w) * h;
            means.emplace_back(static_cast<float>(sum[0] / n), static_cast<float>(sum[1] / n),
                               static_cast<float>(sum[2] / n));
        }
    return means;
}

std::string reference_path(const std::string& assignment) {
    std::string file = assignment;
    for (char& c : file)
        if (c == '/') c = '-';
    return test_data_path("references/" + file + ".json");
}

// One test: the mean of the student's batches against the reference's mean and standard error
// (from its own batches, reference_batches - 1 degrees of freedom), by Welch's t-test.
struct MeanComparison {
    stats::MeanEstimate mine, solution;
    double p_value;
    double t() const {
        const double spread = std::sqrt(mine.variance_of_mean + solution.variance_of_mean);
        return spread > 0.0 ? (mine.mean - solution.mean) / spread : 0.0;
    }
};

MeanComparison compare_means(const std::vector<double>& batch_means, double reference_mean, double reference_error,
                             double reference_batches) {
    MeanComparison comparison{stats::estimate_mean(batch_means),
                              {reference_mean, reference_error * reference_error, reference_batches - 1.0},
                              0.0};
    comparison.p_value = stats::welch_p_value(comparison.mine, comparison.solution);
    return comparison;
}

// The failing tests: how many, and the words for the one with the lowest p-value.
struct Failures {
    std::size_t count = 0;
    double worst_p = 2.0;
    std::string worst;

    void add(const MeanComparison& comparison, const std::string& what) {
        ++count;
        if (comparison.p_value >= worst_p) return;
        worst_p = comparison.p_value;
        char numbers[200];
        std::snprintf(numbers, sizeof numbers, ": %.4g against the solution's %.4g +- %.2g (%+.1f %%, p = %.2g)",
                      comparison.mine.mean, comparison.solution.mean, std::sqrt(comparison.solution.variance_of_mean),
                      100.0 * (comparison.mine.mean / comparison.solution.mean - 1.0), comparison.p_value);
        worst = what + numbers;
    }
};

}  // namespace

ReferenceComparison compare_with_reference(const std::string& assignment, int batches, std::uint64_t spp_per_batch,
                                           std::uint64_t first_seed, double alpha) {
    const std::string path = reference_path(assignment);
    std::ifstream file(path);
    if (!file) return {false, path + " is missing: make it with tests/grading/make_references.py --blocks", ""};
    const nlohmann::json reference = nlohmann::json::parse(file);
    const std::uint64_t reference_seed = reference.at("seed").get<std::uint64_t>();
    const std::uint64_t reference_batch_count = reference.at("batches").get<std::uint64_t>();
    if (first_seed < reference_seed + reference_batch_count && reference_seed < first_seed + batches)
        return {false, "the test's seeds overlap the reference's: they must be independent", ""};

    std::size_t tests = 0;  // every block and channel, and the whole image's channels
    for (const auto& view : reference.at("views")) tests += 3 * (view.at("mean").size() + 1);
    const double alpha_each = stats::sidak_alpha(alpha, tests);

    ReferenceComparison result{true, "", ""};
    Failures failures;
    const double reference_batches = static_cast<double>(reference.at("batches").get<std::uint64_t>());
    int view_number = 0;
    for (const auto& view : reference.at("views")) {
        ++view_number;
        const int blocks_x = view.at("blocks")[0].get<int>(), blocks_y = view.at("blocks")[1].get<int>();
        TestRender request;
        request.scene = std::string(FREEZERAY_SOURCE_DIR) + "/" + view.at("scene").get<std::string>();
        request.integrator = view.at("integrator").get<std::string>();
        request.width = view.at("width").get<int>();
        request.height = view.at("height").get<int>();
        request.max_depth = view.value("max_depth", 0);  // 0: the scene's, else the integrator's
        request.samples_per_pixel = spp_per_batch;
        // What chapters 01 to 05 render with (the references were made with their renderers): brute
        // force (the KD-tree is chapter 06's exercise) and textures read as chapter 02 reads them
        // (chapter 08's tiles and MIP maps are its exercises).
        request.accelerator = "bruteforce";
        request.texture_settings = {{"layout", "linear"}, {"filter", "bilinear"}};
        const std::string where = "view " + std::to_string(view_number) + " (" + view.at("scene").get<std::string>() +
                                  ", " + request.integrator + "), ";

        std::vector<std::vector<Spectrum>> per_batch;  // each batch's block means
        Image render_mean(request.width, request.height);  // the mean of the batches, for the evidence
        std::uint64_t invalid = 0;
        for (int b = 0; b < batches; ++b) {
            request.seed = first_seed + static_cast<std::uint64_t>(b);
            const RenderResult rendered = render(request);
            invalid += rendered.invalid_samples;
            per_batch.push_back(block_means(rendered.image, blocks_x, blocks_y));
            for (std::size_t i = 0; i < render_mean.pixel_count(); ++i)
                render_mean[i] += rendered.image[i] / static_cast<float>(batches);
        }
        if (invalid != 0)
            return {false, where + std::to_string(invalid) + " samples were NaN, Inf or negative", ""};

        const std::size_t failing_before = failures.count;
        // The whole image: a small bias everywhere hides in each block's noise, not here.
        for (int c = 0; c < 3; ++c) {
            std::vector<double> values;
            for (const auto& batch : per_batch) {
                double sum = 0.0;
                for (const Spectrum& block : batch) sum += block[c];
                values.push_back(sum / static_cast<double>(batch.size()));
            }
            const MeanComparison comparison =
                compare_means(values, view.at("image_mean")[c].get<double>(),
                              view.at("image_standard_error")[c].get<double>(), reference_batches);
            if (comparison.p_value <= alpha_each)
                failures.add(comparison, where + "the whole image, channel " + "rgb"[c]);
        }
        // Each block, kept for the evidence too (one pixel per block).
        Image mine_blocks(blocks_x, blocks_y), reference_blocks(blocks_x, blocks_y), t_statistics(blocks_x, blocks_y);
        const auto& means = view.at("mean");
        const auto& errors = view.at("standard_error");
        for (std::size_t block = 0; block < means.size(); ++block)
            for (int c = 0; c < 3; ++c) {
                std::vector<double> values;
                for (const auto& batch : per_batch) values.push_back(batch[block][c]);
                const MeanComparison comparison =
                    compare_means(values, means[block][c].get<double>(), errors[block][c].get<double>(), reference_batches);
                const int bx = static_cast<int>(block) % blocks_x, by = static_cast<int>(block) / blocks_x;
                mine_blocks.at(bx, by)[c] = static_cast<float>(comparison.mine.mean);
                reference_blocks.at(bx, by)[c] = static_cast<float>(comparison.solution.mean);
                t_statistics.at(bx, by)[c] = static_cast<float>(comparison.t());
                if (comparison.p_value <= alpha_each)
                    failures.add(comparison, where + "block (" + std::to_string(bx) + ", " + std::to_string(by) +
                                                 ") of " + std::to_string(blocks_x) + "x" + std::to_string(blocks_y) +
                                                 ", channel " + "rgb"[c]);
            }
        if (failures.count != failing_before && result.evidence.empty())
            result.evidence = "evidence: " + stats::write_evidence(
                                                 assignment,
                                                 {{"mine", render_mean},
                                                  {"mine-blocks", mine_blocks},
                                                  {"reference-blocks", reference_blocks},
                                                  {"t", t_statistics}},
                                                 where + "your render (the mean of the batches), its block means, "
                                                         "the solution's, and the t statistic of each block");
    }
    char summary[200];
    if (failures.count != 0) {
        std::snprintf(summary, sizeof summary,
                      "the render differs from the solution's in %zu of %zu tests (blocks and the whole image, per "
                      "channel); the worst: ",
                      failures.count, tests);
        result.passed = false;
        result.message = summary + failures.worst;
    } else {
        std::snprintf(summary, sizeof summary,
                      "%zu tests (blocks and the whole image, per channel) match the solution's, each at "
                      "false-failure rate %.2g",
                      tests, alpha_each);
        result.message = summary;
    }
    return result;
}

}  // namespace freezeray::testing
