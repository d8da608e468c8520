// The comparison tool: checkpoints, fits, times to accuracy, the report's agreement with the
// data, and bad input refused before anything is rendered or written.
#include "freezeray/comparison.hpp"
#include "freezeray/error.hpp"
#include "freezeray/metrics.hpp"
#include "freezeray/random.hpp"

#include "test_scenes.hpp"

#include <catch2/catch.hpp>

#include <filesystem>
#include <cmath>
#include <fstream>
#include <functional>
#include <map>
#include <random>
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

namespace {

// Gives each checkpoint after the first the pass that ended there, with the error a render of
// the pass's duration has: error(pass seconds).
void add_passes(std::vector<Checkpoint>& checkpoints, const std::function<double(double)>& error) {
    for (std::size_t i = 1; i < checkpoints.size(); ++i) {
        Checkpoint& c = checkpoints[i];
        c.pass_seconds = c.seconds - checkpoints[i - 1].seconds;
        c.pass_samples_per_pixel = c.samples_per_pixel - checkpoints[i - 1].samples_per_pixel;
        c.pass_relative_mse = error(c.pass_seconds);
    }
}

// Checkpoints at 1, 2, 4, ... 2^(n-1) seconds with relMSE error(t), measured against a reference,
// and their passes.
std::vector<Checkpoint> series(int n, const std::function<double(double)>& error) {
    std::vector<Checkpoint> checkpoints;
    for (int i = 0; i < n; ++i) {
        const double t = std::ldexp(1.0, i);
        checkpoints.push_back({t, std::uint64_t(1) << i, -1.0, error(t), -1.0});
    }
    add_passes(checkpoints, error);
    return checkpoints;
}

}  // namespace

TEST_CASE("a clean 1/t series is fitted exactly, with -1 in its interval, and times follow it", "[unit][compare]") {
    // relMSE = 0.5 / t: slope -1, intercept log10(0.5).
    std::vector<Checkpoint> checkpoints;
    for (double t : {0.01, 0.1, 0.2, 0.4, 0.8, 1.6}) checkpoints.push_back({t, 1, -1.0, 0.5 / t, -1.0});
    add_passes(checkpoints, [](double t) { return 0.5 / t; });
    const ConvergenceFit fit = fit_convergence(checkpoints);
    CHECK(fit.points == 5);  // the first checkpoint has no pass before it
    CHECK(fit.from_passes);
    CHECK(fit.slope == Approx(-1.0));
    CHECK(fit.slope_low == Approx(-1.0));  // every pairwise slope is -1
    CHECK(fit.slope_high == Approx(-1.0));
    CHECK_FALSE(fit.has_interval());  // 5 passes: an interval needs 6, fewer give one too wide to mean anything
    CHECK_FALSE(fit.agrees_with_unbiased_rate());
    CHECK(fit.predict(10.0) == Approx(0.05));
    const auto times = times_to_accuracy(checkpoints, {1.0, 1e-2, 1e-3});
    CHECK(times[0].measured);  // 0.5 / 0.4 = 1.25 > 1 and 0.5 / 0.8 = 0.625 <= 1
    CHECK(times[0].seconds == Approx(0.5).epsilon(1e-6));  // interpolated between 0.4 and 0.8
    CHECK_FALSE(times[1].measured);
    CHECK(times[1].seconds == Approx(50.0));  // along slope -1: 0.5 / t = 0.01
    CHECK(times[1].beyond_limit);             // 50 s is more than 10 x the run's 1.6 s
    CHECK(times[2].seconds == Approx(500.0)); // kept as a number, for the CSV
    CHECK(times[2].beyond_limit);
}

TEST_CASE("a time read along slope -1 within ten times the run is a number, beyond it is not", "[unit][compare]") {
    // 0.08 / t at 1 ... 32 s reaches 0.0025 at 32 s; 1e-3 needs 80 s (2.5 x the run), 1e-4 800 s (25 x).
    const auto times = times_to_accuracy(series(6, [](double t) { return 0.08 / t; }), {1e-3, 1e-4});
    CHECK_FALSE(times[0].measured);
    CHECK(times[0].seconds == Approx(80.0));
    CHECK_FALSE(times[0].beyond_limit);
    CHECK(times[1].seconds == Approx(800.0));
    CHECK(times[1].beyond_limit);
}

