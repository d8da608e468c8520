// The error-versus-time plot and the colour bar of a comparison report, written as SVG by hand:
// a few rectangles, lines and texts do not need a plotting library (see report_svg.hpp).
#include "report_svg.hpp"

#include "freezeray/false_colour.hpp"
#include "report_content.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>
#include <vector>

namespace freezeray::report {

namespace {

// The plot's canvas and the rectangle of its axes; the legend sits right of the axes.
constexpr double CanvasWidth = 960, CanvasHeight = 600;
constexpr double Left = 90, Right = 690, Top = 50, Bottom = 525;
constexpr double LegendX = 715;

// M. Okabe and K. Ito, "Color Universal Design (CUD): How to make figures and presentations that
// are friendly to colorblind people", 2008: eight colours that stay distinct for every common
// colour-vision deficiency. Ordered for contrast on white, so yellow comes last.
const char* const OkabeIto[] = {"#0072B2", "#D55E00", "#009E73", "#CC79A7",
                                "#E69F00", "#56B4E9", "#000000", "#F0E442"};

// A coordinate with one decimal, enough at this size.
std::string coordinate(double value) {
    char text[32];
    std::snprintf(text, sizeof(text), "%.1f", value);
    return text;
}

// The opening <svg> tag, with the namespace only for a file of its own.
std::string svg_open(SvgUse use, double width, double height, const std::string& label) {
    const std::string size = coordinate(width) + "\" height=\"" + coordinate(height);
    return std::string("<svg") + (use == SvgUse::File ? " xmlns=\"http://www.w3.org/2000/svg\"" : "") +
           " width=\"" + size + "\" viewBox=\"0 0 " + coordinate(width) + " " + coordinate(height) +
           "\" font-family=\"Helvetica, Arial, sans-serif\" role=\"img\" aria-label=\"" + escape_xml(label) +
           "\">\n<title>" + escape_xml(label) + "</title>\n";
}

std::string text_element(double x, double y, const std::string& text, const std::string& attributes = "") {
    return "<text x=\"" + coordinate(x) + "\" y=\"" + coordinate(y) + "\"" + attributes + ">" + escape_xml(text) +
           "</text>\n";
}

std::string line_element(double x1, double y1, double x2, double y2, const std::string& attributes) {
    return "<line x1=\"" + coordinate(x1) + "\" y1=\"" + coordinate(y1) + "\" x2=\"" + coordinate(x2) + "\" y2=\"" +
           coordinate(y2) + "\" " + attributes + "/>\n";
}

// A marker centred on (x, y); the shape changes with the run as well as the colour, so that
// lines stay apart in grey scale too: circle, square, triangle, diamond.
std::string marker(std::size_t index, double x, double y, const std::string& colour) {
    const std::string fill = " fill=\"" + colour + "\"/>\n";
    const double r = 4.5;
    switch (index % 4) {
    case 0: return "<circle cx=\"" + coordinate(x) + "\" cy=\"" + coordinate(y) + "\" r=\"" + coordinate(r) + "\"" + fill;
    case 1:
        return "<rect x=\"" + coordinate(x - r) + "\" y=\"" + coordinate(y - r) + "\" width=\"" + coordinate(2 * r) +
               "\" height=\"" + coordinate(2 * r) + "\"" + fill;
    case 2:
        return "<polygon points=\"" + coordinate(x) + "," + coordinate(y - 1.2 * r) + " " + coordinate(x + 1.1 * r) + "," +
               coordinate(y + 0.8 * r) + " " + coordinate(x - 1.1 * r) + "," + coordinate(y + 0.8 * r) + "\"" + fill;
    default:
        return "<polygon points=\"" + coordinate(x) + "," + coordinate(y - 1.3 * r) + " " + coordinate(x + 1.3 * r) + "," +
               coordinate(y) + " " + coordinate(x) + "," + coordinate(y + 1.3 * r) + " " + coordinate(x - 1.3 * r) + "," +
               coordinate(y) + "\"" + fill;
    }
}

// The whole decades [low, high] that hold every value (at least one decade; `fallback` if none).
std::pair<int, int> decade_range(const std::vector<double>& values, std::pair<int, int> fallback) {
    if (values.empty()) return fallback;
    const auto [smallest, largest] = std::minmax_element(values.begin(), values.end());
    const int low = static_cast<int>(std::floor(std::log10(*smallest) + 1e-9));
    int high = static_cast<int>(std::ceil(std::log10(*largest) - 1e-9));
    if (high <= low) high = low + 1;
    return {low, high};
}

// Log–log axes: from (seconds, relMSE) to canvas coordinates.
struct LogAxes {
    std::pair<int, int> x_decades, y_decades;
    double x(double seconds) const {
        return Left + (std::log10(seconds) - x_decades.first) / (x_decades.second - x_decades.first) * (Right - Left);
    }
    double y(double error) const {
        return Bottom - (std::log10(error) - y_decades.first) / (y_decades.second - y_decades.first) * (Bottom - Top);
    }
};

// Grid lines (decades dark, 2..9 light when there are few decades) and decade labels.
std::string grid_and_ticks(const LogAxes& axes) {
    std::string svg;
    const bool minor_x = axes.x_decades.second - axes.x_decades.first <= 6;
    const bool minor_y = axes.y_decades.second - axes.y_decades.first <= 6;
    for (int k = axes.x_decades.first; k <= axes.x_decades.second; ++k) {
        const double x = axes.x(std::pow(10.0, k));
        svg += line_element(x, Top, x, Bottom, "stroke=\"#cccccc\"");
        svg += line_element(x, Bottom, x, Bottom + 6, "stroke=\"#333333\"");
        svg += text_element(x, Bottom + 22, decade_label(k), " font-size=\"14\" text-anchor=\"middle\"");
        for (int m = 2; minor_x && m <= 9 && k < axes.x_decades.second; ++m) {
            const double xm = axes.x(m * std::pow(10.0, k));
            svg += line_element(xm, Top, xm, Bottom, "stroke=\"#eeeeee\"");
        }
    }
    for (int k = axes.y_decades.first; k <= axes.y_decades.second; ++k) {
        const double y = axes.y(std::pow(10.0, k));
        svg += line_element(Left, y, Right, y, "stroke=\"#cccccc\"");
        svg += line_element(Left - 6, y, Left, y, "stroke=\"#333333\"");
        svg += text_element(Left - 10, y + 5, decade_label(k), " font-size=\"14\" text-anchor=\"end\"");
        for (int m = 2; minor_y && m <= 9 && k < axes.y_decades.second; ++m) {
            const double ym = axes.y(m * std::pow(10.0, k));
            svg += line_element(Left, ym, Right, ym, "stroke=\"#eeeeee\"");
        }
    }
    return svg;
}

// A name short enough for the legend.
std::string legend_name(const std::string& name) {
    return name.size() <= 24 ? name : name.substr(0, 23) + "…";
}

}  // namespace

std::string run_colour(std::size_t index) { return OkabeIto[index % 8]; }

std::string escape_xml(const std::string& text) {
    std::string escaped;
    for (const char c : text) {
        switch (c) {
        case '&': escaped += "&amp;"; break;
        case '<': escaped += "&lt;"; break;
        case '>': escaped += "&gt;"; break;
        case '"': escaped += "&quot;"; break;
        case '\'': escaped += "&#39;"; break;
        default: escaped += c;
        }
    }
    return escaped;
}

std::string convergence_plot_svg(const Comparison& comparison, SvgUse use) {
    // The points of every run, and which kind of error they are.
    std::vector<std::vector<std::pair<double, double>>> series;
    std::vector<double> all_seconds, all_errors;
    bool any_measured = false, any_estimated = false;
    for (const IntegratorRun& run : comparison.runs) {
        series.emplace_back();
        for (const Checkpoint& checkpoint : run.checkpoints) {
            const double error = checkpoint_error(checkpoint, comparison.reference_relative_mse);
            if (!(error > 0.0 && checkpoint.seconds > 0.0) || !std::isfinite(error) || !std::isfinite(checkpoint.seconds)) {
                continue;
            }
            series.back().emplace_back(checkpoint.seconds, error);
            all_seconds.push_back(checkpoint.seconds);
            all_errors.push_back(error);
            if (checkpoint.relative_mse >= 0.0) {
                any_measured = true;
            } else {
                any_estimated = true;
            }
        }
    }
    const std::string quantity = any_estimated && !any_measured ? "estimated relMSE (no reference)"
                                 : any_estimated                ? "relMSE (estimated where no reference)"
                                                                : "relMSE";
    const LogAxes axes{decade_range(all_seconds, {-1, 1}), decade_range(all_errors, {-3, 0})};

    const std::string title = "Error versus time: " + short_scene_name(comparison.scene);
    std::string svg = svg_open(use, CanvasWidth, CanvasHeight, title + " (log–log)");
    svg += "<rect width=\"" + coordinate(CanvasWidth) + "\" height=\"" + coordinate(CanvasHeight) + "\" fill=\"#ffffff\"/>\n";
    svg += "<defs><clipPath id=\"plot-area\"><rect x=\"" + coordinate(Left) + "\" y=\"" + coordinate(Top) +
           "\" width=\"" + coordinate(Right - Left) + "\" height=\"" + coordinate(Bottom - Top) + "\"/></clipPath></defs>\n";
    svg += text_element((Left + Right) / 2, 30, title, " font-size=\"18\" font-weight=\"bold\" text-anchor=\"middle\"");
    svg += grid_and_ticks(axes);
    svg += "<rect x=\"" + coordinate(Left) + "\" y=\"" + coordinate(Top) + "\" width=\"" + coordinate(Right - Left) +
           "\" height=\"" + coordinate(Bottom - Top) + "\" fill=\"none\" stroke=\"#333333\"/>\n";
    svg += text_element((Left + Right) / 2, CanvasHeight - 22, "wall time (s)", " font-size=\"15\" text-anchor=\"middle\"");
    svg += text_element(0, 0, quantity + ", log scale",
                        " font-size=\"15\" text-anchor=\"middle\" transform=\"translate(22 " +
                            coordinate((Top + Bottom) / 2) + ") rotate(-90)\"");
    if (all_errors.empty()) {
        svg += text_element((Left + Right) / 2, (Top + Bottom) / 2, "no checkpoints to plot",
                            " font-size=\"16\" fill=\"#666666\" text-anchor=\"middle\"");
    }

    // One polyline with markers per run, and its fitted line dashed (clipped to the axes); behind
    // them a grey guide of slope -1, the unbiased rate, through the middle of the first run's
    // checkpoints, to hold each line against.
    svg += "<g clip-path=\"url(#plot-area)\">\n";
    const double floor = reference_floor(comparison.reference_relative_mse);
    if (floor > 0.0 && !all_errors.empty()) {
        // Below this line the reference's own noise hides the runs' errors.
        svg += line_element(Left, axes.y(floor), Right, axes.y(floor), "stroke=\"#b2182b\" stroke-width=\"1\"");
        svg += text_element(Right - 6, axes.y(floor) + 16, "reference too noisy below",
                            " font-size=\"12\" fill=\"#b2182b\" text-anchor=\"end\"");
    }
    for (const auto& points : series) {
        if (points.empty()) continue;
        const auto& [seconds, error] = points[points.size() / 2];
        const double left = std::pow(10.0, axes.x_decades.first), right = std::pow(10.0, axes.x_decades.second);
        svg += line_element(axes.x(left), axes.y(error * seconds / left), axes.x(right), axes.y(error * seconds / right),
                            "stroke=\"#999999\" stroke-width=\"1.5\" stroke-dasharray=\"2 4\"");
        break;
    }
    for (std::size_t i = 0; i < comparison.runs.size(); ++i) {
        const std::string colour = run_colour(i);
        const ConvergenceFit& fit = comparison.runs[i].fit;
        if (fit.points > 0 && !series[i].empty()) {
            // Over the checkpoints only: the fit describes the run, it does not extrapolate it.
            const double first = series[i].front().first, last = series[i].back().first;
            svg += line_element(axes.x(first), axes.y(fit.predict(first)), axes.x(last), axes.y(fit.predict(last)),
                                "stroke=\"" + colour + "\" stroke-width=\"1.5\" stroke-dasharray=\"7 5\"");
        }
        std::string points;
        for (const auto& [seconds, error] : series[i]) points += coordinate(axes.x(seconds)) + "," + coordinate(axes.y(error)) + " ";
        svg += "<polyline fill=\"none\" stroke=\"" + colour + "\" stroke-width=\"2\" points=\"" + points + "\"/>\n";
        for (const auto& [seconds, error] : series[i]) svg += marker(i, axes.x(seconds), axes.y(error), colour);
    }
    svg += "</g>\n";

    // The legend: a sample of each line with the integrator's name and its fitted slope.
    double y = Top + 12;
    for (std::size_t i = 0; i < comparison.runs.size(); ++i, y += 42) {
        const IntegratorRun& run = comparison.runs[i];
        svg += line_element(LegendX, y, LegendX + 30, y, "stroke=\"" + run_colour(i) + "\" stroke-width=\"2\"");
        svg += marker(i, LegendX + 15, y, run_colour(i));
        svg += text_element(LegendX + 38, y + 5, legend_name(run.integrator), " font-size=\"15\"");
        const std::string slope = run.fit.points > 0 ? "slope " + format_slope(run.fit.slope) +
                                                           (run.fit.disagrees_with_unbiased_rate() ? " (not −1)" : "")
                                                     : "no fit";
        svg += text_element(LegendX + 38, y + 23, slope, " font-size=\"13\" fill=\"#444444\"");
    }
    svg += line_element(LegendX, y, LegendX + 30, y, "stroke=\"#444444\" stroke-width=\"1.5\" stroke-dasharray=\"7 5\"");
    svg += text_element(LegendX + 38, y + 5, "robust fit", " font-size=\"13\" fill=\"#444444\"");
    y += 24;
    svg += line_element(LegendX, y, LegendX + 30, y, "stroke=\"#999999\" stroke-width=\"1.5\" stroke-dasharray=\"2 4\"");
    svg += text_element(LegendX + 38, y + 5, "slope −1: unbiased rate", " font-size=\"13\" fill=\"#444444\"");
    return svg + "</svg>\n";
}

std::string colour_bar_svg(SvgUse use) {
    constexpr double Width = 520, Height = 78, BarLeft = 30, BarRight = 490, BarTop = 8, BarBottom = 32;
    std::string svg = svg_open(use, Width, Height, "colour bar of the error maps: viridis from 1e-3 to 10, log scale");
    // 33 stops of the 256-entry table: between them the gradient interpolates as the table does.
    svg += "<defs><linearGradient id=\"viridis-scale\">\n";
    for (int i = 0; i <= 32; ++i) {
        svg += "<stop offset=\"" + coordinate(i / 32.0 * 100.0) + "%\" stop-color=\"" + viridis_hex(i / 32.0) + "\"/>\n";
    }
    svg += "</linearGradient></defs>\n";
    svg += "<rect x=\"" + coordinate(BarLeft) + "\" y=\"" + coordinate(BarTop) + "\" width=\"" +
           coordinate(BarRight - BarLeft) + "\" height=\"" + coordinate(BarBottom - BarTop) +
           "\" fill=\"url(#viridis-scale)\" stroke=\"#333333\"/>\n";
    const int lowest = static_cast<int>(std::lround(std::log10(FalseColourLowest)));
    const int highest = static_cast<int>(std::lround(std::log10(FalseColourHighest)));
    for (int k = lowest; k <= highest; ++k) {
        const double x = BarLeft + false_colour_position(std::pow(10.0, k)) * (BarRight - BarLeft);
        svg += line_element(x, BarBottom, x, BarBottom + 6, "stroke=\"#333333\"");
        svg += text_element(x, BarBottom + 22, decade_label(k), " font-size=\"14\" text-anchor=\"middle\"");
    }
    svg += text_element(Width / 2, Height - 4, "relative error per pixel (log scale)",
                        " font-size=\"13\" fill=\"#444444\" text-anchor=\"middle\"");
    return svg + "</svg>\n";
}

}  // namespace freezeray::report
