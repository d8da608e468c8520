// Reading and writing image files: the format chosen by the extension, whole-file reads, and
// atomic writes (temporary file, then rename). The formats themselves live in image_io_*.cpp.
#include "freezeray/error.hpp"
#include "freezeray/image.hpp"
#include "image_io_formats.hpp"

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string>
#include <system_error>
#include <utility>

#include <unistd.h>  // getpid, to name temporary files

namespace freezeray {

namespace fs = std::filesystem;
using image_io::Bytes;

namespace {

// The largest file we read into memory: an uncompressed RGBA float image of MaxPixelCount pixels
// plus room for a header. Anything bigger cannot be an image we accept.
constexpr std::uintmax_t MaxFileBytes = static_cast<std::uintmax_t>(image_io::MaxPixelCount) * 16 + (1u << 20);

// The extension of `path` in lower case, with its dot (".exr"), or "" if it has none.
std::string lowercase_extension(const std::string& path) {
    std::string extension = fs::path(path).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return extension;
}

// The text of the last C library error (errno), for messages.
std::string last_system_error() { return std::strerror(errno); }

// The folder that will hold `path` ("." for a bare file name).
fs::path folder_of(const std::string& path) {
    const fs::path parent = fs::path(path).parent_path();
    return parent.empty() ? fs::path(".") : parent;
}

// Throws InputError unless the folder that should hold `path` exists.
void check_folder(const std::string& path) {
    const fs::path folder = folder_of(path);
    std::error_code error;
    if (!fs::exists(folder, error)) {
        throw InputError(path, "the folder '" + folder.string() + "' does not exist");
    }
    if (!fs::is_directory(folder, error)) {
        throw InputError(path, "'" + folder.string() + "' is not a folder");
    }
}

// A fresh name beside `path` for a temporary file: unique per process and per call, so that two
// renders (or two threads) writing the same image never share a temporary file.
std::string temporary_name_for(const std::string& path) {
    static std::atomic<unsigned> counter{0};
    return path + ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(counter++);
}

// Removes a temporary file when it goes out of scope, unless it was renamed into place first:
// whatever fails (or throws) between creating and renaming it, nothing half-written remains.
class TemporaryFile {
public:
    explicit TemporaryFile(std::string name) : name_(std::move(name)) {}
    ~TemporaryFile() {
        if (!kept_) {
            std::error_code ignored;
            fs::remove(name_, ignored);
        }
    }
    TemporaryFile(const TemporaryFile&) = delete;
    TemporaryFile& operator=(const TemporaryFile&) = delete;

