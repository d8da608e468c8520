// write_comparison_report: the report's folder and every file in it. Each file is written
// atomically (a temporary file, then renamed into place), and if anything fails, everything
// written so far is removed again: a report is there whole or not at all.
#include "freezeray/comparison.hpp"
#include "freezeray/error.hpp"
#include "freezeray/image.hpp"
#include "freezeray/false_colour.hpp"
#include "report_content.hpp"
#include "report_svg.hpp"

#include <atomic>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <system_error>
#include <vector>

#include <unistd.h>  // getpid, to name temporary files

namespace freezeray {

namespace {

namespace fs = std::filesystem;

// Writes `text` to `path` atomically: into a fresh temporary file beside it, then renamed over it
// (POSIX rename replaces the destination in one step), as write_image does for images.
void write_text_atomically(const fs::path& path, const std::string& text) {
    static std::atomic<unsigned> counter{0};
    const fs::path temporary = path.string() + ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(counter++);
    std::FILE* file = std::fopen(temporary.c_str(), "wb");
    if (file == nullptr) throw InputError(path.string(), "cannot create the temporary file '" + temporary.string() + "'");
    const bool written = std::fwrite(text.data(), 1, text.size(), file) == text.size();
    const bool closed = std::fclose(file) == 0;
    std::error_code error;
    if (written && closed) fs::rename(temporary, path, error);
    if (!written || !closed || error) {
        std::error_code ignored;
        fs::remove(temporary, ignored);
        throw InputError(path.string(), error ? "cannot move the temporary file into place: " + error.message()
                                              : std::string("cannot write the temporary file"));
    }
}

// The report's folder and what has been written into it. Unless commit() is called, the
// destructor removes every file written and every folder created (when empty), so that a report
// that fails half-way leaves nothing behind.
class ReportFolder {
public:
    // Creates `folder` and its images/ subfolder (with any missing parents).
    explicit ReportFolder(const std::string& folder) : root_(folder) {
        create_folder(root_);
        create_folder(root_ / "images");
    }
    ~ReportFolder() {
        if (committed_) return;
        std::error_code ignored;
        for (const fs::path& file : written_files_) fs::remove(file, ignored);
        for (auto folder = created_folders_.rbegin(); folder != created_folders_.rend(); ++folder) {
            fs::remove(*folder, ignored);  // fails, harmlessly, if someone else put a file there
        }
    }
    ReportFolder(const ReportFolder&) = delete;
    ReportFolder& operator=(const ReportFolder&) = delete;

    void write_text(const std::string& relative, const std::string& text) {
        write_text_atomically(root_ / relative, text);
        written_files_.push_back(root_ / relative);
    }
    void write_png(const std::string& relative, const Image& image) {
        write_image((root_ / relative).string(), image);
        written_files_.push_back(root_ / relative);
    }
    // The report is complete: keep it.
    void commit() { committed_ = true; }

private:
    // Creates `folder` and the parents it lacks, remembering each one created.
    void create_folder(const fs::path& folder) {
        std::vector<fs::path> missing;
        std::error_code error;
        for (fs::path p = folder; !p.empty() && !fs::exists(p, error); p = p.parent_path()) {
            missing.push_back(p);
            if (p == p.parent_path()) break;
        }
        for (auto p = missing.rbegin(); p != missing.rend(); ++p) {
            const bool created = fs::create_directory(*p, error);
            if (error) {
                throw InputError(root_.string(), "cannot create the folder '" + p->string() + "': " + error.message());
            }
            if (created) created_folders_.push_back(*p);
        }
        if (!fs::is_directory(folder, error)) {
            throw InputError(root_.string(), "'" + folder.string() + "' exists and is not a folder");
        }
    }

