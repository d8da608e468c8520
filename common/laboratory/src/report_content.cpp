// What a comparison report says, whatever its format (see report_content.hpp).
#include "report_content.hpp"

#include "freezeray/metrics.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <set>

namespace freezeray::report {

namespace {

// A name that is safe as a file name on every system: letters, digits, '-', '_' and '.' kept,
// anything else replaced by '-'; never empty, never hidden.
std::string safe_file_name(const std::string& name) {
    std::string safe;
    for (const char c : name) {
        const bool keep = std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == '.';
        safe += keep ? c : '-';
    }
    if (safe.empty() || safe.front() == '.') safe = "run" + safe;
    return safe;
}

// A value the table can show: finite and not negative (negative means "none").
bool has_value(double value) { return std::isfinite(value) && value >= 0.0; }

// Which way a column is better.
enum class Better { Nowhere, Lower, Higher };

}  // namespace

Layout report_layout(const Comparison& comparison) {
    Layout layout;
    std::set<std::string> taken = {ReferenceName};
    for (const IntegratorRun& run : comparison.runs) {
        const std::string base = safe_file_name(run.integrator);
        std::string name = base;
        for (int copy = 2; taken.count(name) > 0; ++copy) name = base + "-" + std::to_string(copy);
        taken.insert(name);
        layout.run_names.push_back(name);
    }
    if (comparison.reference) {
        layout.width = comparison.reference->width();
        layout.height = comparison.reference->height();
    } else if (!comparison.runs.empty()) {
        layout.width = comparison.runs.front().result.image.width();
        layout.height = comparison.runs.front().result.image.height();
    }
    for (std::size_t i = 0; i < comparison.crops.size(); ++i) {
        const CropRegion& crop = comparison.crops[i];
        const int x0 = std::max(crop.x, 0), y0 = std::max(crop.y, 0);
        const int x1 = std::min(crop.x + crop.width, layout.width), y1 = std::min(crop.y + crop.height, layout.height);
        if (x1 <= x0 || y1 <= y0) continue;
        layout.crops.push_back({static_cast<int>(i) + 1, CropRegion{x0, y0, x1 - x0, y1 - y0, crop.reason}});
    }
    return layout;
}

std::string image_file(const std::string& name) { return "images/" + name + ".png"; }
std::string error_map_file(const std::string& name) { return "images/" + name + "-error.png"; }
std::string crop_file(int number, const std::string& name) {
    return "images/crop-" + std::to_string(number) + "-" + name + ".png";
}

bool has_error_map(const Comparison& comparison, const IntegratorRun& run) {
    if (comparison.reference) return true;
    const Image& variance = run.result.variance;
    return variance.pixel_count() > 0 && variance.width() == run.result.image.width() &&
           variance.height() == run.result.image.height();
}

// Estimated: the render's own estimate, else the last checkpoint's.
double shown_relative_mse(const IntegratorRun& run) {
    if (!run.error_is_estimated) return run.relative_mse;
    if (run.result.estimated_relative_mse >= 0.0 || run.checkpoints.empty()) return run.result.estimated_relative_mse;
    return run.checkpoints.back().estimated_relative_mse;
}

MetricsTable metrics_table(const Comparison& comparison) {
    MetricsTable table;
    table.headers = {"samples per pixel", "wall time (s)", "MSE", "relMSE", "SSIM", "efficiency 1/(relMSE·s)"};
    // At equal time every run took (about) the budget: its time is not a result, so not ranked.
    const Better time_better = comparison.equal_time ? Better::Nowhere : Better::Lower;
    const Better better[] = {Better::Nowhere, time_better, Better::Lower, Better::Lower, Better::Higher, Better::Higher};
    const bool compares_error[] = {false, false, false, true, false, true};  // measured and estimated differ

    std::vector<std::vector<double>> values;  // per row, per column; negative: none
    const std::optional<std::size_t> unconverged = unconverged_run(comparison);
    for (const IntegratorRun& run : comparison.runs) {
        const double seconds = run.result.seconds;
        const double relative = shown_relative_mse(run);
        double efficiency = run.efficiency;
        if (!has_value(efficiency) && relative > 0.0 && seconds > 0.0) efficiency = 1.0 / (relative * seconds);
        // Below the reference's floor the relMSE (and so the efficiency) is not known, only bounded.
        const double floor = reference_floor(comparison.reference_relative_mse);
        const bool below_floor = !run.error_is_estimated && floor > 0.0 && run.relative_mse < floor;
        values.push_back({static_cast<double>(run.result.samples_per_pixel), seconds,
                          run.error_is_estimated ? -1.0 : run.mse, below_floor ? -1.0 : relative,
                          run.error_is_estimated ? -1.0 : run.ssim, below_floor ? -1.0 : efficiency});
        TableRow row;
        row.integrator = run.integrator;
        row.estimated = run.error_is_estimated;
        row.not_converged = unconverged && *unconverged == table.rows.size();
        for (std::size_t column = 0; column < values.back().size(); ++column) {
            const double value = values.back()[column];
            std::string text = column == 0 ? std::to_string(run.result.samples_per_pixel) : format_number(value);
            if (column == 3 && run.error_is_estimated && has_value(value)) text += " (estimated)";
            if (column == 3 && below_floor) text = "< " + format_number(floor) + " †";
            if (column == 5 && below_floor && seconds > 0.0) text = "> " + format_number(1.0 / (floor * seconds)) + " †";
            if (row.not_converged && column >= 2 && has_value(value)) text += " ‡";
            row.cells.push_back({text, false});
        }
        table.rows.push_back(row);
    }

    const bool any_measured = std::any_of(comparison.runs.begin(), comparison.runs.end(),
                                          [](const IntegratorRun& run) { return !run.error_is_estimated; });
    for (std::size_t column = 0; column < table.headers.size(); ++column) {
        if (better[column] == Better::Nowhere) continue;
        std::vector<std::size_t> candidates;
        for (std::size_t row = 0; row < table.rows.size(); ++row) {
            const bool comparable = (!compares_error[column] || !any_measured || !table.rows[row].estimated) &&
                                    !table.rows[row].not_converged;  // ‡ wins nothing
            if (comparable && has_value(values[row][column])) candidates.push_back(row);
        }
        if (candidates.size() < 2) continue;
        double best = values[candidates.front()][column];
        for (const std::size_t row : candidates) {
            const double value = values[row][column];
            best = better[column] == Better::Lower ? std::min(best, value) : std::max(best, value);
        }
        for (const std::size_t row : candidates) {
            if (values[row][column] == best) table.rows[row].cells[column].best = true;
        }
    }
    return table;
}

AccuracyTable accuracy_table(const Comparison& comparison) {
    AccuracyTable table;
    for (const IntegratorRun& run : comparison.runs) {
        for (const TimeToAccuracy& time : run.time_to_accuracy) {
            if (std::find(table.targets.begin(), table.targets.end(), time.target) == table.targets.end()) {
                table.targets.push_back(time.target);
            }
        }
    }
    for (const IntegratorRun& run : comparison.runs) {
        std::vector<std::string> texts;
        for (const double target : table.targets) {
            const auto time = std::find_if(run.time_to_accuracy.begin(), run.time_to_accuracy.end(),
                                           [&](const TimeToAccuracy& t) { return t.target == target; });
            if (time != run.time_to_accuracy.end() && time->below_reference_floor) {
                texts.push_back("† reference too noisy");
            } else if (time == run.time_to_accuracy.end() || std::isnan(time->seconds)) {
                texts.push_back("—");
            } else if (time->measured) {
                texts.push_back(format_number(time->seconds) + " s (measured)");
            } else if (!(time->slope < 0.0) && !std::isfinite(time->seconds)) {
                texts.push_back("not reached; its error does not fall");
            } else if (std::isinf(time->seconds)) {
                texts.push_back("not reached; no checkpoint to read");
            } else if (time->beyond_limit) {
                texts.push_back("not reached within the run; beyond " + format_number(TimeToAccuracy::ExtrapolationLimit) +
                                "× its time not estimated");
            } else {
                texts.push_back(format_number(time->seconds) + " s (along its slope " + format_slope(time->slope) + ")");
            }
        }
        table.rows.emplace_back(run.integrator, texts);
    }
    table.note = "Measured: the run reached the target (interpolated between the checkpoints around it). Along its "
                 "slope: read forward from where the run ended, along the slope fitted to its passes (−1, the rate "
                 "of an unbiased estimator, when there is no fit), and given as a number only up to " +
                 format_number(TimeToAccuracy::ExtrapolationLimit) + "× the run's time; further out it is not estimated.";
    return table;
}

std::string format_number(double value) {
    if (!has_value(value)) return "—";
    char text[32];
    std::snprintf(text, sizeof(text), "%.4g", value);
    return text;
}

std::string format_slope(double slope) {
    char text[32];
    std::snprintf(text, sizeof(text), "%.2f", std::abs(slope));
    return (slope < 0.0 && std::string(text) != "0.00" ? "−" : "") + std::string(text);
}

std::string decade_label(int exponent) {
    if (exponent >= 0 && exponent <= 3) return std::to_string(static_cast<int>(std::lround(std::pow(10.0, exponent))));
    return "1e" + std::to_string(exponent);
}

std::string describe_crop(const NumberedCrop& crop) {
    const CropRegion& r = crop.region;
    std::string text = "crop " + std::to_string(crop.number) + ": " + std::to_string(r.width) + " × " +
                       std::to_string(r.height) + " pixels at (" + std::to_string(r.x) + ", " + std::to_string(r.y) + ")";
    return r.reason.empty() ? text : text + ", " + r.reason;
}

std::string describe_fit(const IntegratorRun& run) {
    const ConvergenceFit& fit = run.fit;
    if (fit.points == 0) return "no fit (" + fit.no_fit_reason + ")";
    // An estimated error that grows with time: paths bright and rare enough to raise the variance
    // are still being found, and until they stop the estimate is too low.
    if (run.error_is_estimated && fit.slope > 0.0)
        return "slope " + format_slope(fit.slope) + " from " + std::to_string(fit.points) +
               " checkpoints: the estimated error rises with time, so it is not yet reliable (rare bright paths are "
               "still being found; the estimate is too low until they stop)";
    if (!fit.has_interval())
        return "slope " + format_slope(fit.slope) + " from " + std::to_string(fit.points) +
               " checkpoints (no interval: they share their samples)";
    std::string text = "slope " + format_slope(fit.slope) + " (95 %: " + format_slope(fit.slope_low) + " to " +
                       format_slope(fit.slope_high) + ") from " + std::to_string(fit.points) + " passes";
    if (fit.disagrees_with_unbiased_rate())
        text += "; not −1, the unbiased rate: fireflies still being found, bias, or a reference not converged";
    return text;
}

std::vector<std::pair<std::string, std::string>> header_facts(const Comparison& comparison, const Layout& layout) {
    std::string reference = "none: every error is estimated from the render's own per-pixel variance, which cannot "
                            "see what a render has not found yet (rare bright paths) nor bias";
    if (comparison.reference) {
        reference = comparison.reference_description.empty() ? "given" : comparison.reference_description;
        if (comparison.reference_relative_mse > 0.0)
            reference += "; its own estimated relMSE " + format_number(comparison.reference_relative_mse) +
                         " is subtracted from every relMSE measured against it, and it is too noisy for errors below " +
                         format_number(reference_floor(comparison.reference_relative_mse)) + " (marked †)";
        else
            reference += "; its header does not give its own error, so the errors below include its noise";
    }
    return {{"Scene", comparison.scene},
            {"Renderer", comparison.renderer},
            {"Budget", comparison.budget},
            {"Reference", reference},
            {"Image", std::to_string(layout.width) + " × " + std::to_string(layout.height) + " pixels"}};
}

std::vector<std::string> how_to_read(const Comparison& comparison) {
    std::vector<std::string> paragraphs = {
        "Every integrator rendered the same scene with the same budget (" + comparison.budget +
            "), so their errors compare directly: at equal time, the one with the lower error is the better "
            "method for this scene.",
        "relMSE is the mean over pixels and channels of (x − r)² / (r² + 0.01): the squared error relative to "
        "the reference's brightness (Rousselle, Knaus and Zwicker 2011). Efficiency is 1 / (relMSE × time). "
        "The relMSE of an unbiased estimator falls like 1 / time, so its efficiency does not depend on how long "
        "it ran: an integrator twice as efficient reaches the same error in half the time.",
        "On the log–log plot of error against time, an unbiased estimator's line is straight with slope −1: "
        "the MSE halves when the time doubles (the grey guide). The dashed lines are robust fits (Theil–Sen: the "
        "median of the slopes between pairs of points) to each pass's own samples, whose errors are independent "
        "(the checkpoints' are not: each image holds the samples of the one before), against the pass's own time "
        "— a pass of d seconds has the error a whole render of d seconds would have, so the line it gives runs "
        "through the checkpoints; at least 4 passes spanning at least 4× in time; from 6 passes on, the table gives "
        "each slope's 95 % interval (fewer give intervals too wide to say anything); a slope whose interval excludes −1 shows fireflies "
        "still being found, bias, or a reference that is itself not converged. "
        "Time to accuracy reads the curves at a target error: measured when the run got there, else read along "
        "its fitted slope from where it ended, and given as a number only up to 10× the run's time.",
        std::string("Best in each column is marked: ") + (comparison.equal_time ? "" : "lowest time, ") +
            "lowest MSE and relMSE; highest SSIM (structural similarity, 1 is identical) and efficiency."};
    if (!comparison.reference) {
        paragraphs.push_back(
            "There is no reference: each relMSE is estimated from the render's own per-pixel variance, which "
            "assumes the integrator is unbiased and cannot see bias. MSE and SSIM need a reference and are left out.");
    }
    return paragraphs;
}

std::string error_map_caption(const Comparison& comparison) {
    const std::string scale = ", averaged over R, G and B, on a log scale from 1e-3 (dark) to 10 (bright); the "
                              "same scale for every integrator (viridis, Smith and van der Walt 2015).";
    if (comparison.reference) return "Per-pixel relative error |x − r| / (|r| + 0.01)" + scale;
    return "Per-pixel estimated relative error √variance / (|x| + 0.01), from each render's own variance" + scale +
           " Grey: unknown, a black pixel with no variance beside lit ones (no light found there yet).";
}

std::string short_scene_name(const std::string& path) {
    const std::filesystem::path file(path);
    const std::string folder = file.parent_path().filename().string();
    const std::string name = file.filename().string();
    if (name.empty()) return path;
    return folder.empty() || folder == "." || folder == ".." ? name : folder + "/" + name;
}

CropErrorTable crop_error_table(const Comparison& comparison, const CropRegion& region) {
    CropErrorTable table;
    if (!comparison.reference) return table;
    auto crop = [&](const Image& image) {
        Image part(region.width, region.height);
        for (int y = 0; y < region.height; ++y)
            for (int x = 0; x < region.width; ++x) part.at(x, y) = image.at(region.x + x, region.y + y);
        return part;
    };
    const Image reference = crop(*comparison.reference);
    std::vector<double> mse_values, relative_values;
    for (const IntegratorRun& run : comparison.runs) {
        const Image part = crop(run.result.image);
        mse_values.push_back(mse(part, reference));
        relative_values.push_back(relative_mse(part, reference));
    }
    auto cells = [&](const std::vector<double>& values) {
        std::vector<Cell> row;
        const auto best = std::min_element(values.begin(), values.end());
        for (std::size_t i = 0; i < values.size(); ++i)
            row.push_back({format_number(values[i]), values.size() > 1 && values[i] == *best});
        return row;
    };
    table.mse = cells(mse_values);
    table.relative_mse = cells(relative_values);
    return table;
}

std::optional<std::size_t> unconverged_run(const Comparison& comparison) {
    return odd_one_out(comparison.agreements, comparison.runs.size());
}

std::string verdict(const Comparison& comparison) {
    const std::optional<std::size_t> unconverged = unconverged_run(comparison);
    const bool any_measured = std::any_of(comparison.runs.begin(), comparison.runs.end(),
                                          [](const IntegratorRun& run) { return !run.error_is_estimated; });
    const double floor = reference_floor(comparison.reference_relative_mse);
    std::vector<std::size_t> candidates;  // comparable runs with an error, best first
    for (std::size_t i = 0; i < comparison.runs.size(); ++i) {
        const IntegratorRun& run = comparison.runs[i];
        if (unconverged && *unconverged == i) continue;
        if (any_measured && run.error_is_estimated) continue;
        if (!(shown_relative_mse(run) > 0.0)) continue;
        candidates.push_back(i);
    }
    std::string left_out;
    if (unconverged)
        left_out = " " + comparison.runs[*unconverged].integrator +
                   " is left out: its images disagree with every other run's far beyond their noise, so its own "
                   "error estimate cannot be trusted (it has not converged).";
    if (candidates.size() < 2) return left_out.empty() ? "" : "No verdict:" + left_out;
    std::sort(candidates.begin(), candidates.end(), [&](std::size_t a, std::size_t b) {
        return shown_relative_mse(comparison.runs[a]) < shown_relative_mse(comparison.runs[b]);
    });
    const IntegratorRun& first = comparison.runs[candidates[0]];
    const IntegratorRun& second = comparison.runs[candidates[1]];
    const double a = shown_relative_mse(first), b = shown_relative_mse(second);
    const std::string how = comparison.equal_time ? "at equal time" : "at equal samples";
    std::string text;
    if (floor > 0.0 && b < floor) {
        text = "No winner can be named: " + first.integrator + " and " + second.integrator +
               " both lie below what the reference can measure (relMSE " + format_number(floor) + ").";
    } else {
        const double ratio = b / a;
        char sentence[400];
        std::snprintf(sentence, sizeof sentence, "%s has the lowest relMSE %s: %s against %s's %s, %.3g× lower%s.",
                      first.integrator.c_str(), how.c_str(),
                      (floor > 0.0 && a < floor ? "< " + format_number(floor) : format_number(a)).c_str(),
                      second.integrator.c_str(), format_number(b).c_str(), ratio,
                      floor > 0.0 && a < floor ? " at least (the reference cannot measure below its floor)" : "");
        text = sentence;
        if (ratio < 1.5)
            text += " That is within what a second run with another seed could reverse: one run each is no measure "
                    "of the spread; repeat with other --seed values before calling it.";
        else
            text += " Each number is one run; other --seed values show the spread.";
    }
    if (!any_measured)
        text += " The errors are estimated from each run's own per-pixel variance, which sees no light a run has not "
                "found yet: check against a --reference.";
    return text + left_out;
}

std::vector<std::string> integrator_notes(const Comparison& comparison) {
    std::vector<std::string> lines;
    for (const IntegratorRun& run : comparison.runs) {
        for (const std::string& warning : run.result.warnings) lines.push_back(run.integrator + ": warning: " + warning);
        for (const std::string& note : run.result.notes)  // notes that name their integrator already keep their text
            lines.push_back(note.rfind(run.integrator + ":", 0) == 0 ? note : run.integrator + ": " + note);
    }
    // Every pair of runs: do their images agree within their own noise (pairwise_agreements, in
    // run_comparison)? Without a reference this is the one check that sees what a run has not
    // found yet.
    const std::size_t n = comparison.runs.size();
    for (const RunAgreement& pair : comparison.agreements) {
        if (pair.first >= n || pair.second >= n) continue;
        const IntegratorRun &a = comparison.runs[pair.first], &b = comparison.runs[pair.second];
        const Agreement& agree = pair.agreement;
        char text[320];
        std::snprintf(text, sizeof text,
                      "their relMSE against each other is %.3g times the sum of their own estimates (about 1 ± %.2g "
                      "if both had converged)",
                      agree.statistic, agree.standard_error);
        std::string line = a.integrator + " and " + b.integrator + ": ";
        if (agree.disagree()) {
            line += "disagree beyond their combined noise, so at least one of them has not converged: ";
            line += text;
            if (agree.one_sided > 0)
                line += "; " + std::to_string(agree.one_sided) + " pixel-channels are lit in one and black with no variance in the other";
        } else if (agree.statistic < 1.0 - 6.0 * agree.standard_error) {
            // Far closer than independent noise allows: they drew the same random numbers.
            line += "agree more closely than independent renders could (" + std::string(text) +
                    "): they share their random numbers (the same seed), so this says little";
        } else {
            line += "agree within their noise: " + std::string(text);
        }
        lines.push_back(line);
    }
    // Which one has not converged: a run at odds with every other, when those agree among themselves.
    if (const std::optional<std::size_t> odd = odd_one_out(comparison.agreements, n))
        lines.push_back(comparison.runs[*odd].integrator + " disagrees with every other run, far more than they disagree "
                                                           "among themselves: it is the one that has not converged");
    return lines;
}

}  // namespace freezeray::report
