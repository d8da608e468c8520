// The comparison report (common/laboratory/src/report_*.cpp, common/image-files/src/false_colour.cpp): every file is written, the
// numbers in it are the runs' numbers, the HTML page is self-contained, the best values are
// marked in the right rows, and a report that cannot be written leaves nothing behind.
#include "freezeray/comparison.hpp"
#include "freezeray/error.hpp"
#include "freezeray/false_colour.hpp"
#include "freezeray/image.hpp"
#include "freezeray/metrics.hpp"
#include "image_files.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

using namespace freezeray;
using namespace freezeray::test;
namespace fs = std::filesystem;

namespace {

constexpr int Width = 16, Height = 12;

// A small "scene": a dim gradient with a bright square, so that relative errors vary over it.
Image reference_image() {
    Image image(Width, Height);
    for (int y = 0; y < Height; ++y) {
        for (int x = 0; x < Width; ++x) {
            const bool lit = x >= 4 && x < 10 && y >= 3 && y < 8;
            image.at(x, y) = lit ? Spectrum(0.9f, 0.8f, 0.6f) : Spectrum(0.05f * x / Width, 0.1f, 0.2f * y / Height);
        }
    }
    return image;
}

// `reference` with relative noise of amplitude `noise` (uniform, fixed seed).
Image noisy(const Image& reference, float noise, unsigned seed) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<float> uniform(-1.0f, 1.0f);
    Image image = reference;
    for (Spectrum& pixel : image.pixels()) {
        for (int c = 0; c < 3; ++c) pixel[c] *= 1.0f + noise * uniform(random);
    }
    return image;
}

// A run with plausible numbers: `passes` checkpoints at 1, 2, 4, ... spp whose relMSE falls like
// 1 / time, final metrics measured against `reference` (or estimated without one), the fit and
// the times to 1e-2 and 1e-3 from comparison.cpp.
IntegratorRun make_run(const std::string& name, const Image& reference, bool has_reference, float noise,
                       double seconds_per_sample, int passes, unsigned seed) {
    IntegratorRun run;
    run.integrator = name;
    run.result.image = noisy(reference, noise, seed);
    run.result.variance = Image(Width, Height);
    for (std::size_t i = 0; i < reference.pixel_count(); ++i) {
        run.result.variance[i] = reference[i] * reference[i] * (noise * noise / 3.0f);
    }
    run.result.samples_per_pixel = std::uint64_t(1) << (passes - 1);
    run.result.seconds = 0.01 + seconds_per_sample * double(run.result.samples_per_pixel);
    const double final_relative = relative_mse(run.result.image, reference);
    const double final_mse = mse(run.result.image, reference);
    run.result.estimated_relative_mse = 1.1 * final_relative;
    for (int k = 0; k < passes; ++k) {
        Checkpoint checkpoint;
        checkpoint.samples_per_pixel = std::uint64_t(1) << k;
        checkpoint.seconds = 0.01 + seconds_per_sample * double(checkpoint.samples_per_pixel);
        const double scale = double(run.result.samples_per_pixel) / double(checkpoint.samples_per_pixel);
        checkpoint.estimated_relative_mse = 1.1 * final_relative * scale;
        if (has_reference) {
            checkpoint.mse = final_mse * scale;
            checkpoint.relative_mse = final_relative * scale;
        }
        if (k > 0) {  // the pass from 2^(k-1) to 2^k spp: half the samples, twice the error
            checkpoint.pass_samples_per_pixel = std::uint64_t(1) << (k - 1);
            checkpoint.pass_seconds = seconds_per_sample * double(checkpoint.pass_samples_per_pixel);
            checkpoint.pass_estimated_relative_mse = 2.0 * checkpoint.estimated_relative_mse;
            if (has_reference) checkpoint.pass_relative_mse = 2.0 * checkpoint.relative_mse;
        }
        run.checkpoints.push_back(checkpoint);
    }
    run.error_is_estimated = !has_reference;
    if (has_reference) {
        run.mse = final_mse;
        run.relative_mse = final_relative;
        run.ssim = ssim(run.result.image, reference);
        run.mape = mape(run.result.image, reference);
    }
    const double shown = has_reference ? run.relative_mse : run.result.estimated_relative_mse;
    run.efficiency = 1.0 / (shown * run.result.seconds);
    run.fit = fit_convergence(run.checkpoints);
    run.time_to_accuracy = times_to_accuracy(run.checkpoints, {1e-2, 1e-3});
    return run;
}

