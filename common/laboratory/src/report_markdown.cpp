// report.md: the comparison as Markdown, readable as plain text and rendered by any Markdown
// viewer. Images are links to the files in images/; the best value of a column is in bold.
#include "report_content.hpp"

#include <algorithm>

#include <string>
#include <vector>

namespace freezeray::report {

namespace {

// Text safe inside a table cell: a '|' would end the cell.
std::string cell_text(const std::string& text) {
    std::string escaped;
    for (const char c : text) escaped += c == '|' ? std::string("\\|") : std::string(1, c);
    return escaped;
}

// One table row: "| a | b | c |".
std::string table_row(const std::vector<std::string>& cells) {
    std::string row = "|";
    for (const std::string& cell : cells) row += " " + cell + " |";
    return row + "\n";
}

// The line under a table's header: the first column left-aligned, the others as given.
std::string table_rule(std::size_t columns, const std::string& alignment) {
    std::vector<std::string> cells = {":--"};
    for (std::size_t i = 1; i < columns; ++i) cells.push_back(alignment);
    return table_row(cells);
}

std::string image_link(const std::string& alt, const std::string& file) { return "![" + cell_text(alt) + "](" + file + ")"; }

std::string metrics_section(const Comparison& comparison) {
    const MetricsTable table = metrics_table(comparison);
    std::vector<std::string> header = {"integrator"};
    header.insert(header.end(), table.headers.begin(), table.headers.end());
    std::string text = "## Results\n\n";
    if (const std::string v = verdict(comparison); !v.empty()) text += "**Verdict.** " + v + "\n\n";
    text += table_row(header) + table_rule(header.size(), "--:");
    for (const TableRow& row : table.rows) {
        std::vector<std::string> cells = {cell_text(row.integrator)};
        for (const Cell& cell : row.cells) cells.push_back(cell.best ? "**" + cell.text + "**" : cell.text);
        text += table_row(cells);
    }
    text += "\n**Bold**: the best of its column.";
    if (std::any_of(table.rows.begin(), table.rows.end(), [](const TableRow& r) { return r.not_converged; }))
        text += " ‡: the agreement tests say this run has not converged; its error is not what it estimates, and it "
                "is not ranked.";
    return text + "\n\n";
}

std::string plot_section(const Comparison& comparison, const Layout& layout) {
    std::string text = "## Error versus time\n\n" + image_link("relMSE against wall time, log–log", PlotFile) + "\n\n";
    for (std::size_t i = 0; i < comparison.runs.size(); ++i) {
        text += "- " + layout.run_names[i] + ": " + describe_fit(comparison.runs[i]) + "\n";
    }
    return text + "\nEvery checkpoint (time, samples per pixel, errors) is in [" + CsvFile + "](" + CsvFile +
           "), one row per checkpoint, numbered from 1; every time to accuracy, the extrapolated ones as numbers "
           "too, in [" + TimesCsvFile + "](" + TimesCsvFile + ").\n\n";
}

std::string accuracy_section(const Comparison& comparison) {
    const AccuracyTable table = accuracy_table(comparison);
    if (table.targets.empty()) return "";
    std::vector<std::string> header = {"integrator"};
    for (const double target : table.targets) header.push_back("relMSE " + format_number(target));
    std::string text = "## Time to accuracy\n\n" + table_row(header) + table_rule(header.size(), "--:");
    for (const auto& [integrator, times] : table.rows) {
        std::vector<std::string> cells = {cell_text(integrator)};
        cells.insert(cells.end(), times.begin(), times.end());
        text += table_row(cells);
    }
    return text + "\n" + table.note + "\n\n";
}

// One row of images: a header with the names, then the images.
std::string image_row(const std::vector<std::string>& names, const std::vector<std::string>& files) {
    std::vector<std::string> header, images;
    for (std::size_t i = 0; i < names.size(); ++i) {
        header.push_back(cell_text(names[i]));
        images.push_back(image_link(names[i], files[i]));
    }
    std::string rule = "|";
    for (std::size_t i = 0; i < names.size(); ++i) rule += " :-: |";
    return table_row(header) + rule + "\n" + table_row(images) + "\n";
}

std::string images_section(const Comparison& comparison, const Layout& layout) {
    std::vector<std::string> names, files;
    if (comparison.reference) {
        names.push_back(ReferenceName);
        files.push_back(image_file(ReferenceName));
    }
    for (const std::string& name : layout.run_names) {
        names.push_back(name);
        files.push_back(image_file(name));
    }
    std::string text = "## Images\n\n" + image_row(names, files);
    if (layout.crops.empty()) return text;
    text += "## Crops\n\nMagnified " + std::to_string(CropMagnification) + "×, nearest neighbour: every pixel is a " +
            std::to_string(CropMagnification) + "×" + std::to_string(CropMagnification) + " square.\n\n";
    for (const NumberedCrop& crop : layout.crops) {
        std::vector<std::string> crop_files;
        for (const std::string& name : names) crop_files.push_back(crop_file(crop.number, name));
        text += "### " + describe_crop(crop) + "\n\n" + image_row(names, crop_files);
        const CropErrorTable errors = crop_error_table(comparison, crop.region);
        if (errors.mse.empty()) continue;
        text += "| in this crop |";
        for (const std::string& name : layout.run_names) text += " " + name + " |";
        text += "\n| :-- |";
        for (std::size_t i = 0; i < layout.run_names.size(); ++i) text += " --: |";
        text += "\n| MSE |";
        for (const Cell& cell : errors.mse) text += " " + (cell.best ? "**" + cell.text + "**" : cell.text) + " |";
        text += "\n| relMSE |";
        for (const Cell& cell : errors.relative_mse) text += " " + (cell.best ? "**" + cell.text + "**" : cell.text) + " |";
        text += "\n\n";
    }
    return text;
}

std::string error_maps_section(const Comparison& comparison, const Layout& layout) {
    std::vector<std::string> names, files;
    for (std::size_t i = 0; i < comparison.runs.size(); ++i) {
        if (!has_error_map(comparison, comparison.runs[i])) continue;
        names.push_back(layout.run_names[i]);
        files.push_back(error_map_file(layout.run_names[i]));
    }
    if (names.empty()) return "";
    return "## Per-pixel relative error\n\n" + error_map_caption(comparison) + "\n\n" + image_row(names, files) +
           image_link("colour bar: 1e-3 to 10, log scale", ColourBarFile) + "\n\n";
}

}  // namespace

std::string comparison_markdown(const Comparison& comparison, const Layout& layout) {
    std::string text = "# Comparison of integrators: " + short_scene_name(comparison.scene) + "\n\n";
    for (const auto& [label, value] : header_facts(comparison, layout)) text += "- **" + label + ":** " + value + "\n";
    text += "\n## How to read this\n\n";
    for (const std::string& paragraph : how_to_read(comparison)) text += paragraph + "\n\n";
    text += metrics_section(comparison);
    if (const std::vector<std::string> notes = integrator_notes(comparison); !notes.empty()) {
        text += "## Notes from the integrators\n\n";
        for (const std::string& line : notes) text += "- " + line + "\n";
        text += "\n";
    }
    text += plot_section(comparison, layout);
    text += accuracy_section(comparison);
    text += images_section(comparison, layout);
    text += error_maps_section(comparison, layout);
    return text;
}

}  // namespace freezeray::report
