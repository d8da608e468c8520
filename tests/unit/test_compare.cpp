// The comparison tool: checkpoints, fits, times to accuracy, the report's agreement with the
// data, and bad input refused before anything is rendered or written.
#include "freezeray/comparison.hpp"
#include "freezeray/error.hpp"
#include "freezeray/metrics.hpp"

#include "test_scenes.hpp"

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>

using namespace freezeray;
using freezeray::testing::TemporaryFolder;

namespace {

// The furnace's exact image: radiance 1 everywhere.
std::string write_furnace_reference(const TemporaryFolder& folder, int width, int height) {
    const std::string path = folder.file("reference.exr");
    write_image(path, Image(width, height, Spectrum(1.0f)));
    return path;
}

CompareRequest furnace_request(const TemporaryFolder& folder) {
    CompareRequest request;
    request.scene = testing::scene_path("furnace/scene.json");
    request.integrators = {"pt-naive", "pt-is"};
    request.samples_per_pixel = 16;
    request.width = 8;
    request.height = 8;
    request.seed = 3;
    request.quiet = true;
    request.out_folder = folder.file("report");
    request.reference = write_furnace_reference(folder, 8, 8);
    return request;
}

std::vector<std::string> lines_of(const std::string& path) {
    std::ifstream in(path);
    std::vector<std::string> lines;
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

}  // namespace

TEST_CASE("a line through known points is fitted exactly, and times to accuracy follow it", "[unit][compare]") {
    // relMSE = 0.5 / t: slope -1, intercept log10(0.5).
    std::vector<Checkpoint> checkpoints;
    for (double t : {0.01, 0.1, 0.2, 0.4, 0.8, 1.6}) checkpoints.push_back({t, 1, -1.0, 0.5 / t, -1.0});
    const ConvergenceFit fit = fit_convergence(checkpoints);
    CHECK(fit.points == 5);  // the first checkpoint is left out
    CHECK(fit.slope == Approx(-1.0));
    CHECK(fit.predict(10.0) == Approx(0.05));
    const auto times = times_to_accuracy(checkpoints, fit, {1.0, 1e-2});
    CHECK(times[0].measured);  // 0.5 / 0.4 = 1.25 > 1 and 0.5 / 0.8 = 0.625 <= 1
    CHECK(times[0].seconds == Approx(0.5).epsilon(1e-6));  // interpolated between 0.4 and 0.8
    CHECK_FALSE(times[1].measured);
    CHECK(times[1].seconds == Approx(50.0));      // extrapolated: 0.5 / t = 0.01
}

TEST_CASE("compare renders every integrator with monotone checkpoints and consistent metrics", "[unit][compare]") {
    TemporaryFolder folder;
    const CompareRequest request = furnace_request(folder);
    const Comparison comparison = run_comparison(request, testing::full_registry());
    REQUIRE(comparison.runs.size() == 2u);
    REQUIRE(comparison.reference);
    for (const IntegratorRun& run : comparison.runs) {
        CHECK(run.result.samples_per_pixel == 16u);
        REQUIRE(run.checkpoints.size() == 5u);  // 1, 2, 4, 8, 16 spp
        for (std::size_t i = 1; i < run.checkpoints.size(); ++i) {
            CHECK(run.checkpoints[i].seconds >= run.checkpoints[i - 1].seconds);
            CHECK(run.checkpoints[i].samples_per_pixel == 2 * run.checkpoints[i - 1].samples_per_pixel);
        }
        // The last checkpoint is the final image.
        CHECK(run.checkpoints.back().relative_mse == Approx(run.relative_mse));
        CHECK(run.relative_mse == Approx(relative_mse(run.result.image, *comparison.reference)));
        CHECK(run.efficiency == Approx(1.0 / (run.relative_mse * run.result.seconds)));
        CHECK(run.ssim <= 1.0);
    }
}

TEST_CASE("the report's CSV and table agree with the runs", "[unit][compare]") {
    TemporaryFolder folder;
    const CompareRequest request = furnace_request(folder);
    const Comparison comparison = run_comparison(request, testing::full_registry());
    write_comparison_report(comparison, request.out_folder);
    for (const char* file : {"report.html", "report.md", "convergence.csv"})
        CHECK(std::filesystem::exists(request.out_folder + "/" + file));

    const auto csv = lines_of(request.out_folder + "/convergence.csv");
    std::size_t checkpoints = 0;
    for (const IntegratorRun& run : comparison.runs) checkpoints += run.checkpoints.size();
    REQUIRE(csv.size() == checkpoints + 1);  // a header and one row per checkpoint
    // Every run's last CSV row carries its final relMSE.
    for (const IntegratorRun& run : comparison.runs) {
        std::string last;
        for (const std::string& line : csv)
            if (line.rfind(run.integrator + ",", 0) == 0) last = line;
        std::vector<std::string> fields;
        std::stringstream stream(last);
        for (std::string field; std::getline(stream, field, ',');) fields.push_back(field);
        REQUIRE(fields.size() >= 6u);
        CHECK(std::stod(fields[5]) == Approx(run.relative_mse).epsilon(1e-6));
    }
    // The markdown table names every integrator.
    std::ifstream md(request.out_folder + "/report.md");
    const std::string text((std::istreambuf_iterator<char>(md)), std::istreambuf_iterator<char>());
    for (const IntegratorRun& run : comparison.runs) CHECK_THAT(text, Catch::Contains(run.integrator));
}

TEST_CASE("compare refuses bad input before rendering and writes nothing", "[unit][compare]") {
    TemporaryFolder folder;
    auto refused = [&](CompareRequest request, const std::string& expected) {
        try {
            run_comparison(request, testing::full_registry());
            FAIL("no error for " << expected);
        } catch (const InputError& e) {
            CHECK_THAT(e.what(), Catch::Contains(expected));
        }
        CHECK_FALSE(std::filesystem::exists(request.out_folder));
    };
    CompareRequest unknown = furnace_request(folder);
    unknown.integrators = {"pt-naive", "pt-nothing"};
    refused(unknown, "pt-nothing");

    CompareRequest wrong_size = furnace_request(folder);
    wrong_size.width = 16;
    refused(wrong_size, "reference.exr");

    CompareRequest unreadable = furnace_request(folder);
    std::ofstream(folder.file("broken.exr")) << "not an image";
    unreadable.reference = folder.file("broken.exr");
    refused(unreadable, "broken.exr");

    CompareRequest nowhere = furnace_request(folder);
    nowhere.out_folder = folder.file("no/such/place/report");
    refused(nowhere, "does not exist");
}