TEST_CASE("a time to accuracy is read forward from where the run ended, never before it", "[unit][compare]") {
    // Early passes converge faster than the run goes on (start-up, the first bounces found
    // quickly): 0.02 / t up to 1 s, then the error flattens to 0.087 at 10 s. Read along a line
    // through all the checkpoints, 0.01 came out "reached in 9.7 s" though the run was at 0.087 at
    // 10 s; from the end along the run's own slope it lies beyond 10 s.
    std::vector<Checkpoint> checkpoints;
    for (double t : {0.125, 0.25, 0.5, 1.0}) checkpoints.push_back({t, 1, -1.0, 0.02 / t, -1.0});
    for (double t : {2.0, 4.0, 10.0}) checkpoints.push_back({t, 1, -1.0, 0.087 * std::pow(10.0 / t, 0.5), -1.0});
    const auto times = times_to_accuracy(checkpoints, {1e-2});
    CHECK_FALSE(times[0].measured);
    CHECK(times[0].seconds > 10.0);
    // An error that does not fall is never said to reach a target.
    const auto rising = times_to_accuracy(series(7, [](double t) { return 0.02 * std::pow(t, 0.3); }), {1e-3});
    CHECK_FALSE(std::isfinite(rising[0].seconds));
    CHECK(rising[0].beyond_limit);
}

TEST_CASE("one firefly does not move the robust fit, which least squares would tilt", "[unit][compare]") {
    // 1/t, but the checkpoint at 32 s caught a firefly that multiplies its error by 8.
    auto checkpoints = series(8, [](double t) { return 1.0 / t; });
    checkpoints[5].relative_mse *= 8.0;
    checkpoints[5].pass_relative_mse *= 8.0;  // the pass that found it
    const ConvergenceFit fit = fit_convergence(checkpoints);
    REQUIRE(fit.points == 7);
    CHECK(fit.slope == Approx(-1.0));  // 15 of the 21 pairwise slopes are exactly -1
    CHECK(fit.agrees_with_unbiased_rate());
    // The least-squares slope through the same points, for contrast: noticeably flatter.
    std::vector<double> x, y;
    for (std::size_t i = 1; i < checkpoints.size(); ++i) {
        x.push_back(std::log10(checkpoints[i].seconds));
        y.push_back(std::log10(checkpoints[i].relative_mse));
    }
    CHECK(fit_line(x, y).slope > -0.95);  // -1 + 3 (5 - 4) / 28 = -0.89 in units of log10 2
    // The time to 1e-3 along slope -1 is placed by the median: the firefly does not move it either.
    const auto times = times_to_accuracy(checkpoints, {1e-3});
    CHECK(times[0].seconds == Approx(1000.0));
}

TEST_CASE("a rising error is fitted with a positive slope and flagged as not the unbiased rate", "[unit][compare]") {
    // An estimate that grows as rare bright paths are found: 0.02 t^0.3.
    const ConvergenceFit fit = fit_convergence(series(7, [](double t) { return 0.02 * std::pow(t, 0.3); }));
    REQUIRE(fit.points == 6);
    CHECK(fit.slope == Approx(0.3));
    CHECK(fit.slope_low > -1.0);
    CHECK_FALSE(fit.agrees_with_unbiased_rate());
}

TEST_CASE("too few checkpoints, or too short a span of time, give no fit and say why", "[unit][compare]") {
    const auto two = fit_convergence(series(3, [](double t) { return 1.0 / t; }));  // the first is left out
    CHECK(two.points == 0);
    CHECK(two.no_fit_reason == "2 checkpoints, 4 needed");
    CHECK_FALSE(two.agrees_with_unbiased_rate());
    std::vector<Checkpoint> short_span;
    for (double t : {1.0, 1.5, 2.0, 2.5, 3.0, 3.5}) short_span.push_back({t, 1, -1.0, 1.0 / t, -1.0});
    const auto close = fit_convergence(short_span);
    CHECK(close.points == 0);
    CHECK(close.no_fit_reason == "checkpoints span 2.3x in time, 4x needed");
    // Cumulative checkpoints without their passes: a slope, but no interval to test it with.
    std::vector<Checkpoint> cumulative;
    for (int i = 0; i < 6; ++i) cumulative.push_back({std::ldexp(1.0, i), 1, -1.0, std::ldexp(1.0, -i), -1.0});
    const auto unpassed = fit_convergence(cumulative);
    CHECK(unpassed.points == 5);
    CHECK(unpassed.slope == Approx(-1.0));
    CHECK_FALSE(unpassed.has_interval());
    CHECK_FALSE(unpassed.agrees_with_unbiased_rate());
    CHECK_FALSE(unpassed.disagrees_with_unbiased_rate());
    // Times to accuracy still read along slope -1 from what there is.
    const auto times = times_to_accuracy(short_span, {0.1});
    CHECK(times[0].seconds == Approx(10.0));
    CHECK_FALSE(times[0].beyond_limit);  // 10 s is within 10 x the run's 3.5 s
}

