// OpenEXR through Syoyo Fujita's tinyexr. Debian's libtinyexr already contains the
// implementation, so we only include the declarations (no TINYEXR_IMPLEMENTATION here).
// We write 32-bit float R, G, B with ZIP compression and the image metadata as string
// attributes; we read any scanline or tiled single-part file with R, G, B (half, float or uint)
// or a single grey channel, ignoring alpha and other channels.
#include "freezeray/error.hpp"
#include "image_io_exr_check.hpp"
#include "image_io_formats.hpp"

#include <tinyexr.h>

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

namespace freezeray::image_io {

namespace {

// Takes tinyexr's error message (freeing it), or describes the error code when it gave none.
std::string take_error(const char* message, int code) {
    std::string text = message != nullptr ? message : "error code " + std::to_string(code);
    if (message != nullptr) FreeEXRErrorMessage(message);
    while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
    return text;
}

// Owns a parsed header and a loaded image, and frees them through tinyexr on every exit path.
struct LoadedExr {
    EXRHeader header;
    EXRImage image;
    LoadedExr() {
        InitEXRHeader(&header);
        InitEXRImage(&image);
    }
    ~LoadedExr() {
        FreeEXRImage(&image);
        FreeEXRHeader(&header);
    }
    LoadedExr(const LoadedExr&) = delete;
    LoadedExr& operator=(const LoadedExr&) = delete;
};

// The index of the channel called `name`, or -1.
int find_channel(const EXRHeader& header, const char* name) {
    for (int i = 0; i < header.num_channels; ++i) {
        if (std::strcmp(header.channels[i].name, name) == 0) return i;
    }
    return -1;
}

// The names of all channels, for messages: "A, Z".
std::string channel_list(const EXRHeader& header) {
    std::string list;
    for (int i = 0; i < header.num_channels; ++i) list += (i > 0 ? ", " : "") + std::string(header.channels[i].name);
    return list.empty() ? "none" : list;
}

// One sample of a channel buffer, in the pixel type tinyexr decoded it to.
float sample(const unsigned char* buffer, int pixel_type, std::size_t index) {
    if (pixel_type == TINYEXR_PIXELTYPE_UINT) {
        return static_cast<float>(reinterpret_cast<const unsigned int*>(buffer)[index]);
    }
    return reinterpret_cast<const float*>(buffer)[index];  // halves were asked for as floats
}

// Standard attributes that tinyexr writes itself: metadata must not duplicate them.
bool is_reserved_attribute(const std::string& name) {
    static const char* const reserved[] = {"channels", "compression", "dataWindow", "displayWindow",
                                           "lineOrder", "pixelAspectRatio", "screenWindowCenter",
                                           "screenWindowWidth", "tiles", "type", "name", "chunkCount", "version"};
    for (const char* word : reserved) {
        if (name == word) return true;
    }
    return false;
}

}  // namespace

// Decodes an OpenEXR file: RGB (or one grey channel) as float, and its string attributes.
Image decode_exr(const Bytes& bytes, const std::string& path) {
    EXRVersion version;
    if (ParseEXRVersionFromMemory(&version, bytes.data(), bytes.size()) != TINYEXR_SUCCESS) {
        throw InputError(path, "not an OpenEXR file (bad magic number or version)");
    }
    if (version.multipart != 0 || version.non_image != 0) {
        throw InputError(path, "multi-part and deep OpenEXR files are not supported");
    }

    ExrHeaderCheck(bytes, path).run();

    LoadedExr exr;
    const char* message = nullptr;
    int code = ParseEXRHeaderFromMemory(&exr.header, &version, bytes.data(), bytes.size(), &message);
    if (code != TINYEXR_SUCCESS) {
        throw InputError(path, "not a valid OpenEXR file: " + take_error(message, code));
    }
    // Check the size before tinyexr allocates anything for the pixels.
    const EXRBox2i& window = exr.header.data_window;
    check_image_size(std::int64_t(window.max_x) - window.min_x + 1, std::int64_t(window.max_y) - window.min_y + 1, path);

    // The channels to read: R, G, B, else Y or a lone channel as grey.
    int source[3] = {find_channel(exr.header, "R"), find_channel(exr.header, "G"), find_channel(exr.header, "B")};
    if (source[0] < 0 || source[1] < 0 || source[2] < 0) {
        const int grey = exr.header.num_channels == 1 ? 0 : find_channel(exr.header, "Y");
        if (grey < 0) {
            throw InputError(path, "the OpenEXR file has no R, G, B or Y channels (it has: " +
                                       channel_list(exr.header) + ")");
        }
        source[0] = source[1] = source[2] = grey;
    }
    // Ask tinyexr to convert half-float channels to float as it decodes.
    for (int i = 0; i < exr.header.num_channels; ++i) {
        if (exr.header.pixel_types[i] == TINYEXR_PIXELTYPE_HALF) {
            exr.header.requested_pixel_types[i] = TINYEXR_PIXELTYPE_FLOAT;
        }
    }

    // When a scanline decode fails, tinyexr 1.0.1 calls FreeEXRImage before it has set the
    // image's channel count, so without this the channel buffers would leak (found by fuzz_image).
    exr.image.num_channels = exr.header.num_channels;
    code = LoadEXRImageFromMemory(&exr.image, &exr.header, bytes.data(), bytes.size(), &message);
    if (code != TINYEXR_SUCCESS) {
        // tinyexr 1.0.1 already released the pixels of a failed decode but left the pointers
        // dangling: forget them, or our destructor would free them a second time.
        InitEXRImage(&exr.image);
        throw InputError(path, "cannot decode the OpenEXR pixels: " + take_error(message, code));
    }
    check_image_size(exr.image.width, exr.image.height, path);

    Image image(exr.image.width, exr.image.height);
    const int* types = exr.header.requested_pixel_types;
    if (exr.image.tiles == nullptr) {
        // Scanline file: one buffer per channel, rows from the top.
        for (std::size_t i = 0; i < image.pixel_count(); ++i) {
            for (int c = 0; c < 3; ++c) image[i][c] = sample(exr.image.images[source[c]], types[source[c]], i);
        }
    } else {
        // Tiled file: the finest level's tiles, each tile_size_x wide in memory, clipped at the edges.
        const int tile_width = exr.header.tile_size_x, tile_height = exr.header.tile_size_y;
        for (int t = 0; t < exr.image.num_tiles; ++t) {
            const EXRTile& tile = exr.image.tiles[t];
            for (int j = 0; j < tile.height; ++j) {
                for (int i = 0; i < tile.width; ++i) {
                    const int x = tile.offset_x * tile_width + i, y = tile.offset_y * tile_height + j;
                    if (x >= image.width() || y >= image.height()) continue;
                    const std::size_t index = static_cast<std::size_t>(j) * tile_width + i;
                    for (int c = 0; c < 3; ++c) image.at(x, y)[c] = sample(tile.images[source[c]], types[source[c]], index);
                }
            }
        }
    }

    for (int i = 0; i < exr.header.num_custom_attributes; ++i) {
        const EXRAttribute& attribute = exr.header.custom_attributes[i];
        if (std::strcmp(attribute.type, "string") != 0 || attribute.value == nullptr || attribute.size < 0) continue;
        std::string value(reinterpret_cast<const char*>(attribute.value), static_cast<std::size_t>(attribute.size));
        while (!value.empty() && value.back() == '\0') value.pop_back();  // some writers add a terminator
        image.metadata[attribute.name] = value;
    }
    return image;
}

// Encodes an image as a ZIP-compressed OpenEXR file of 32-bit float B, G, R channels (the
// alphabetical order OpenEXR's own library writes), with the metadata as string attributes.
Bytes encode_exr(const Image& image, const std::string& path) {
    if (image.metadata.size() > TINYEXR_MAX_CUSTOM_ATTRIBUTES) {
        throw InputError(path, "too many metadata entries for OpenEXR (at most " +
                                   std::to_string(TINYEXR_MAX_CUSTOM_ATTRIBUTES) + ")");
    }
    std::vector<EXRAttribute> attributes;
    for (const auto& [key, value] : image.metadata) {
        if (key.empty() || key.size() > 255 || key.find('\0') != std::string::npos || is_reserved_attribute(key)) {
            throw InputError(path, "the metadata key '" + key + "' cannot be an OpenEXR attribute name");
        }
        if (value.size() > static_cast<std::size_t>(INT32_MAX)) {
            throw InputError(path, "the metadata value of '" + key + "' is too long");
        }
        EXRAttribute attribute{};
        std::memcpy(attribute.name, key.data(), key.size());
        std::strcpy(attribute.type, "string");
        // tinyexr only reads the value while saving, despite the non-const pointer.
        attribute.value = reinterpret_cast<unsigned char*>(const_cast<char*>(value.data()));
        attribute.size = static_cast<int>(value.size());
        attributes.push_back(attribute);
    }

    // One plane of floats per channel, in the order of the channel list: B, G, R.
    const int component_of_channel[3] = {2, 1, 0};
    std::vector<float> planes[3];
    for (int channel = 0; channel < 3; ++channel) {
        planes[channel].reserve(image.pixel_count());
        for (const Spectrum& pixel : image.pixels()) planes[channel].push_back(pixel[component_of_channel[channel]]);
    }
    unsigned char* plane_pointers[3] = {reinterpret_cast<unsigned char*>(planes[0].data()),
                                        reinterpret_cast<unsigned char*>(planes[1].data()),
                                        reinterpret_cast<unsigned char*>(planes[2].data())};

    EXRChannelInfo channels[3]{};
    std::strcpy(channels[0].name, "B");
    std::strcpy(channels[1].name, "G");
    std::strcpy(channels[2].name, "R");
    int pixel_types[3] = {TINYEXR_PIXELTYPE_FLOAT, TINYEXR_PIXELTYPE_FLOAT, TINYEXR_PIXELTYPE_FLOAT};
    int stored_types[3] = {TINYEXR_PIXELTYPE_FLOAT, TINYEXR_PIXELTYPE_FLOAT, TINYEXR_PIXELTYPE_FLOAT};

    // Everything the header points to is owned here, so it must not go through FreeEXRHeader.
    EXRHeader header;
    InitEXRHeader(&header);
    header.num_channels = 3;
    header.channels = channels;
    header.pixel_types = pixel_types;             // the type of our buffers
    header.requested_pixel_types = stored_types;  // the type in the file
    header.compression_type = TINYEXR_COMPRESSIONTYPE_ZIP;
    header.num_custom_attributes = static_cast<int>(attributes.size());
    header.custom_attributes = attributes.empty() ? nullptr : attributes.data();

    EXRImage exr_image;
    InitEXRImage(&exr_image);
    exr_image.num_channels = 3;
    exr_image.images = plane_pointers;
    exr_image.width = image.width();
    exr_image.height = image.height();

    unsigned char* memory = nullptr;
    const char* message = nullptr;
    const std::size_t size = SaveEXRImageToMemory(&exr_image, &header, &memory, &message);
    if (size == 0 || memory == nullptr) {
        std::free(memory);
        throw InputError(path, "cannot encode the image as OpenEXR: " + take_error(message, 0));
    }
    Bytes bytes(memory, memory + size);
    std::free(memory);  // tinyexr allocates the file with malloc
    return bytes;
}

}  // namespace freezeray::image_io