// Two runs: pt-naive is faster, pt-mis better in every error and in efficiency.
Comparison make_comparison(bool has_reference = true) {
    const Image reference = reference_image();
    Comparison comparison;
    comparison.scene = "scenes/cornell-box/scene.json";
    comparison.renderer = "ch03";
    comparison.budget = "passes of 1 ms and 2.5 ms per sample";  // neither equal time nor equal samples: time is ranked
    if (has_reference) {
        comparison.reference = reference;
        comparison.reference_description = "reference.exr (4096 spp)";
    }
    comparison.runs.push_back(make_run("pt-naive", reference, has_reference, 0.3f, 0.001, 7, 1));
    comparison.runs.push_back(make_run("pt-mis", reference, has_reference, 0.1f, 0.0025, 6, 2));
    comparison.runs[0].checkpoints[0].estimated_relative_mse = -1.0;  // a missing value: an empty CSV field
    comparison.crops = {{2, 3, 5, 4, "highest error"}, {12, 8, 8, 8, "chosen by the user"}};  // the second is clipped
    comparison.agreements = pairwise_agreements(comparison.runs);  // as run_comparison does
    return comparison;
}

std::string read_text(const std::string& path) {
    const std::vector<unsigned char> bytes = read_bytes(path);
    return {bytes.begin(), bytes.end()};
}

std::vector<std::string> split(const std::string& text, char separator) {
    std::vector<std::string> parts;
    std::stringstream stream(text);
    for (std::string part; std::getline(stream, part, separator);) parts.push_back(part);
    if (!text.empty() && text.back() == separator) parts.push_back("");
    return parts;
}

std::size_t count(const std::string& text, const std::string& what) {
    std::size_t found = 0;
    for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + what.size())) ++found;
    return found;
}

// The cells of the first Markdown table row after `section` that starts with "| name |",
// trimmed and without bold marks.
std::vector<std::string> markdown_row(const std::string& markdown, const std::string& section, const std::string& name) {
    const std::size_t start = markdown.find("\n| " + name + " |", markdown.find(section));
    REQUIRE(start != std::string::npos);
    const std::string line = markdown.substr(start + 1, markdown.find('\n', start + 1) - start - 1);
    std::vector<std::string> cells;
    for (std::string cell : split(line, '|')) {
        const std::size_t first = cell.find_first_not_of(' '), last = cell.find_last_not_of(' ');
        cells.push_back(first == std::string::npos ? "" : cell.substr(first, last - first + 1));
    }
    return std::vector<std::string>(cells.begin() + 1, cells.end() - 1);  // drop the text outside the bars
}

bool bold(const std::string& cell) { return cell.size() > 4 && cell.rfind("**", 0) == 0; }
double number_in(const std::string& cell) { return std::strtod(cell.c_str() + (bold(cell) ? 2 : 0), nullptr); }

// Decodes base64 (RFC 4648), to check the images embedded in the HTML page.
std::vector<unsigned char> decode_base64(const std::string& text) {
    const std::string alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::vector<unsigned char> bytes;
    unsigned bits = 0, value = 0;
    for (const char c : text) {
        if (c == '=') break;
        value = (value << 6) | unsigned(alphabet.find(c));
        bits += 6;
        if (bits >= 8) {
            bits -= 8;
            bytes.push_back(static_cast<unsigned char>(value >> bits));
        }
    }
    return bytes;
}

}  // namespace

