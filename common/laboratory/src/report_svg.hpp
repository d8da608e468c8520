// The two drawings of a comparison report, as SVG text: the log–log plot of error against time,
// and the colour bar of the false-colour error maps.
#pragma once

#include "freezeray/comparison.hpp"

#include <string>

namespace freezeray::report {

// A file of its own (with the SVG namespace declaration) or inline in an HTML page, whose parser
// puts <svg> in the SVG namespace by itself.
enum class SvgUse { File, InlineHtml };

// The error-versus-time plot, 800 x 500: one polyline with markers per run from its checkpoints
// (relMSE, or the estimated relMSE where there is no reference), its fitted line dashed, decade
// ticks, a legend with each integrator's slope.
std::string convergence_plot_svg(const Comparison& comparison, SvgUse use);

// The colour bar of the error maps: viridis from 1e-3 to 10 with a tick per decade.
std::string colour_bar_svg(SvgUse use);

// The colour of the i-th run in plots and tables: the Okabe–Ito palette.
std::string run_colour(std::size_t index);

// Text with &, <, >, " and ' escaped, for XML and HTML.
std::string escape_xml(const std::string& text);

}  // namespace freezeray::report
