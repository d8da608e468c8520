// Image error metrics, all on linear radiance, averaged over pixels and the three channels.
#pragma once

#include "freezeray/image.hpp"

namespace freezeray {

// The epsilon of relMSE: keeps the error of near-black pixels from dominating. 1e-2 as in
// Rousselle, Knaus and Zwicker, "Adaptive Sampling and Reconstruction using Greedy Error
// Minimization", 2011 (and Bitterli's benchmark scenes).
inline constexpr double RelativeMseEpsilon = 1e-2;

// Mean squared error.
double mse(const Image& image, const Image& reference);
// Relative MSE: mean of (x - r)^2 / (r^2 + epsilon).
double relative_mse(const Image& image, const Image& reference, double epsilon = RelativeMseEpsilon);
// Root mean squared error.
double rmse(const Image& image, const Image& reference);
// Peak signal-to-noise ratio in dB for a given peak value: 10 log10(peak^2 / MSE).
double psnr(const Image& image, const Image& reference, double peak = 1.0);
// Mean absolute percentage error: mean of |x - r| / (|r| + epsilon).
double mape(const Image& image, const Image& reference, double epsilon = RelativeMseEpsilon);
// Structural similarity (Wang, Bovik, Sheikh and Simoncelli, "Image Quality Assessment: From
// Error Visibility to Structural Similarity", IEEE TIP 2004) on luminance, with 8x8 windows and
// C1 = (0.01 L)^2, C2 = (0.03 L)^2 for dynamic range L = the reference's peak luminance.
double ssim(const Image& image, const Image& reference);

// Throws InputError when the two images differ in size (`what` names the second one).
void check_same_size(const Image& image, const Image& reference, const std::string& what);

}  // namespace freezeray