TEST_CASE("a comparison report writes every file, crops magnified 4x nearest-neighbour", "[unit][report]") {
    TemporaryFolder temporary;
    const std::string folder = temporary.file("reports/cornell");  // its parent is created too
    write_comparison_report(make_comparison(), folder);

    for (const std::string file :
         {"report.md", "report.html", "convergence.csv", "images/convergence.svg", "images/colour-bar.svg",
          "images/reference.png", "images/pt-naive.png", "images/pt-mis.png", "images/pt-naive-error.png",
          "images/pt-mis-error.png", "images/crop-1-reference.png", "images/crop-1-pt-naive.png",
          "images/crop-1-pt-mis.png", "images/crop-2-reference.png", "images/crop-2-pt-mis.png"}) {
        INFO(file);
        CHECK(fs::is_regular_file(fs::path(folder) / file));
    }
    for (const auto& entry : fs::recursive_directory_iterator(folder)) {
        CHECK(entry.path().filename().string().find(".tmp-") == std::string::npos);
    }
    const Image whole = read_image(folder + "/images/reference.png");
    const Image crop = read_image(folder + "/images/crop-1-reference.png");
    REQUIRE(crop.width() == 5 * 4);
    REQUIRE(crop.height() == 4 * 4);
    for (int y = 0; y < crop.height(); ++y) {
        for (int x = 0; x < crop.width(); ++x) REQUIRE(crop.at(x, y) == whole.at(2 + x / 4, 3 + y / 4));
    }
    const Image clipped = read_image(folder + "/images/crop-2-pt-mis.png");
    CHECK(clipped.width() == 4 * 4);
    CHECK(clipped.height() == 4 * 4);
}

TEST_CASE("convergence.csv has one full-precision row per checkpoint", "[unit][report]") {
    TemporaryFolder temporary;
    const Comparison comparison = make_comparison();
    write_comparison_report(comparison, temporary.file("report"));
    const std::vector<std::string> lines = split(read_text(temporary.file("report/convergence.csv")), '\n');

    REQUIRE(lines.front() == "integrator,checkpoint,seconds,samples_per_pixel,mse,relative_mse,estimated_relative_mse,"
                             "relative_mse_less_reference,pass_seconds,pass_samples_per_pixel,pass_relative_mse,"
                             "pass_estimated_relative_mse");
    std::size_t line = 1;
    for (const IntegratorRun& run : comparison.runs) {
        for (std::size_t i = 0; i < run.checkpoints.size(); ++i, ++line) {
            REQUIRE(line < lines.size());
            const std::vector<std::string> fields = split(lines[line], ',');
            REQUIRE(fields.size() == 12);
            CHECK(fields[7].empty());  // the reference does not give its own error
            const Checkpoint& expected = run.checkpoints[i];
            CHECK(fields[0] == run.integrator);
            CHECK(fields[1] == std::to_string(i + 1));
            CHECK(std::strtod(fields[2].c_str(), nullptr) == Approx(expected.seconds).epsilon(1e-8));
            CHECK(fields[3] == std::to_string(expected.samples_per_pixel));
            const double values[] = {expected.mse, expected.relative_mse, expected.estimated_relative_mse};
            for (int k = 0; k < 3; ++k) {
                if (values[k] < 0.0) {
                    CHECK(fields[4 + k].empty());
                } else {
                    CHECK(std::strtod(fields[4 + k].c_str(), nullptr) == Approx(values[k]).epsilon(1e-8));
                }
            }
            // The pass that ended here: none before the first checkpoint.
            if (i == 0) {
                for (int k = 8; k < 12; ++k) CHECK(fields[k].empty());
            } else {
                CHECK(std::strtod(fields[8].c_str(), nullptr) == Approx(expected.pass_seconds).epsilon(1e-8));
                CHECK(fields[9] == std::to_string(expected.pass_samples_per_pixel));
                CHECK(std::strtod(fields[10].c_str(), nullptr) == Approx(expected.pass_relative_mse).epsilon(1e-8));
                CHECK(std::strtod(fields[11].c_str(), nullptr) ==
                      Approx(expected.pass_estimated_relative_mse).epsilon(1e-8));
            }
        }
    }
    CHECK(line == lines.size() - 1);  // the last line ends with a newline: one empty part after it
    CHECK(lines.back().empty());
}

