// A floating-point RGB image and its file formats: OpenEXR, PFM, Radiance HDR and PNG.
#pragma once

#include "freezeray/math.hpp"

#include <map>
#include <string>
#include <vector>

namespace freezeray {

// Linear RGB pixels in row-major order, row 0 at the top.
class Image {
public:
    Image() = default;
    Image(int width, int height, Spectrum fill = Spectrum(0.0f));
    // Takes `pixels` (row-major, row 0 at the top), which must hold width x height of them.
    Image(int width, int height, std::vector<Spectrum> pixels);

    int width() const { return width_; }
    int height() const { return height_; }
    std::size_t pixel_count() const { return pixels_.size(); }

    Spectrum& at(int x, int y) { return pixels_[static_cast<std::size_t>(y) * width_ + x]; }
    const Spectrum& at(int x, int y) const { return pixels_[static_cast<std::size_t>(y) * width_ + x]; }
    Spectrum& operator[](std::size_t i) { return pixels_[i]; }
    const Spectrum& operator[](std::size_t i) const { return pixels_[i]; }

    std::vector<Spectrum>& pixels() { return pixels_; }
    const std::vector<Spectrum>& pixels() const { return pixels_; }

    // Free-form key/value pairs stored with the image where the format allows it (EXR string
    // attributes): sample count, seed, integrator, estimated error.
    std::map<std::string, std::string> metadata;

private:
    int width_ = 0;
    int height_ = 0;
    std::vector<Spectrum> pixels_;
};

// Options for writing. Exposure (in stops) scales the linear values before PNG's sRGB encoding;
// the floating-point formats always store the unscaled radiance.
struct ImageWriteOptions {
    float exposure_stops = 0.0f;
};

// The formats, chosen by the file extension (case-insensitive).
enum class ImageFormat { Exr, Pfm, Hdr, Png };

// The format for a path, or an InputError naming the path if the extension is not one we write.
ImageFormat image_format_for_path(const std::string& path);

// Reads an image. PNG (and JPEG, BMP, TGA, which stb_image also reads) are decoded from sRGB to
// linear. Throws InputError naming the file for a missing, unreadable, truncated or corrupt file.
Image read_image(const std::string& path);

// Writes an image atomically: to a temporary file in the same folder, then renamed over `path`,
// so a failure or an interruption never leaves a torn file. Throws InputError on failure.
void write_image(const std::string& path, const Image& image, const ImageWriteOptions& options = {});

// Throws InputError unless a file can be created at `path` (folder exists and is writable,
// extension known). Called before a long render so that it does not fail at the very end.
void check_image_writable(const std::string& path);

// The sRGB transfer function (IEC 61966-2-1) and its inverse, on one channel.
float linear_to_srgb(float linear);
float srgb_to_linear(float encoded);

}  // namespace freezeray
