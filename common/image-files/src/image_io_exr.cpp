// OpenEXR through the reference implementation, the OpenEXR library (Debian's libopenexr-dev),
// with its C++ interface: Imf::InputFile and Imf::OutputFile with a frame buffer of float
// channels ("Reading and Writing Image Files with the OpenEXR Library",
// https://openexr.com/en/latest/ReadingAndWritingImageFiles.html).
// We write 32-bit float R, G, B with ZIP compression and the image metadata as string
// attributes; we read any scanline or tiled single-part file with R, G, B (half, float or uint)
// or a single grey channel, ignoring alpha and other channels.
#include "freezeray/error.hpp"
#include "image_io_exr_attributes.hpp"
#include "image_io_exr_streams.hpp"
#include "image_io_formats.hpp"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <ImfPartType.h>
#include <ImfStringAttribute.h>
#include <ImfTileDescriptionAttribute.h>
#include <ImfTiledInputFile.h>

#include <algorithm>
#include <cstdint>
#include <exception>
#include <string>
#include <utility>
#include <vector>

namespace freezeray::image_io {

namespace {

// Our pixels are three packed floats, which the frame buffer addresses with a stride.
static_assert(sizeof(Spectrum) == 3 * sizeof(float), "Spectrum must be three packed floats");

// The most bytes one block of the file (defined in check_block_size) may take uncompressed.
constexpr std::int64_t MaxBlockBytes = std::int64_t(1) << 26;

// About how many pixels are decoded at a time (whole blocks, so at least one block).
constexpr std::int64_t StripPixels = std::int64_t(1) << 20;

// Standard attributes that OpenEXR writes itself: metadata must not duplicate them.
bool is_reserved_attribute(const std::string& name) {
    static const char* const reserved[] = {"channels", "compression", "dataWindow", "displayWindow",
                                           "lineOrder", "pixelAspectRatio", "screenWindowCenter",
                                           "screenWindowWidth", "tiles", "type", "name", "chunkCount", "version"};
    for (const char* word : reserved) {
        if (name == word) return true;
    }
    return false;
}

// The names of all channels, for messages: "A, Z" (OpenEXR keeps them in alphabetical order).
std::string channel_list(const Imf::ChannelList& channels) {
    std::string list;
    for (auto channel = channels.begin(); channel != channels.end(); ++channel) {
        list += (list.empty() ? "" : ", ") + std::string(channel.name());
    }
    return list.empty() ? "none" : list;
}

// The scan lines in one block of a scanline file, for each compression (the file layout
// document, https://openexr.com/en/latest/OpenEXRFileLayout.html, "Regular Scan Line Blocks";
// numLinesInBuffer in ImfCompressor.cpp).
std::int64_t lines_per_block(Imf::Compression compression) {
    switch (compression) {
    case Imf::ZIP_COMPRESSION:
    case Imf::PXR24_COMPRESSION: return 16;
    case Imf::PIZ_COMPRESSION:
    case Imf::B44_COMPRESSION:
    case Imf::B44A_COMPRESSION:
    case Imf::DWAA_COMPRESSION: return 32;
    case Imf::DWAB_COMPRESSION: return 256;
    default: return 1;  // none, RLE, ZIPS
    }
}

// The bytes of one pixel of every channel, uncompressed (channels are not subsampled here).
std::int64_t bytes_per_pixel_in(const Imf::Header& header) {
    std::int64_t bytes = 0;
    for (auto channel = header.channels().begin(); channel != header.channels().end(); ++channel) {
        bytes += channel.channel().type == Imf::HALF ? 2 : 4;
    }
    return bytes;
}

// OpenEXR sizes its buffers from the header before it reads any pixel: a block of scan lines
// (ScanLineInputFile), or a tile and, when a tiled file is read by scan lines, a whole row of
// tiles (InputFile::setFrameBuffer). A block here is `width` (or the tile width, when wider)
// times `rows` (the lines per block, or the tile height), at the larger of the file's bytes per
// pixel and ours (12). Refuses a block of more than MaxBlockBytes (64 MiB, as much as a block of
// 256 lines, DWAB's, of 16384 RGBA float pixels), so that a small corrupt header can make OpenEXR
// and us allocate a few times 64 MiB at most before its pixels turn out to be missing.
void check_block_size(const Imf::Header& header, bool tiled, std::int64_t width, const std::string& path) {
    const std::int64_t file_bytes_per_pixel = bytes_per_pixel_in(header);
    const std::int64_t bytes_per_pixel = std::max<std::int64_t>(file_bytes_per_pixel, sizeof(Spectrum));
    std::int64_t block_width = width, rows = lines_per_block(header.compression());
    if (tiled) {
        block_width = std::max<std::int64_t>(width, header.tileDescription().xSize);
        rows = header.tileDescription().ySize;
    }
    // Compared by division: the product of three header values could overflow.
    if (bytes_per_pixel > MaxBlockBytes || block_width > MaxBlockBytes / bytes_per_pixel ||
        rows > MaxBlockBytes / (block_width * bytes_per_pixel)) {
        throw InputError(path, "the OpenEXR file's blocks of " + std::to_string(block_width) + " x " +
                                   std::to_string(rows) + " pixels of " + std::to_string(file_bytes_per_pixel) +
                                   " bytes are too large (more than 2^26 bytes)");
    }
}

// OpenEXR 3.1 takes a block whose data is shorter than its pixels as uncompressed all the same,
// and the rest of the block is whatever its buffer held before (LineBufferTask::execute in
// ImfScanLineInputFile.cpp, TileBufferTask::execute in ImfTiledInputFile.cpp: a block is
// decompressed only when it has a compressor and is shorter than its pixels). So in an
// uncompressed file every block must hold all its pixels (found by fuzz_image when EXR went
// through tinyexr: regressions/image/exr-uint-chunk-too-short.bin).
void check_uncompressed_blocks(const Bytes& bytes, const Imf::Header& header, bool tiled, const std::string& path) {
    const std::int64_t bytes_per_pixel = bytes_per_pixel_in(header);
    const auto refuse = [&](const std::string& block, int size, std::int64_t needed) {
        throw InputError(path, "the uncompressed OpenEXR " + block + " holds " + std::to_string(size) +
                                   " bytes, not " + std::to_string(needed));
    };
    MemoryInputStream stream(bytes, path);
    if (!tiled) {
        Imf::InputFile file(stream);
        const Imath::Box2i window = file.header().dataWindow();
        const std::int64_t needed = (std::int64_t(window.max.x) - window.min.x + 1) * bytes_per_pixel;
        for (int y = window.min.y; y <= window.max.y; ++y) {  // one scan line per block
            const char* data = nullptr;
            int size = 0;
            file.rawPixelData(y, data, size);
            if (size < needed) refuse("scan line " + std::to_string(y), size, needed);
        }
        return;
    }
    // Tiles are read in the order they are stored, each telling which tile and level it is.
    Imf::TiledInputFile file(stream);
    std::int64_t tiles = 0;
    for (int ly = 0; ly < file.numYLevels(); ++ly) {
        for (int lx = 0; lx < file.numXLevels(); ++lx) {
            if (file.isValidLevel(lx, ly)) tiles += std::int64_t(file.numXTiles(lx)) * file.numYTiles(ly);
        }
    }
    for (std::int64_t t = 0; t < tiles; ++t) {
        int dx = 0, dy = 0, lx = 0, ly = 0, size = 0;
        const char* data = nullptr;
        file.rawTileData(dx, dy, lx, ly, data, size);
        const Imath::Box2i tile = file.dataWindowForTile(dx, dy, lx, ly);
        const std::int64_t needed = (std::int64_t(tile.max.x) - tile.min.x + 1) * (std::int64_t(tile.max.y) - tile.min.y + 1) *
                                    bytes_per_pixel;
        if (size < needed) refuse("tile (" + std::to_string(dx) + ", " + std::to_string(dy) + ")", size, needed);
    }
}

// Makes room for `more` pixels after those already decoded, at most doubling the capacity and
// never beyond `total`: memory grows with what the file has really decoded, so that a small
// corrupt file claiming a large image fails before we allocate the whole image.
void make_room(std::vector<Spectrum>& pixels, std::size_t more, std::size_t total) {
    const std::size_t needed = pixels.size() + more;
    if (needed > pixels.capacity()) pixels.reserve(std::min(total, std::max(needed, 2 * pixels.capacity())));
}

// The channels to read into our R, G, B: R, G, B; else Y, or a lone channel, as grey (one name).
std::vector<std::string> channels_to_read(const Imf::ChannelList& channels, const std::string& path) {
    if (channels.findChannel("R") && channels.findChannel("G") && channels.findChannel("B")) return {"R", "G", "B"};
    if (channels.findChannel("Y")) return {"Y"};
    int count = 0;
    for (auto channel = channels.begin(); channel != channels.end(); ++channel) ++count;
    if (count == 1) return {channels.begin().name()};
    throw InputError(path, "the OpenEXR file has no R, G, B or Y channels (it has: " + channel_list(channels) + ")");
}

// Decodes the pixels of an opened file, block by block, into rows of pixels from the top.
// What this cannot see: a compressed block that decompresses to fewer bytes than its pixels
// (OpenEXR 3.1's ZIP and RLE decoders do not compare the two, ImfZip.cpp and
// ImfRleCompressor.cpp) leaves the rest of the block as OpenEXR's buffer held it, so such a
// corrupt file reads as wrong pixels, never out of bounds. OpenEXR's newer core library
// (OpenEXRCore, which its C++ reader uses from 3.3) refuses such blocks.
std::vector<Spectrum> read_pixels(Imf::InputFile& file, const std::vector<std::string>& names, std::int64_t rows_per_strip) {
    const Imath::Box2i window = file.header().dataWindow();
    const std::int64_t width = std::int64_t(window.max.x) - window.min.x + 1;
    const std::int64_t height = std::int64_t(window.max.y) - window.min.y + 1;
    const std::size_t total = static_cast<std::size_t>(width * height);
    std::vector<Spectrum> pixels;
    for (std::int64_t top = window.min.y; top <= window.max.y; top += rows_per_strip) {
        const std::int64_t rows = std::min(rows_per_strip, std::int64_t(window.max.y) - top + 1);
        const std::size_t first = pixels.size();
        make_room(pixels, static_cast<std::size_t>(rows * width), total);
        pixels.resize(first + static_cast<std::size_t>(rows * width));
        // Each channel lands in one float of our pixels; Slice::Make finds the address of pixel
        // (x, y) of the data window from the strip's first pixel and its origin.
        Imf::FrameBuffer frame;
        for (std::size_t c = 0; c < names.size(); ++c) {
            frame.insert(names[c], Imf::Slice::Make(Imf::FLOAT, &pixels[first][static_cast<int>(c)],
                                                    Imath::V2i(window.min.x, static_cast<int>(top)), width, rows,
                                                    sizeof(Spectrum), sizeof(Spectrum) * static_cast<std::size_t>(width)));
        }
        file.setFrameBuffer(frame);
        file.readPixels(static_cast<int>(top), static_cast<int>(top + rows - 1));
    }
    return pixels;
}

}  // namespace

// Decodes an OpenEXR file: RGB (or one grey channel) as float, and its string attributes.
Image decode_exr(const Bytes& bytes, const std::string& path) {
    int version = check_exr_attributes(bytes, path);
    MemoryInputStream stream(bytes, path);

    // First the header alone, to check what it asks for before OpenEXR allocates anything.
    Imf::Header header;
    std::vector<std::string> names;
    std::int64_t rows_per_block = 1;
    try {
        stream.seekg(8);  // after the magic number and the version field
        header.readFrom(stream, version);
        const Imath::Box2i window = header.dataWindow();
        const std::int64_t width = std::int64_t(window.max.x) - window.min.x + 1;
        check_image_size(width, std::int64_t(window.max.y) - window.min.y + 1, path);
        header.sanityCheck(Imf::isTiled(version));
        if (header.hasType() && header.type() != Imf::SCANLINEIMAGE && header.type() != Imf::TILEDIMAGE) {
            throw InputError(path, "deep OpenEXR files are not supported");
        }
        for (auto channel = header.channels().begin(); channel != header.channels().end(); ++channel) {
            if (channel.channel().xSampling != 1 || channel.channel().ySampling != 1) {
                throw InputError(path, "channel '" + std::string(channel.name()) + "' is subsampled, which is not supported");
            }
        }
        names = channels_to_read(header.channels(), path);
        check_block_size(header, Imf::isTiled(version), width, path);
        rows_per_block = Imf::isTiled(version) ? header.tileDescription().ySize : lines_per_block(header.compression());
    } catch (const InputError&) {
        throw;
    } catch (const std::exception& error) {  // Iex::BaseExc and the standard library's
        throw InputError(path, std::string("not a valid OpenEXR file: ") + error.what());
    }

    // Then the pixels, a strip of whole blocks at a time.
    const Imath::Box2i window = header.dataWindow();
    const std::int64_t width = std::int64_t(window.max.x) - window.min.x + 1;
    const std::int64_t rows_per_strip = rows_per_block * std::max<std::int64_t>(1, StripPixels / (rows_per_block * width));
    std::vector<Spectrum> pixels;
    try {
        stream.seekg(0);
        Imf::InputFile file(stream);
        // OpenEXR rebuilds a damaged offset table from what it finds; a block still missing means
        // the file was cut short (or never finished).
        if (!file.isComplete()) throw InputError(path, "the OpenEXR file is truncated: some blocks of pixels are missing");
        if (header.compression() == Imf::NO_COMPRESSION) check_uncompressed_blocks(bytes, header, Imf::isTiled(version), path);
        pixels = read_pixels(file, names, rows_per_strip);
    } catch (const InputError&) {
        throw;
    } catch (const std::exception& error) {
        throw InputError(path, std::string("cannot decode the OpenEXR pixels: ") + error.what());
    }

    const std::int64_t height = std::int64_t(window.max.y) - window.min.y + 1;
    Image image(static_cast<int>(width), static_cast<int>(height), std::move(pixels));
    if (names.size() == 1) {
        for (Spectrum& pixel : image.pixels()) pixel = Spectrum(pixel.x);  // grey
    }
    for (auto attribute = header.begin(); attribute != header.end(); ++attribute) {
        const auto* text = dynamic_cast<const Imf::StringAttribute*>(&attribute.attribute());
        if (text == nullptr || is_reserved_attribute(attribute.name())) continue;
        std::string value = text->value();
        while (!value.empty() && value.back() == '\0') value.pop_back();  // some writers add a terminator
        image.metadata[attribute.name()] = value;
    }
    return image;
}

// Encodes an image as a ZIP-compressed OpenEXR file of 32-bit float R, G, B channels (stored in
// the alphabetical order B, G, R, as OpenEXR always does), with the metadata as string attributes.
Bytes encode_exr(const Image& image, const std::string& path) {
    for (const auto& [key, value] : image.metadata) {
        if (key.empty() || key.size() > 255 || key.find('\0') != std::string::npos || is_reserved_attribute(key)) {
            throw InputError(path, "the metadata key '" + key + "' cannot be an OpenEXR attribute name");
        }
        if (value.size() > static_cast<std::size_t>(INT32_MAX)) {
            throw InputError(path, "the metadata value of '" + key + "' is too long");
        }
    }
    MemoryOutputStream stream(path);
    try {
        Imf::Header header(image.width(), image.height());  // data and display window (0, 0) to (w - 1, h - 1)
        header.compression() = Imf::ZIP_COMPRESSION;
        for (const auto& [key, value] : image.metadata) header.insert(key, Imf::StringAttribute(value));
        const char* const names[3] = {"R", "G", "B"};
        Imf::FrameBuffer frame;
        for (int c = 0; c < 3; ++c) {
            header.channels().insert(names[c], Imf::Channel(Imf::FLOAT));
            frame.insert(names[c], Imf::Slice::Make(Imf::FLOAT, &image.pixels()[0][c], Imath::V2i(0, 0), image.width(),
                                                    image.height(), sizeof(Spectrum),
                                                    sizeof(Spectrum) * static_cast<std::size_t>(image.width())));
        }
        // The table of chunk offsets is written when the file object is destroyed, so the bytes
        // are complete only after this block.
        Imf::OutputFile file(stream, header);
        file.setFrameBuffer(frame);
        file.writePixels(image.height());
    } catch (const std::exception& error) {
        throw InputError(path, std::string("cannot encode the image as OpenEXR: ") + error.what());
    }
    return std::move(stream.bytes());
}

}  // namespace freezeray::image_io