TEST_CASE("report.md's table shows the runs' numbers, best of each column in bold", "[unit][report]") {
    TemporaryFolder temporary;
    const Comparison comparison = make_comparison();
    write_comparison_report(comparison, temporary.file("report"));
    const std::string markdown = read_text(temporary.file("report/report.md"));

    for (const IntegratorRun& run : comparison.runs) {
        INFO(run.integrator);
        const std::vector<std::string> cells = markdown_row(markdown, "## Results", run.integrator);
        REQUIRE(cells.size() == 7);
        CHECK(cells[1] == std::to_string(run.result.samples_per_pixel));
        CHECK(number_in(cells[2]) == Approx(run.result.seconds).epsilon(1e-3));
        CHECK(number_in(cells[3]) == Approx(run.mse).epsilon(1e-3));
        CHECK(number_in(cells[4]) == Approx(run.relative_mse).epsilon(1e-3));
        CHECK(number_in(cells[5]) == Approx(run.ssim).epsilon(1e-3));
        CHECK(number_in(cells[6]) == Approx(run.efficiency).epsilon(1e-3));
    }
    // pt-naive is faster; pt-mis has the lower errors, the higher SSIM and efficiency.
    const std::vector<std::string> naive = markdown_row(markdown, "## Results", "pt-naive");
    const std::vector<std::string> mis = markdown_row(markdown, "## Results", "pt-mis");
    CHECK(bold(naive[2]));
    CHECK_FALSE(bold(mis[2]));
    for (int column = 3; column <= 6; ++column) {
        INFO("column " << column);
        CHECK(bold(mis[column]));
        CHECK_FALSE(bold(naive[column]));
    }
    CHECK_FALSE(bold(naive[1]));  // samples per pixel: no best
    CHECK(markdown.find("](images/convergence.svg)") != std::string::npos);
    CHECK(markdown.find("](images/crop-2-pt-naive.png)") != std::string::npos);
    CHECK(markdown.find("slope −") != std::string::npos);
}

TEST_CASE("report.html marks the best values in the right rows", "[unit][report]") {
    TemporaryFolder temporary;
    write_comparison_report(make_comparison(), temporary.file("report"));
    const std::string html = read_text(temporary.file("report/report.html"));
    const std::string table = html.substr(html.find("<table class=\"metrics\">"));
    const auto row_of = [&](const std::string& name) {
        const std::size_t start = table.find("</span>" + name + "</td>");
        REQUIRE(start != std::string::npos);
        return table.substr(start, table.find("</tr>", start) - start);
    };
    CHECK(count(row_of("pt-naive"), "class=\"best\"") == 1);  // time
    CHECK(count(row_of("pt-mis"), "class=\"best\"") == 4);    // MSE, relMSE, SSIM, efficiency
    CHECK(count(row_of("pt-mis"), "★") == 4);
}

TEST_CASE("at equal time the wall time is not ranked: every run took the budget", "[unit][report]") {
    TemporaryFolder temporary;
    Comparison comparison = make_comparison();
    comparison.equal_time = true;
    write_comparison_report(comparison, temporary.file("report"));
    const std::string markdown = read_text(temporary.file("report/report.md"));
    CHECK_FALSE(bold(markdown_row(markdown, "## Results", "pt-naive")[2]));
    CHECK_FALSE(bold(markdown_row(markdown, "## Results", "pt-mis")[2]));
    CHECK(bold(markdown_row(markdown, "## Results", "pt-mis")[4]));  // relMSE still is
    CHECK(markdown.find("lowest time") == std::string::npos);
}

