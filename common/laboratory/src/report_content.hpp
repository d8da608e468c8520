// What a comparison report says, whatever its format: the file names of its images, the table of
// metrics with the best value of each column marked, the times to accuracy, how numbers are
// written, and the text that explains it all. report_markdown.cpp and report_html.cpp only lay
// this out; report_writer.cpp writes the files these names refer to.
#pragma once

#include "freezeray/comparison.hpp"

#include <optional>
#include <string>
#include <vector>

namespace freezeray::report {

// Files of the report, relative to its folder.
inline const std::string PlotFile = "images/convergence.svg";
inline const std::string ColourBarFile = "images/colour-bar.svg";
inline const std::string CsvFile = "convergence.csv";
inline const std::string TimesCsvFile = "time_to_accuracy.csv";
inline const std::string ReferenceName = "reference";
// Crops are magnified this many times, nearest neighbour, so that every pixel stays visible.
inline constexpr int CropMagnification = 4;

// A crop region inside the image, numbered from 1 in the order of Comparison::crops.
struct NumberedCrop {
    int number = 0;
    CropRegion region;
};

// The names under which a comparison's images are written, and the crops that fit the image.
struct Layout {
    std::vector<std::string> run_names;  // one per run: its integrator, made safe and unique
    std::vector<NumberedCrop> crops;     // clipped to the image; empty ones left out
    int width = 0, height = 0;           // of every image
};

// The layout of `comparison`'s report (image size from the reference, else the first run).
Layout report_layout(const Comparison& comparison);

// "images/<name>.png", "images/<name>-error.png", "images/crop-<k>-<name>.png".
std::string image_file(const std::string& name);
std::string error_map_file(const std::string& name);
std::string crop_file(int number, const std::string& name);

// True when the report has a false-colour error map of `run`: measured against the reference, or
// else estimated from the run's variance (when it has one).
bool has_error_map(const Comparison& comparison, const IntegratorRun& run);

// The relMSE of a run as the report shows it: measured, or estimated when there is no reference.
double shown_relative_mse(const IntegratorRun& run);

// One cell of the metrics table: its text ("—" when there is no value) and whether it is the
// best of its column.
struct Cell {
    std::string text;
    bool best = false;
};

struct TableRow {
    std::string integrator;
    bool estimated = false;
    // The agreement tests say this run has not converged (unconverged_run): its error columns
    // are marked ‡, and none of its columns is starred, whatever its own estimate says.
    bool not_converged = false;
    std::vector<Cell> cells;  // one per MetricsTable::headers
};

struct MetricsTable {
    std::vector<std::string> headers;  // after the integrator column
    std::vector<TableRow> rows;
};

// The table: samples per pixel, wall time, MSE, relMSE, SSIM, efficiency. Best per column:
// lowest time (at equal samples only), MSE and relMSE; highest SSIM and efficiency (only when
// two runs or more have a value; a measured relMSE is never compared with an estimated one).
MetricsTable metrics_table(const Comparison& comparison);

// The run the agreement tests name as not converged (odd_one_out over the runs' pairwise
// agreements), if any: its own error estimate is contradicted, and it wins nothing.
std::optional<std::size_t> unconverged_run(const Comparison& comparison);

// The report's verdict in one or two sentences: which run has the lowest error (measured
// against the reference, else estimated, and then said to be so), by how much against the
// runner-up, what the number rests on (one run each), and which run was left out as not
// converged. Empty with fewer than two comparable runs.
std::string verdict(const Comparison& comparison);

// Times to reach each target relMSE: targets in the order the runs give them, and per run one
// text per target ("3.21 s (measured)", "41.2 s (along slope −1)", "> 10× budget (not
// measured)", "never (no checkpoint to read)", "—"), and the note that explains them.
struct AccuracyTable {
    std::vector<double> targets;
    std::vector<std::pair<std::string, std::vector<std::string>>> rows;
    std::string note;
};
AccuracyTable accuracy_table(const Comparison& comparison);

// The error of each run inside one crop against the reference: MSE and relMSE over the crop's
// pixels, best (lowest) marked; empty without a reference. It shows where each integrator
// wins, which one number for the whole image hides.
struct CropErrorTable {
    std::vector<Cell> mse;           // one per run
    std::vector<Cell> relative_mse;  // one per run
};
CropErrorTable crop_error_table(const Comparison& comparison, const CropRegion& region);

// Numbers as the report writes them: 4 significant digits (%.4g); "—" when negative (no value).
std::string format_number(double value);
// A slope with two decimals and a true minus sign: "−1.02".
std::string format_slope(double slope);
// A power of ten as a tick label: "1e-3", "1e-1", "1", "10", "1000", "1e4".
std::string decade_label(int exponent);
// A crop's place in words: "16 × 16 pixels at (40, 8), highest error".
std::string describe_crop(const NumberedCrop& crop);
// What a run's fit says: "slope −1.02 (95 %: −1.10 to −0.95) from 6 checkpoints", "no fit (2
// checkpoints, 4 needed)", and whether it is not −1 or, estimated, rises with time.
std::string describe_fit(const IntegratorRun& run);

// The header facts, as (label, value) pairs: scene, renderer, budget, reference, image size.
std::vector<std::pair<std::string, std::string>> header_facts(const Comparison& comparison, const Layout& layout);

// The "how to read this" paragraphs, plain text (no markup).
std::vector<std::string> how_to_read(const Comparison& comparison);

// What the integrators said about their runs (RenderResult warnings and notes: a Markov chain's
// acceptance rates, a scene whose light no path reaches), as "integrator: text" lines.
std::vector<std::string> integrator_notes(const Comparison& comparison);

// The caption of the error maps: what is mapped, and the bounds.
std::string error_map_caption(const Comparison& comparison);

// A scene's path shortened for titles: its file name and the folder holding it
// ("/home/me/scenes/cornell-box/scene.json" -> "cornell-box/scene.json").
std::string short_scene_name(const std::string& path);

// The report as Markdown (report_markdown.cpp), its images linked as files of the folder.
std::string comparison_markdown(const Comparison& comparison, const Layout& layout);

// The report as one self-contained HTML page (report_html.cpp), with the PNG files already written
// in `folder` embedded as data URIs.
std::string comparison_html(const Comparison& comparison, const Layout& layout, const std::string& folder);

}  // namespace freezeray::report