    fs::path root_;
    std::vector<fs::path> created_folders_;
    std::vector<fs::path> written_files_;
    bool committed_ = false;
};

std::string size_text(const Image& image) { return std::to_string(image.width()) + "x" + std::to_string(image.height()); }

// Throws InputError unless there is something to report and every image has the same size.
void check_comparison(const Comparison& comparison, const report::Layout& layout, const std::string& folder) {
    if (comparison.runs.empty()) throw InputError(folder, "there is no integrator run to report");
    if (layout.width <= 0 || layout.height <= 0) throw InputError(folder, "the images to report are empty");
    for (const IntegratorRun& run : comparison.runs) {
        const Image& image = run.result.image;
        if (image.width() != layout.width || image.height() != layout.height) {
            throw InputError(folder, "the image of '" + run.integrator + "' is " + size_text(image) + ", but " +
                                         (comparison.reference ? "the reference" : "the first image") + " is " +
                                         std::to_string(layout.width) + "x" + std::to_string(layout.height));
        }
    }
}

// The pixels of `region`, each repeated `factor` times in x and y (nearest neighbour), so that a
// viewer's smoothing cannot hide the noise we want to show.
Image magnified_crop(const Image& image, const CropRegion& region, int factor) {
    Image crop(region.width * factor, region.height * factor);
    for (int y = 0; y < crop.height(); ++y) {
        for (int x = 0; x < crop.width(); ++x) crop.at(x, y) = image.at(region.x + x / factor, region.y + y / factor);
    }
    return crop;
}

// A CSV field (RFC 4180): quoted when it holds a comma, a quote or a line break.
std::string csv_text(const std::string& text) {
    if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
    std::string quoted = "\"";
    for (const char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
    return quoted + "\"";
}

// A number at full precision (%.9g); empty when negative or NaN ("no value").
std::string csv_number(double value) {
    if (!(value >= 0.0)) return "";
    char text[32];
    std::snprintf(text, sizeof(text), "%.9g", value);
    return text;
}

// A number that may be negative (a difference of errors).
std::string csv_signed(double value) {
    char text[32];
    std::snprintf(text, sizeof(text), "%.9g", value);
    return text;
}

// convergence.csv: one row per checkpoint of every run, checkpoints numbered from 1.
std::string convergence_csv(const Comparison& comparison) {
    // relative_mse as measured against the reference; relative_mse_less_reference without the
    // reference's own noise (empty when the reference does not give it). The pass_ columns are
    // those of the pass that ended at the checkpoint, alone (its own samples; empty for the first).
    std::string csv = "integrator,checkpoint,seconds,samples_per_pixel,mse,relative_mse,estimated_relative_mse,"
                      "relative_mse_less_reference,pass_seconds,pass_samples_per_pixel,pass_relative_mse,"
                      "pass_estimated_relative_mse\n";
    for (const IntegratorRun& run : comparison.runs) {
        for (std::size_t i = 0; i < run.checkpoints.size(); ++i) {
            const Checkpoint& c = run.checkpoints[i];
            csv += csv_text(run.integrator) + "," + std::to_string(i + 1) + "," + csv_number(c.seconds) + "," +
                   std::to_string(c.samples_per_pixel) + "," + csv_number(c.mse) + "," + csv_number(c.relative_mse) +
                   "," + csv_number(c.estimated_relative_mse) + "," +
                   (c.relative_mse >= 0.0 && comparison.reference_relative_mse > 0.0
                        ? csv_signed(less_reference_noise(c.relative_mse, comparison.reference_relative_mse))
                        : std::string()) +
                   "," + csv_number(c.pass_seconds) + "," +
                   (c.pass_seconds > 0.0 ? std::to_string(c.pass_samples_per_pixel) : std::string()) + "," +
                   csv_number(c.pass_relative_mse) + "," + csv_number(c.pass_estimated_relative_mse) + "\n";
        }
    }
    return csv;
}

// time_to_accuracy.csv: one row per run and target; the seconds are empty where the report has no
// number (not reached and not estimated).
std::string time_to_accuracy_csv(const Comparison& comparison) {
    std::string csv = "integrator,target_relative_mse,seconds,how\n";
    for (const IntegratorRun& run : comparison.runs) {
        for (const TimeToAccuracy& t : run.time_to_accuracy) {
            const bool number = std::isfinite(t.seconds) && (t.measured || !t.beyond_limit);
            char how[96];
            if (t.measured)
                std::snprintf(how, sizeof how, "measured");
            else if (t.below_reference_floor)
                std::snprintf(how, sizeof how, "below what the reference can measure");
            else if (!std::isfinite(t.seconds))
                std::snprintf(how, sizeof how, "not reached; its error does not fall");
            else if (t.beyond_limit)
                std::snprintf(how, sizeof how, "not reached; beyond %gx the run's time not estimated",
                              TimeToAccuracy::ExtrapolationLimit);
            else
                std::snprintf(how, sizeof how, "along its slope %.2f", t.slope);
            csv += csv_text(run.integrator) + "," + csv_number(t.target) + "," + (number ? csv_number(t.seconds) : "") +
                   "," + how + "\n";
        }
    }
    return csv;
}

// Every image of the report: renders, reference, error maps, crops.
void write_images(ReportFolder& files, const Comparison& comparison, const report::Layout& layout) {
    using report::ReferenceName;
    if (comparison.reference) files.write_png(report::image_file(ReferenceName), *comparison.reference);
    for (std::size_t i = 0; i < comparison.runs.size(); ++i) {
        const RenderResult& result = comparison.runs[i].result;
        const std::string& name = layout.run_names[i];
        files.write_png(report::image_file(name), result.image);
        if (!report::has_error_map(comparison, comparison.runs[i])) continue;
        files.write_png(report::error_map_file(name), comparison.reference
                                                          ? relative_error_map(result.image, *comparison.reference)
                                                          : estimated_error_map(result.image, result.variance));
    }
    for (const report::NumberedCrop& crop : layout.crops) {
        const int factor = report::CropMagnification;
        if (comparison.reference) {
            files.write_png(report::crop_file(crop.number, ReferenceName),
                            magnified_crop(*comparison.reference, crop.region, factor));
        }
        for (std::size_t i = 0; i < comparison.runs.size(); ++i) {
            files.write_png(report::crop_file(crop.number, layout.run_names[i]),
                            magnified_crop(comparison.runs[i].result.image, crop.region, factor));
        }
    }
}

}  // namespace

void write_comparison_report(const Comparison& comparison, const std::string& folder) {
    try {
        const report::Layout layout = report::report_layout(comparison);
        check_comparison(comparison, layout, folder);
        ReportFolder files(folder);
        write_images(files, comparison, layout);
        files.write_text(report::PlotFile, report::convergence_plot_svg(comparison, report::SvgUse::File));
        files.write_text(report::ColourBarFile, report::colour_bar_svg(report::SvgUse::File));
        files.write_text(report::CsvFile, convergence_csv(comparison));
        files.write_text(report::TimesCsvFile, time_to_accuracy_csv(comparison));
        files.write_text("report.md", report::comparison_markdown(comparison, layout));
        // Last, because it embeds the PNG files written above.
        files.write_text("report.html", report::comparison_html(comparison, layout, folder));
        files.commit();
    } catch (const InputError& error) {
        if (error.where() == folder) throw;
        throw InputError(folder, error.what());
    } catch (const fs::filesystem_error& error) {
        throw InputError(folder, error.what());
    }
}

}  // namespace freezeray