namespace {

// A render simulated exactly: `pixels` pixels whose samples are exponential with means 0.5 ... 2,
// averaged at checkpoints of 1, 2, 4, ... 2^(passes - 1) samples per pixel, one millisecond a
// sample; relMSE against the exact means, for each cumulative image and each pass's samples alone.
std::vector<Checkpoint> simulated_run(std::uint64_t seed, int pixels, int passes) {
    PCG32 random(seed, 17);
    std::vector<double> sums(static_cast<std::size_t>(pixels), 0.0), previous(sums);
    std::vector<Checkpoint> checkpoints;
    std::uint64_t done = 0;
    for (int k = 0; k < passes; ++k) {
        const std::uint64_t target = std::uint64_t(1) << k;
        double cumulative = 0.0, pass = 0.0;
        for (int p = 0; p < pixels; ++p) {
            const double mean = 0.5 + 0.5 * (p % 4);
            double& sum = sums[static_cast<std::size_t>(p)];
            for (std::uint64_t s = done; s < target; ++s) sum -= mean * std::log(1.0 - random.next_double());
            const double weight = 1.0 / (mean * mean + RelativeMseEpsilon);
            const double x = sum / double(target);
            cumulative += weight * (x - mean) * (x - mean) / pixels;
            const double y = (sum - previous[static_cast<std::size_t>(p)]) / double(target - done);
            pass += weight * (y - mean) * (y - mean) / pixels;
            previous[static_cast<std::size_t>(p)] = sum;
        }
        Checkpoint c{1e-3 * double(target), target, -1.0, cumulative, -1.0};
        if (k > 0) {
            c.pass_seconds = 1e-3 * double(target - done);
            c.pass_samples_per_pixel = target - done;
            c.pass_relative_mse = pass;
        }
        checkpoints.push_back(c);
        done = target;
    }
    return checkpoints;
}

}  // namespace