    const std::string& name() const { return name_; }
    void keep() { kept_ = true; }

private:
    std::string name_;
    bool kept_ = false;
};

// Writes `bytes` to `path` atomically: a reader sees the old file or the new one, never a torn
// one, because rename() within a folder replaces the destination in one step (POSIX rename).
void write_bytes_atomically(const std::string& path, const Bytes& bytes) {
    check_folder(path);
    TemporaryFile temporary(temporary_name_for(path));

    std::FILE* file = std::fopen(temporary.name().c_str(), "wb");
    if (file == nullptr) {
        throw InputError(path, "cannot create the temporary file '" + temporary.name() + "': " + last_system_error());
    }
    const std::size_t written = std::fwrite(bytes.data(), 1, bytes.size(), file);
    const bool write_failed = written != bytes.size() || std::fflush(file) != 0;
    const std::string write_error = write_failed ? last_system_error() : std::string();
    if (std::fclose(file) != 0 || write_failed) {
        throw InputError(path, "cannot write the temporary file '" + temporary.name() + "': " +
                                   (write_failed ? write_error : last_system_error()));
    }

    std::error_code error;
    fs::rename(temporary.name(), path, error);
    if (error) {
        std::error_code ignored;
        if (fs::is_directory(path, ignored)) {
            throw InputError(path, "is a folder, not a file");
        }
        throw InputError(path, "cannot move the temporary file into place: " + error.message());
    }
    temporary.keep();
}

// The whole content of the file at `path`, or an InputError saying why it cannot be read.
Bytes read_file_bytes(const std::string& path) {
    std::error_code error;
    if (!fs::exists(path, error)) {
        throw InputError(path, error ? "cannot access the file: " + error.message() : std::string("no such file"));
    }
    if (fs::is_directory(path, error)) {
        throw InputError(path, "is a folder, not an image file");
    }
    std::FILE* file = std::fopen(path.c_str(), "rb");
    if (file == nullptr) {
        throw InputError(path, "cannot open the file: " + last_system_error());
    }
    // Read in chunks rather than trusting the file size, which pipes and special files lack.
    Bytes bytes;
    unsigned char chunk[1 << 16];
    std::size_t count = 0;
    while ((count = std::fread(chunk, 1, sizeof(chunk), file)) > 0) {
        if (bytes.size() + count > MaxFileBytes) {
            std::fclose(file);
            throw InputError(path, "the file is too large to be an image we can read");
        }
        bytes.insert(bytes.end(), chunk, chunk + count);
    }
    const bool read_failed = std::ferror(file) != 0;
    const std::string read_error = read_failed ? last_system_error() : std::string();
    std::fclose(file);
    if (read_failed) {
        throw InputError(path, "cannot read the file: " + read_error);
    }
    if (bytes.empty()) {
        throw InputError(path, "the file is empty");
    }
    return bytes;
}

}  // namespace

// Throws InputError unless width x height is positive and at most MaxPixelCount pixels.
void image_io::check_image_size(std::int64_t width, std::int64_t height, const std::string& path) {
    if (width <= 0 || height <= 0) {
        throw InputError(path, "invalid image size " + std::to_string(width) + "x" + std::to_string(height));
    }
    // Compare without overflow: width * height > MaxPixelCount.
    if (width > MaxPixelCount || height > MaxPixelCount / width) {
        throw InputError(path, "image size " + std::to_string(width) + "x" + std::to_string(height) +
                                   " is too large (more than 2^28 pixels)");
    }
}

// Maps a path's extension (any case) to a format we can write, else throws InputError.
ImageFormat image_format_for_path(const std::string& path) {
    const std::string extension = lowercase_extension(path);
    if (extension == ".exr") return ImageFormat::Exr;
    if (extension == ".pfm") return ImageFormat::Pfm;
    if (extension == ".hdr") return ImageFormat::Hdr;
    if (extension == ".png") return ImageFormat::Png;
    if (extension.empty()) {
        throw InputError(path, "has no file extension (expected .exr, .pfm, .hdr or .png)");
    }
    throw InputError(path, "unknown image extension '" + extension + "' (expected .exr, .pfm, .hdr or .png)");
}

// Reads the image at `path`, decoding by extension; throws InputError naming the file on failure.
Image read_image(const std::string& path) {
    const std::string extension = lowercase_extension(path);
    const bool is_8_bit = extension == ".png" || extension == ".jpg" || extension == ".jpeg" ||
                          extension == ".bmp" || extension == ".tga";
    if (!is_8_bit && extension != ".exr" && extension != ".pfm" && extension != ".hdr") {
        const std::string readable = " (readable: .exr, .pfm, .hdr, .png, .jpg, .jpeg, .bmp, .tga)";
        throw InputError(path, extension.empty() ? "has no file extension" + readable
                                                 : "unknown image extension '" + extension + "'" + readable);
    }
    const Bytes bytes = read_file_bytes(path);
    if (extension == ".exr") return image_io::decode_exr(bytes, path);
    if (extension == ".pfm") return image_io::decode_pfm(bytes, path);
    if (extension == ".hdr") return image_io::decode_hdr(bytes, path);
    return image_io::decode_srgb(bytes, path);
}

// Encodes `image` in the format of `path`'s extension and writes it atomically.
void write_image(const std::string& path, const Image& image, const ImageWriteOptions& options) {
    const ImageFormat format = image_format_for_path(path);
    if (image.width() <= 0 || image.height() <= 0) {
        throw InputError(path, "cannot write an empty image (" + std::to_string(image.width()) + "x" +
                                   std::to_string(image.height()) + ")");
    }
    Bytes bytes;
    switch (format) {
    case ImageFormat::Exr: bytes = image_io::encode_exr(image, path); break;
    case ImageFormat::Pfm: bytes = image_io::encode_pfm(image); break;
    case ImageFormat::Hdr: bytes = image_io::encode_hdr(image, path); break;
    case ImageFormat::Png: bytes = image_io::encode_png(image, options.exposure_stops, path); break;
    }
    write_bytes_atomically(path, bytes);
}

// Throws InputError unless an image could be written at `path` now: a known extension, an
// existing folder, and permission to create a file in it (tested by creating one).
void check_image_writable(const std::string& path) {
    image_format_for_path(path);
    check_folder(path);
    std::error_code error;
    if (fs::is_directory(path, error)) {
        throw InputError(path, "is a folder, not a file");
    }
    TemporaryFile probe(temporary_name_for(path));
    std::FILE* file = std::fopen(probe.name().c_str(), "wb");
    if (file == nullptr) {
        throw InputError(path, "cannot create a file in the folder '" + folder_of(path).string() +
                                   "': " + last_system_error());
    }
    std::fclose(file);
}

}  // namespace freezeray
