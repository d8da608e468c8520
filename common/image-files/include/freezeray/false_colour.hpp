// False-colour maps of per-pixel error: viridis on a log scale between fixed bounds, so that the
// maps of different integrators (and of different reports) can be compared by eye. The viridis
// map itself serves other per-pixel quantities too (chapter 06's images of traversal work).
#pragma once

#include "freezeray/image.hpp"

#include <string>

namespace freezeray {

// The bounds of the log scale: an error at or below the lowest gets the dark end of the map, one
// at or above the highest its bright end. Four decades cover "invisible" to "completely wrong".
inline constexpr double FalseColourLowest = 1e-3;
inline constexpr double FalseColourHighest = 10.0;

// Viridis at t in [0, 1] (clamped), as sRGB-encoded components in [0, 1].
Spectrum viridis_srgb(double t);

// The linear RGB whose sRGB encoding is viridis at t: what an Image holds for write_image to
// show the colour.
Spectrum viridis_linear(double t);

// The same colour as "#rrggbb", for SVG and CSS.
std::string viridis_hex(double t);

// Where a relative error falls on the map, in [0, 1]: log10 between the bounds, clamped (zero
// error gives 0, NaN gives 1 so that it stands out).
double false_colour_position(double relative_error);

// The per-pixel relative error |x - r| / (|r| + 1e-2), averaged over the three channels.
double pixel_relative_error(const Spectrum& pixel, const Spectrum& reference);

// The false-colour map of `image`'s relative error against `reference` (same size). Its pixels are
// linear RGB, so that write_image's sRGB encoding gives back the viridis colours.
Image relative_error_map(const Image& image, const Image& reference);

// Without a reference: the false-colour map of each pixel's standard error relative to its value,
// sqrt(variance) / (|x| + 1e-2), averaged over channels (`variance` is the variance of the mean).
// A pixel that is black with zero variance while a neighbour is lit has found no light yet: its
// variance says nothing of its error, and it is painted UnknownErrorColour, not as exact.
Image estimated_error_map(const Image& image, const Image& variance);

// The colour of a pixel whose estimated error is unknown (a mid grey, which viridis never takes).
inline const Spectrum UnknownErrorColour{0.2140f, 0.2140f, 0.2140f};  // sRGB 128

}  // namespace freezeray