TEST_CASE("the slope's interval, fitted to independent passes, covers -1 about 95 % of the time", "[unit][compare]") {
    // 400 simulated unbiased renders (64 pixels, 1 ... 1024 spp), whose true slope is -1. Were
    // Sen's interval exact, the count covering -1 would be binomial(400, 0.95): mean 380, standard
    // deviation 4.4, so fewer than 352 (88 %) has probability below 1e-9 (the passes give 382).
    // The same fit fed with the cumulative checkpoints as if they were independent (what an
    // earlier version did) fails that criterion (315 of 400, 79 %): their errors are correlated,
    // each image holding the samples of the one before, so they lie too smoothly on their curve
    // and the interval is too narrow.
    constexpr int Trials = 400;
    int covered = 0, covered_cumulative = 0;
    for (int trial = 0; trial < Trials; ++trial) {
        const std::vector<Checkpoint> run = simulated_run(1000 + trial, 64, 11);
        const ConvergenceFit fit = fit_convergence(run);
        REQUIRE(fit.from_passes);
        REQUIRE(fit.points == 10);
        covered += fit.agrees_with_unbiased_rate();
        std::vector<Checkpoint> as_passes = run;
        for (std::size_t i = 1; i < as_passes.size(); ++i) {
            as_passes[i].pass_seconds = as_passes[i].seconds;
            as_passes[i].pass_relative_mse = as_passes[i].relative_mse;
        }
        covered_cumulative += fit_convergence(as_passes).agrees_with_unbiased_rate();
    }
    INFO("passes cover -1 in " << covered << " of " << Trials << ", cumulative checkpoints in " << covered_cumulative);
    CHECK(covered >= 352);
    CHECK(covered_cumulative < 352);
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

TEST_CASE("with a time budget too, the last checkpoint is the final image", "[unit][compare]") {
    TemporaryFolder folder;
    CompareRequest request = furnace_request(folder);
    request.integrators = {"pt-mis", "bdpt"};  // a per-pixel integrator and a splatting one
    request.samples_per_pixel = 0;
    request.time_seconds = 0.3;
    const Comparison comparison = run_comparison(request, testing::full_registry());
    for (const IntegratorRun& run : comparison.runs) {
        INFO(run.integrator);
        REQUIRE_FALSE(run.checkpoints.empty());
        const Checkpoint& last = run.checkpoints.back();
        CHECK(last.samples_per_pixel == run.result.samples_per_pixel);
        CHECK(last.relative_mse == Approx(run.relative_mse));
        CHECK(last.estimated_relative_mse == Approx(run.result.estimated_relative_mse));
        CHECK(last.seconds <= run.result.seconds);
    }
    // The times file: one row per run and target, as the report's table.
    write_comparison_report(comparison, request.out_folder);
    const auto times = lines_of(request.out_folder + "/time_to_accuracy.csv");
    REQUIRE(times.size() == 1 + 2 * comparison.runs.size());
    CHECK(times[0] == "integrator,target_relative_mse,seconds,how");
}

TEST_CASE("a run that overshoots its time budget says so", "[unit][compare]") {
    // One pass (one sample in each of 128 x 128 pixels of the Cornell box) cannot be cut, and takes
    // far longer than a budget of a millisecond.
    TemporaryFolder folder;
    CompareRequest request;
    request.scene = testing::scene_path("cornell-box/scene.json");
    request.integrators = {"pt-mis"};
    request.time_seconds = 0.001;
    request.width = request.height = 128;
    request.selections[CapabilityKind::Sampler] = "independent";  // the course's default (sobol) would add its own warning
    request.quiet = true;
    request.out_folder = folder.file("report");
    const Comparison comparison = run_comparison(request, testing::full_registry());
    const RenderResult& result = comparison.runs[0].result;
    REQUIRE(result.seconds > 0.00105);
    REQUIRE(result.warnings.size() == 1u);
    CHECK_THAT(result.warnings[0], Catch::Contains("of its 0.001 s budget"));
}

TEST_CASE("a reference's own noise is subtracted, and what it cannot measure is left out", "[unit][compare]") {
    // Measured against a reference whose own relMSE is 0.001: 1/t + 0.001. The floor is 0.01,
    // so the checkpoints after 100 s are left out of the fit and 1e-3 is not read at all.
    const double noise = 1e-3;
    const auto checkpoints = series(10, [&](double t) { return 1.0 / t + noise; });  // 1 ... 512 s
    CHECK(less_reference_noise(0.5, noise) == Approx(0.499));
    CHECK(reference_floor(noise) == Approx(0.01));
    CHECK(reference_floor(-1.0) == 0.0);  // unknown: no floor
    const ConvergenceFit fit = fit_convergence(checkpoints, noise);
    // The passes of 1 ... 64 s; those of 128 and 256 s (1/d < 0.01) lie below the floor.
    CHECK(fit.points == 7);
    CHECK(fit.slope == Approx(-1.0));
    // Without the correction the same passes bend towards the reference's noise: a flatter fit
    // (-0.976 through the nine passes of 1 ... 256 s).
    CHECK(fit_convergence(checkpoints).slope > -0.98);
    const auto times = times_to_accuracy(checkpoints, {0.05, 1e-3}, noise);
    CHECK(times[0].measured);
    CHECK(times[0].seconds == Approx(20.0).epsilon(0.05));  // 1/t = 0.05, between 16 and 32 s
    CHECK(times[1].below_reference_floor);
    CHECK_FALSE(times[1].measured);
}

TEST_CASE("a reference of the runs' own seed is refused; a noisy one marks what it cannot measure", "[unit][compare]") {
    TemporaryFolder folder;
    CompareRequest request = furnace_request(folder);
    const auto write_reference = [&](const std::map<std::string, std::string>& header) {
        Image image(8, 8, Spectrum(1.0f));
        image.metadata = header;
        write_image(request.reference, image);
    };
    SECTION("the same seed, from sample 0: its noise is the runs' own") {
        write_reference({{"freezeray:seed", "3"}, {"freezeray:sample_offset", "0"}});
        CHECK_THROWS_WITH(run_comparison(request, testing::full_registry()), Catch::Contains("seed 3, this comparison's"));
    }
    SECTION("the same seed from sample 16 on does not overlap 16 samples per pixel") {
        write_reference({{"freezeray:seed", "3"}, {"freezeray:sample_offset", "16"}});
        CHECK_NOTHROW(run_comparison(request, testing::full_registry()));
    }
    SECTION("at equal time any offset may be reached: refused") {
        write_reference({{"freezeray:seed", "3"}, {"freezeray:sample_offset", "16"}});
        request.samples_per_pixel = 0;
        request.time_seconds = 0.1;
        CHECK_THROWS_WITH(run_comparison(request, testing::full_registry()), Catch::Contains("seed 3"));
    }
    SECTION("another seed, too noisy for the errors it would measure") {
        write_reference({{"freezeray:seed", "4"}, {"freezeray:estimated_relative_mse", "0.05"}});
        const Comparison comparison = run_comparison(request, testing::full_registry());
        CHECK(comparison.reference_relative_mse == Approx(0.05));
        for (const IntegratorRun& run : comparison.runs) {
            CHECK(run.relative_mse == Approx(run.raw_relative_mse - 0.05));
            for (const TimeToAccuracy& t : run.time_to_accuracy) CHECK(t.below_reference_floor);  // 1e-2, 1e-3 < 0.5
        }
        write_comparison_report(comparison, request.out_folder);
        const auto md = lines_of(request.out_folder + "/report.md");
        std::string text;
        for (const std::string& line : md) text += line + "\n";
        CHECK_THAT(text, Catch::Contains("too noisy for errors below 0.5 (marked †)"));
        CHECK_THAT(text, Catch::Contains("< 0.5 †"));
        CHECK_THAT(text, Catch::Contains("† reference too noisy"));
    }
}

TEST_CASE("a reference made for a comparison never gets the comparison's seed, and stays a valid --seed", "[unit][compare]") {
    const std::uint64_t top = std::uint64_t{1} << 63;
    for (const std::uint64_t seed : {std::uint64_t{0}, std::uint64_t{1}, std::uint64_t{3}, std::uint64_t{12345}, top - 1, top,
                                     top + 1, ~std::uint64_t{0}, reference_seed(0)}) {
        CAPTURE(seed);
        CHECK(reference_seed(seed) != seed);
        CHECK(reference_seed(seed) < top);  // a signed 64-bit --seed
    }
    CHECK(reference_seed(1) != reference_seed(2));  // different comparisons, different references
}

TEST_CASE("without a reference the crops show where the runs disagree most", "[unit][compare]") {
    TemporaryFolder folder;
    CompareRequest request = furnace_request(folder);
    request.reference.clear();
    request.width = request.height = 32;  // room for two crops of 8 x 8 that do not overlap
    request.crops = {{0, 0, 4, 4, "chosen by the user"}};
    const Comparison comparison = run_comparison(request, testing::full_registry());
    REQUIRE(comparison.crops.size() == 3u);  // the user's, then two found
    CHECK(comparison.crops[0].reason == "chosen by the user");
    for (std::size_t i = 1; i < 3; ++i) CHECK(comparison.crops[i].reason == "highest disagreement between the runs");
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

TEST_CASE("two renders agree when they differ by their noise, and not when one has missed light", "[unit][compare]") {
    // 64 x 64 pixels of mean 1 and variance of the mean 0.01 per channel: a and b draw their
    // pixels independently, so sum (a - b)^2 / sum (Var a + Var b) is 1 within sqrt(2 / 12288) =
    // 0.0128 (one standard deviation; the margin below is 6 of them, a chance of about 2e-9).
    std::mt19937 random(17);
    std::normal_distribution<float> noise(0.0f, 0.1f);
    const auto render = [&](float shift) {
        RenderResult result;
        result.image = Image(64, 64);
        result.variance = Image(64, 64, Spectrum(0.01f));
        for (std::size_t i = 0; i < result.image.pixel_count(); ++i)
            result.image[i] = Spectrum(1.0f + shift + noise(random), 1.0f + shift + noise(random), 1.0f + shift + noise(random));
        return result;
    };
    const RenderResult a = render(0.0f), b = render(0.0f), biased = render(0.2f);
    const Agreement same = agreement(a, b);
    CHECK(same.terms == 64u * 64u * 3u);
    CHECK(same.statistic == Approx(1.0).margin(0.077));
    CHECK(same.standard_error == Approx(2.0 / std::sqrt(12288.0)).epsilon(0.05));  // the weights vary a little
    CHECK_FALSE(same.disagree());
    // Two standard errors apart on average: D about 1 + 0.2^2 / 0.02 = 3.
    const Agreement apart = agreement(a, biased);
    CHECK(apart.statistic == Approx(3.0).margin(0.25));
    CHECK(apart.disagree());
    // One pixel lit in a, black with no variance in the other: light one render has not found.
    RenderResult dark = b;
    dark.image[5] = Spectrum(0.0f);
    dark.variance[5] = Spectrum(0.0f);
    RenderResult lit = a;
    lit.variance[5] = Spectrum(0.0f);
    const Agreement missed = agreement(lit, dark);
    CHECK(missed.one_sided == 3u);
    CHECK(missed.disagree());
}
