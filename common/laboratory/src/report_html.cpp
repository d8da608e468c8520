// report.html: the comparison as one self-contained page. Every image is embedded as a base64
// data URI and the style is inline, so the page opens offline, from anywhere, on its own; the
// only script is three lines for click-to-zoom.
#include "freezeray/error.hpp"
#include "report_content.hpp"
#include "report_svg.hpp"

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace freezeray::report {

namespace {

// Base64 (RFC 4648, section 4): every 3 bytes become 4 characters of 6 bits each; the last group
// is padded with '='.
std::string base64(const std::vector<unsigned char>& bytes) {
    static const char alphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string text;
    text.reserve((bytes.size() + 2) / 3 * 4);
    for (std::size_t i = 0; i < bytes.size(); i += 3) {
        const std::size_t count = std::min<std::size_t>(3, bytes.size() - i);
        std::uint32_t group = std::uint32_t(bytes[i]) << 16;
        if (count > 1) group |= std::uint32_t(bytes[i + 1]) << 8;
        if (count > 2) group |= std::uint32_t(bytes[i + 2]);
        for (std::size_t k = 0; k < 4; ++k) text += k <= count ? alphabet[(group >> (18 - 6 * k)) & 63] : '=';
    }
    return text;
}

// The PNG file `file` of the report folder as a data URI; InputError if it cannot be read.
std::string png_data_uri(const std::string& folder, const std::string& file) {
    const std::string path = (std::filesystem::path(folder) / file).string();
    std::ifstream stream(path, std::ios::binary);
    std::vector<unsigned char> bytes;
    if (stream) bytes.assign(std::istreambuf_iterator<char>(stream), std::istreambuf_iterator<char>());
    if (bytes.empty()) throw InputError(path, "cannot read the image back to embed it in the report");
    return "data:image/png;base64," + base64(bytes);
}

const char* const Style = R"(<style>
body { font-family: system-ui, -apple-system, "Segoe UI", Helvetica, Arial, sans-serif; color: #222;
       max-width: 1150px; margin: 2em auto; padding: 0 1em; line-height: 1.45; }
h1 { font-size: 1.6em; } h2 { margin-top: 1.8em; border-bottom: 1px solid #ddd; } h3 { font-size: 1em; }
dl.facts { display: grid; grid-template-columns: max-content 1fr; gap: .2em 1em; } dt { font-weight: bold; }
table { border-collapse: collapse; margin: 1em 0; font-variant-numeric: tabular-nums; }
th, td { padding: .3em .8em; border-bottom: 1px solid #ddd; text-align: right; }
th:first-child, td:first-child { text-align: left; }
td.best { font-weight: bold; background: #eaf5ea; } .star { color: #b8860b; }
.swatch { display: inline-block; width: .75em; height: .75em; border-radius: 50%; margin-right: .4em; }
.gallery { display: grid; grid-template-columns: repeat(auto-fill, minmax(230px, 1fr)); gap: 1em; }
.crops { display: flex; flex-wrap: wrap; gap: 1em; } .crops img { min-width: 176px; height: auto; }
figure { margin: 0; } figcaption { font-size: .9em; color: #444; }
.frame { position: relative; line-height: 0; }
.gallery img { width: 100%; } img { image-rendering: pixelated; cursor: zoom-in; display: block; }
.crop-marks { position: absolute; inset: 0; width: 100%; height: 100%; pointer-events: none; }
img.zoomed { position: fixed; inset: 0; margin: auto; width: 94vw; height: 94vh; object-fit: contain;
             z-index: 10; background: #111; box-shadow: 0 0 0 100vmax rgba(0, 0, 0, .85); cursor: zoom-out; }
svg { max-width: 100%; height: auto; }
</style>
)";

std::string image_figure(const std::string& uri, const std::string& name, const std::string& caption,
                         const std::string& overlay = "") {
    return "<figure><div class=\"frame\"><img src=\"" + uri + "\" alt=\"" + escape_xml(name) + "\">" + overlay +
           "</div><figcaption><strong>" + escape_xml(name) + "</strong>" +
           (caption.empty() ? "" : "<br>" + escape_xml(caption)) + "</figcaption></figure>\n";
}

// Numbered rectangles over the first image, showing where the crops come from.
std::string crop_overlay(const Layout& layout) {
    if (layout.crops.empty()) return "";
    const int size = std::max(layout.width, layout.height);
    std::string svg = "<svg class=\"crop-marks\" viewBox=\"0 0 " + std::to_string(layout.width) + " " +
                      std::to_string(layout.height) + "\" preserveAspectRatio=\"none\">";
    for (const NumberedCrop& crop : layout.crops) {
        const CropRegion& r = crop.region;
        svg += "<rect x=\"" + std::to_string(r.x) + "\" y=\"" + std::to_string(r.y) + "\" width=\"" +
               std::to_string(r.width) + "\" height=\"" + std::to_string(r.height) +
               "\" fill=\"none\" stroke=\"#ff00ff\" stroke-width=\"2\" vector-effect=\"non-scaling-stroke\"/>";
        svg += "<text x=\"" + std::to_string(r.x) + "\" y=\"" + std::to_string(r.y) + "\" dy=\"-0.2em\" font-size=\"" +
               std::to_string(std::max(1, size / 12)) + "\" fill=\"#ff00ff\">" + std::to_string(crop.number) + "</text>";
    }
    return svg + "</svg>";
}

std::string facts_and_reading(const Comparison& comparison, const Layout& layout) {
    std::string html = "<dl class=\"facts\">\n";
    for (const auto& [label, value] : header_facts(comparison, layout)) {
        html += "<dt>" + escape_xml(label) + "</dt><dd>" + escape_xml(value) + "</dd>\n";
    }
    html += "</dl>\n<h2>How to read this</h2>\n";
    for (const std::string& paragraph : how_to_read(comparison)) html += "<p>" + escape_xml(paragraph) + "</p>\n";
    return html;
}

std::string metrics_section(const Comparison& comparison) {
    const MetricsTable table = metrics_table(comparison);
    std::string html = "<h2>Results</h2>\n";
    if (const std::string v = verdict(comparison); !v.empty())
        html += "<p class=\"verdict\"><strong>Verdict.</strong> " + escape_xml(v) + "</p>\n";
    html += "<table class=\"metrics\">\n<tr><th>integrator</th>";
    for (const std::string& header : table.headers) html += "<th>" + escape_xml(header) + "</th>";
    html += "</tr>\n";
    for (std::size_t i = 0; i < table.rows.size(); ++i) {
        const TableRow& row = table.rows[i];
        html += std::string("<tr") + (row.estimated ? " class=\"estimated\"" : "") +
                "><td><span class=\"swatch\" style=\"background:" + run_colour(i) + "\"></span>" +
                escape_xml(row.integrator) + "</td>";
        for (const Cell& cell : row.cells) {
            html += cell.best ? "<td class=\"best\">" + escape_xml(cell.text) + " <span class=\"star\">★</span></td>"
                              : "<td>" + escape_xml(cell.text) + "</td>";
        }
        html += "</tr>\n";
    }
    html += "</table>\n<p>★ the best of its column.";
    if (std::any_of(table.rows.begin(), table.rows.end(), [](const TableRow& r) { return r.not_converged; }))
        html += " ‡ the agreement tests say this run has not converged; its error is not what it estimates, and it is "
                "not ranked.";
    return html + "</p>\n";
}

std::string plot_and_accuracy(const Comparison& comparison, const Layout& layout) {
    std::string html = "<h2>Error versus time</h2>\n<div class=\"plot\">" +
                       convergence_plot_svg(comparison, SvgUse::InlineHtml) + "</div>\n<ul>\n";
    for (std::size_t i = 0; i < comparison.runs.size(); ++i) {
        html += "<li>" + escape_xml(layout.run_names[i]) + ": " + escape_xml(describe_fit(comparison.runs[i])) + "</li>\n";
    }
    html += "</ul>\n<p>Every checkpoint is in <code>" + CsvFile + "</code> beside this page, every time to accuracy in <code>" +
            TimesCsvFile + "</code>.</p>\n";

    const AccuracyTable table = accuracy_table(comparison);
    if (table.targets.empty()) return html;
    html += "<h2>Time to accuracy</h2>\n<table>\n<tr><th>integrator</th>";
    for (const double target : table.targets) html += "<th>relMSE " + escape_xml(format_number(target)) + "</th>";
    html += "</tr>\n";
    for (const auto& [integrator, times] : table.rows) {
        html += "<tr><td>" + escape_xml(integrator) + "</td>";
        for (const std::string& time : times) html += "<td>" + escape_xml(time) + "</td>";
        html += "</tr>\n";
    }
    return html + "</table>\n<p>" + escape_xml(table.note) + "</p>\n";
}

std::string images_section(const Comparison& comparison, const Layout& layout, const std::string& folder) {
    std::vector<std::string> names;
    std::string html = "<h2>Images</h2>\n<p>Click an image to magnify it.</p>\n<div class=\"gallery\">\n";
    if (comparison.reference) {
        names.push_back(ReferenceName);
        html += image_figure(png_data_uri(folder, image_file(ReferenceName)), ReferenceName,
                             comparison.reference_description, crop_overlay(layout));
    }
    for (std::size_t i = 0; i < comparison.runs.size(); ++i) {
        const IntegratorRun& run = comparison.runs[i];
        const std::string caption = std::to_string(run.result.samples_per_pixel) + " spp, " +
                                    format_number(run.result.seconds) + " s, relMSE " +
                                    format_number(shown_relative_mse(run)) + (run.error_is_estimated ? " (estimated)" : "");
        const std::string overlay = names.empty() ? crop_overlay(layout) : "";
        names.push_back(layout.run_names[i]);
        html += image_figure(png_data_uri(folder, image_file(names.back())), names.back(), caption, overlay);
    }
    html += "</div>\n";
    if (layout.crops.empty()) return html;
    html += "<h2>Crops</h2>\n<p>Magnified " + std::to_string(CropMagnification) +
            "×, nearest neighbour: every pixel is a square. The numbered boxes on the first image show where they are.</p>\n";
    for (const NumberedCrop& crop : layout.crops) {
        html += "<h3>" + escape_xml(describe_crop(crop)) + "</h3>\n<div class=\"crops\">\n";
        for (const std::string& name : names) {
            html += image_figure(png_data_uri(folder, crop_file(crop.number, name)), name, "");
        }
        html += "</div>\n";
        const CropErrorTable errors = crop_error_table(comparison, crop.region);
        if (errors.mse.empty()) continue;
        html += "<table>\n<tr><th>in this crop</th>";
        for (const std::string& name : layout.run_names) html += "<th>" + escape_xml(name) + "</th>";
        auto row = [&](const char* label, const std::vector<Cell>& cells) {
            html += std::string("</tr>\n<tr><td>") + label + "</td>";
            for (const Cell& cell : cells)
                html += cell.best ? "<td class=\"best\">" + escape_xml(cell.text) + " <span class=\"star\">★</span></td>"
                                  : "<td>" + escape_xml(cell.text) + "</td>";
        };
        row("MSE", errors.mse);
        row("relMSE", errors.relative_mse);
        html += "</tr>\n</table>\n";
    }
    return html;
}

std::string error_maps_section(const Comparison& comparison, const Layout& layout, const std::string& folder) {
    std::string figures;
    for (std::size_t i = 0; i < comparison.runs.size(); ++i) {
        if (!has_error_map(comparison, comparison.runs[i])) continue;
        const std::string& name = layout.run_names[i];
        figures += image_figure(png_data_uri(folder, error_map_file(name)), name, "");
    }
    if (figures.empty()) return "";
    return "<h2>Per-pixel relative error</h2>\n<p>" + escape_xml(error_map_caption(comparison)) +
           "</p>\n<div class=\"gallery\">\n" + figures + "</div>\n<div class=\"colour-bar\">" +
           colour_bar_svg(SvgUse::InlineHtml) + "</div>\n";
}

}  // namespace

std::string comparison_html(const Comparison& comparison, const Layout& layout, const std::string& folder) {
    const std::string title = "Comparison of integrators: " + short_scene_name(comparison.scene);
    std::string html = "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>" +
                       escape_xml(title) + "</title>\n" + Style + "</head>\n<body>\n<h1>" + escape_xml(title) + "</h1>\n";
    html += facts_and_reading(comparison, layout);
    html += metrics_section(comparison);
    if (const std::vector<std::string> notes = integrator_notes(comparison); !notes.empty()) {
        html += "<h2>Notes from the integrators</h2>\n<ul>\n";
        for (const std::string& line : notes) html += "<li>" + escape_xml(line) + "</li>\n";
        html += "</ul>\n";
    }
    html += plot_and_accuracy(comparison, layout);
    html += images_section(comparison, layout, folder);
    html += error_maps_section(comparison, layout, folder);
    html += "<footer><p>Colours: Okabe and Ito, “Color Universal Design” (2008); error maps: viridis (Smith and van "
            "der Walt, 2015).</p></footer>\n";
    html += "<script>\n// Click an image to see it magnified; click again to go back.\n"
            "for (const image of document.querySelectorAll(\"img\"))\n"
            "    image.addEventListener(\"click\", () => image.classList.toggle(\"zoomed\"));\n</script>\n";
    return html + "</body>\n</html>\n";
}

}  // namespace freezeray::report