TEST_CASE("the error-versus-time plot has a line per run and each slope in its legend", "[unit][report]") {
    TemporaryFolder temporary;
    const Comparison comparison = make_comparison();
    write_comparison_report(comparison, temporary.file("report"));
    const std::string svg = read_text(temporary.file("report/images/convergence.svg"));

    CHECK(svg.rfind("<svg", 0) == 0);
    CHECK(svg.find("</svg>") != std::string::npos);
    CHECK(count(svg, "<polyline") == comparison.runs.size());
    CHECK(count(svg, "<text") == count(svg, "</text>"));
    CHECK(count(svg, "<g") == count(svg, "</g>"));
    CHECK(svg.find(">wall time (s)<") != std::string::npos);
    CHECK(svg.find(">relMSE, log scale<") != std::string::npos);
    // The fitted lines and the slope -1 guide, and the legend's sample of each.
    CHECK(count(svg, "stroke-dasharray") == comparison.runs.size() + 3);
    CHECK(svg.find(">slope −1: unbiased rate<") != std::string::npos);
    for (const IntegratorRun& run : comparison.runs) {
        REQUIRE(run.fit.points > 0);
        char slope[32];
        std::snprintf(slope, sizeof(slope), "%.2f", std::abs(run.fit.slope));
        CHECK(svg.find(">" + run.integrator + "<") != std::string::npos);
        CHECK(svg.find(">slope −" + std::string(slope)) != std::string::npos);  // then " (not −1)" when its interval excludes −1
    }
}

TEST_CASE("report.html embeds every image and refers to nothing outside itself", "[unit][report]") {
    TemporaryFolder temporary;
    const std::string folder = temporary.file("report");
    write_comparison_report(make_comparison(), folder);
    const std::string html = read_text(folder + "/report.html");

    // Content (as a string of bytes) -> name.
    auto as_string = [](const std::vector<unsigned char>& bytes) { return std::string(bytes.begin(), bytes.end()); };
    std::map<std::string, std::string> files;
    for (const auto& entry : fs::directory_iterator(folder + "/images")) {
        if (entry.path().extension() == ".png")
            files[as_string(read_bytes(entry.path().string()))] = entry.path().filename().string();
    }
    REQUIRE(files.size() == 11);  // reference, 2 renders, 2 error maps, 2 crops x 3 images

    std::set<std::string> embedded;
    const std::string prefix = "src=\"data:image/png;base64,";
    for (std::size_t at = html.find(prefix); at != std::string::npos; at = html.find(prefix, at + 1)) {
        const std::size_t start = at + prefix.size();
        const auto found = files.find(as_string(decode_base64(html.substr(start, html.find('"', start) - start))));
        REQUIRE(found != files.end());
        embedded.insert(found->second);
    }
    CHECK(embedded.size() == files.size());
    CHECK(count(html, "<img ") == count(html, prefix));
    CHECK(html.find("http") == std::string::npos);
    CHECK(count(html, "url(") == count(html, "url(#"));  // only references inside the page
    CHECK(html.find("<svg") != std::string::npos);       // the plot and the colour bar, inline
}

TEST_CASE("a comparison without a reference reports estimated errors", "[unit][report]") {
    TemporaryFolder temporary;
    const std::string folder = temporary.file("report");
    const Comparison comparison = make_comparison(false);
    write_comparison_report(comparison, folder);

    CHECK_FALSE(fs::exists(folder + "/images/reference.png"));
    CHECK(fs::exists(folder + "/images/pt-naive-error.png"));  // from the variance
    const std::string markdown = read_text(folder + "/report.md");
    const std::vector<std::string> cells = markdown_row(markdown, "## Results", "pt-mis");
    CHECK(cells[3] == "—");  // MSE
    CHECK(cells[4].find("(estimated)") != std::string::npos);
    CHECK(number_in(cells[4]) == Approx(comparison.runs[1].result.estimated_relative_mse).epsilon(1e-3));
    CHECK(cells[5] == "—");  // SSIM
    CHECK(bold(cells[4]));   // estimated errors still compare with each other
    CHECK(markdown.find("There is no reference") != std::string::npos);
    CHECK(read_text(folder + "/images/convergence.svg").find("estimated relMSE") != std::string::npos);
    CHECK(read_text(folder + "/report.html").find("http") == std::string::npos);
}

TEST_CASE("a report that cannot be written throws InputError and leaves nothing", "[unit][report]") {
    TemporaryFolder temporary;

    SECTION("the folder cannot be created") {
        write_file(temporary.file("file"), "not a folder");
        const std::string folder = temporary.file("file/report");
        try {
            write_comparison_report(make_comparison(), folder);
            FAIL("no InputError");
        } catch (const InputError& error) {
            CHECK(error.where() == folder);
        }
        CHECK(temporary.entries() == std::vector<std::string>{"file"});
    }
    SECTION("the last file cannot be written: everything before it is removed") {
        const std::string folder = temporary.file("new/report");
        fs::create_directories(folder + "/report.html");  // a folder where the page should go
        CHECK_THAT(input_error_message([&] { write_comparison_report(make_comparison(), folder); }),
                   Catch::Contains(folder) && Catch::Contains("report.html"));
        std::vector<std::string> left;
        for (const auto& entry : fs::recursive_directory_iterator(temporary.file("new"))) {
            left.push_back(fs::relative(entry.path(), temporary.file("new")).string());
        }
        std::sort(left.begin(), left.end());
        CHECK(left == std::vector<std::string>{"report", "report/report.html"});
    }
    SECTION("images of different sizes are refused before anything is written") {
        Comparison comparison = make_comparison();
        comparison.runs[1].result.image = Image(8, 8);
        CHECK_THAT(input_error_message([&] { write_comparison_report(comparison, temporary.file("report")); }),
                   Catch::Contains("pt-mis") && Catch::Contains("8x8"));
        CHECK(temporary.entries().empty());
    }
}

TEST_CASE("false-colour maps: fixed log bounds on viridis", "[unit][report]") {
    // Viridis at 0, 0.5 and 1 (Smith and van der Walt 2015, matplotlib's table: entries 0, 127-128, 255).
    const Spectrum low(0.267004f, 0.004874f, 0.329415f), middle(0.128149f, 0.565107f, 0.550893f),
        high(0.993248f, 0.906157f, 0.143936f);
    const Image reference = reference_image();
    Image tenth = reference;  // relative error exactly 0.1 in every channel: the middle of 1e-3 .. 10
    for (Spectrum& pixel : tenth.pixels()) pixel += 0.1f * (pixel + Spectrum(RelativeMseEpsilon));
    Comparison comparison;
    comparison.reference = reference;
    for (const auto& [name, image] : {std::pair<std::string, Image>{"exact", reference}, {"tenth", tenth},
                                      {"wrong", Image(Width, Height, Spectrum(1000.0f))}}) {
        IntegratorRun run;
        run.integrator = name;
        run.result.image = image;
        comparison.runs.push_back(run);
    }
    TemporaryFolder temporary;
    write_comparison_report(comparison, temporary.file("report"));

    const std::pair<std::string, Spectrum> expected[] = {{"exact", low}, {"tenth", middle}, {"wrong", high}};
    for (const auto& [name, colour] : expected) {
        INFO(name);
        const Image map = read_image(temporary.file("report/images/" + name + "-error.png"));
        for (const Spectrum& pixel : map.pixels()) {
            for (int c = 0; c < 3; ++c) REQUIRE(linear_to_srgb(pixel[c]) == Approx(colour[c]).margin(1.0 / 255.0));
        }
    }
    const std::string bar = read_text(temporary.file("report/images/colour-bar.svg"));
    for (const std::string label : {">1e-3<", ">1e-2<", ">1e-1<", ">1<", ">10<"}) CHECK(bar.find(label) != std::string::npos);
    CHECK(read_text(temporary.file("report/images/convergence.svg")).find("no checkpoints to plot") != std::string::npos);
}

TEST_CASE("report.md gives each crop's MSE and relMSE per integrator, lowest in bold", "[unit][report]") {
    TemporaryFolder temporary;
    const Comparison comparison = make_comparison();
    write_comparison_report(comparison, temporary.file("report"));
    const std::string markdown = read_text(temporary.file("report/report.md"));

    // Crop 1 is (2, 3) to (7, 7); its errors recomputed here from the images.
    Image reference(5, 4), naive(5, 4), mis(5, 4);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 5; ++x) {
            reference.at(x, y) = comparison.reference->at(2 + x, 3 + y);
            naive.at(x, y) = comparison.runs[0].result.image.at(2 + x, 3 + y);
            mis.at(x, y) = comparison.runs[1].result.image.at(2 + x, 3 + y);
        }
    const std::string section = "### crop 1";
    const std::vector<std::string> mse_row = markdown_row(markdown, section, "MSE");
    const std::vector<std::string> relative_row = markdown_row(markdown, section, "relMSE");
    REQUIRE(mse_row.size() == 3);
    REQUIRE(relative_row.size() == 3);
    CHECK(number_in(mse_row[1]) == Approx(mse(naive, reference)).epsilon(1e-3));
    CHECK(number_in(mse_row[2]) == Approx(mse(mis, reference)).epsilon(1e-3));
    CHECK(number_in(relative_row[1]) == Approx(relative_mse(naive, reference)).epsilon(1e-3));
    CHECK(number_in(relative_row[2]) == Approx(relative_mse(mis, reference)).epsilon(1e-3));
    // pt-mis has a third of pt-naive's noise: it wins in the crop too.
    CHECK(bold(mse_row[2]));
    CHECK_FALSE(bold(mse_row[1]));

    // Without a reference there is nothing to measure a crop against.
    const std::string no_reference_folder = temporary.file("estimated");
    write_comparison_report(make_comparison(false), no_reference_folder);
    CHECK(read_text(no_reference_folder + "/report.md").find("in this crop") == std::string::npos);
}

TEST_CASE("without a reference, a black pixel with no variance beside lit ones is shown as unknown", "[unit][report]") {
    // A 5 x 3 render: lit everywhere but (1, 1), black with zero variance, and the columns x = 3
    // and 4, black with zero variance too (x = 3 beside the lit column x = 2, x = 4 not).
    Image image(5, 3, Spectrum(0.5f)), variance(5, 3, Spectrum(0.01f));
    image.at(1, 1) = Spectrum(0.0f);
    variance.at(1, 1) = Spectrum(0.0f);
    for (int y = 0; y < 3; ++y)
        for (int x = 3; x < 5; ++x) image.at(x, y) = variance.at(x, y) = Spectrum(0.0f);
    const Image map = estimated_error_map(image, variance);
    CHECK(map.at(1, 1) == UnknownErrorColour);  // nothing found yet where light surely is nearby
    CHECK(map.at(3, 1) == UnknownErrorColour);  // beside the lit column x = 2
    CHECK(map.at(4, 1) != UnknownErrorColour);  // black among black: truly black, as far as anyone can tell
    CHECK(map.at(0, 0) != UnknownErrorColour);
}

TEST_CASE("an estimated error that rises with time is called not yet reliable", "[unit][report]") {
    TemporaryFolder temporary;
    Comparison comparison = make_comparison(false);  // no reference: errors are estimated
    IntegratorRun& run = comparison.runs[0];
    run.checkpoints.clear();
    for (int i = 0; i < 7; ++i) {
        const double t = std::ldexp(1.0, i);
        run.checkpoints.push_back({t, std::uint64_t(1) << i, -1.0, -1.0, 0.02 * std::pow(t, 0.3)});
    }
    run.fit = fit_convergence(run.checkpoints);
    write_comparison_report(comparison, temporary.file("report"));
    const std::string markdown = read_text(temporary.file("report/report.md"));
    CHECK_THAT(markdown, Catch::Contains(run.integrator + ": slope 0.30 from 6 checkpoints: the estimated error rises "
                                                          "with time, so it is not yet reliable"));
    CHECK_THAT(markdown, Catch::Contains("cannot see what a render has not found yet"));
}

TEST_CASE("the report says which run disagrees with the others, which agree", "[unit][report]") {
    TemporaryFolder temporary;
    Comparison comparison = make_comparison();
    // A third run, half as bright again: far outside everyone's noise.
    IntegratorRun odd = make_run("pt-nee", reference_image(), true, 0.1f, 0.002, 6, 3);
    for (std::size_t i = 0; i < odd.result.image.pixel_count(); ++i) odd.result.image[i] *= 1.5f;
    comparison.runs.push_back(odd);
    comparison.agreements = pairwise_agreements(comparison.runs);
    write_comparison_report(comparison, temporary.file("report"));
    const std::string markdown = read_text(temporary.file("report/report.md"));
    CHECK_THAT(markdown, Catch::Contains("pt-naive and pt-mis: agree within their noise"));
    CHECK_THAT(markdown, Catch::Contains("pt-naive and pt-nee: disagree beyond their combined noise"));
    CHECK_THAT(markdown, Catch::Contains("pt-nee disagrees with every other run, far more than they disagree among themselves"));
    CHECK(markdown.find("pt-mis disagrees with every other run") == std::string::npos);
}

TEST_CASE("a run the agreement tests call unconverged wins nothing, however low its own estimate", "[unit][report]") {
    // Without a reference, a third run that has missed half the light (its image half as bright)
    // with the lowest estimated relMSE of all: its variance knows nothing of what it missed.
    TemporaryFolder temporary;
    Comparison comparison = make_comparison(false);
    IntegratorRun odd = make_run("pt-nee", reference_image(), false, 0.02f, 0.002, 6, 3);
    for (std::size_t i = 0; i < odd.result.image.pixel_count(); ++i) {
        odd.result.image[i] *= 0.5f;
        odd.result.variance[i] *= 0.25f;
    }
    odd.result.estimated_relative_mse = 1e-7;
    odd.efficiency = 1.0 / (odd.result.estimated_relative_mse * odd.result.seconds);
    comparison.runs.push_back(odd);
    comparison.agreements = pairwise_agreements(comparison.runs);
    write_comparison_report(comparison, temporary.file("report"));
    const std::string markdown = read_text(temporary.file("report/report.md"));
    // The verdict names the best of the others, and says why pt-nee is left out.
    CHECK_THAT(markdown, Catch::Contains("**Verdict.** pt-mis has the lowest relMSE"));
    CHECK_THAT(markdown, Catch::Contains("pt-nee is left out"));
    CHECK_THAT(markdown, Catch::Contains("estimated from each run's own per-pixel variance"));
    // Its row: marked, never bold.
    const std::vector<std::string> row = markdown_row(markdown, "## Results", "pt-nee");
    REQUIRE(row.size() >= 6);
    CHECK(std::none_of(row.begin(), row.end(), [](const std::string& cell) { return cell.find("**") != std::string::npos; }));
    CHECK_THAT(row[4], Catch::Contains("‡"));
    const std::string html = read_text(temporary.file("report/report.html"));
    CHECK(count(html, "<span class=\"star\">") >= 1);
    CHECK_THAT(html, Catch::Contains("pt-nee is left out"));
}

TEST_CASE("the verdict names the winner by the measured error and the ratio to the runner-up", "[unit][report]") {
    const Comparison comparison = make_comparison();
    const double a = comparison.runs[1].relative_mse, b = comparison.runs[0].relative_mse;
    REQUIRE(a < b);
    char ratio[32];
    std::snprintf(ratio, sizeof ratio, "%.3g×", b / a);
    TemporaryFolder temporary;
    write_comparison_report(comparison, temporary.file("report"));
    const std::string markdown = read_text(temporary.file("report/report.md"));
    CHECK_THAT(markdown, Catch::Contains("**Verdict.** pt-mis has the lowest relMSE"));
    CHECK_THAT(markdown, Catch::Contains(std::string(ratio) + " lower"));
    CHECK(markdown.find("left out") == std::string::npos);
}
