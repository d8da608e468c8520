// Writes the OpenEXR seeds of tests/fuzz/corpus/image/ (each prefixed by the selector byte 0,
// which makes fuzz_image read it as .exr): every compression tinyexr writes, half and float,
// RGB, RGBA, a lone Y channel, a tiled file, and a truncated one. Run once by hand:
//   g++ -std=c++20 tests/fuzz/tools/make_exr_seeds.cpp -ltinyexr -o /tmp/make_exr_seeds
//   /tmp/make_exr_seeds tests/fuzz/corpus/image
#include <tinyexr.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

namespace {

void write_seed(const std::string& path, const unsigned char* data, std::size_t size) {
    std::ofstream out(path, std::ios::binary);
    out.put('\0');  // selector: .exr
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
}

// Saves a width x height image with the given channels (names in alphabetical order) and
// writes the file, or its first `keep` bytes when keep > 0.
void save(const std::string& path, const std::vector<std::string>& names, int pixel_type, int compression,
          int width, int height, bool tiled, std::size_t keep = 0) {
    const int n = static_cast<int>(names.size());
    std::vector<std::vector<float>> planes(n, std::vector<float>(static_cast<std::size_t>(width) * height));
    for (int c = 0; c < n; ++c)
        for (std::size_t i = 0; i < planes[c].size(); ++i) planes[c][i] = 0.1f * static_cast<float>(c + 1) * (i % 7);
    std::vector<unsigned char*> pointers;
    for (auto& p : planes) pointers.push_back(reinterpret_cast<unsigned char*>(p.data()));
    std::vector<EXRChannelInfo> channels(n);
    // tinyexr converts float buffers to half or float only; a uint file is written from uint buffers
    // (the float bits, whatever numbers they make).
    const int buffer_type = pixel_type == TINYEXR_PIXELTYPE_UINT ? TINYEXR_PIXELTYPE_UINT : TINYEXR_PIXELTYPE_FLOAT;
    std::vector<int> types(n, buffer_type), stored(n, pixel_type);
    for (int c = 0; c < n; ++c) std::strcpy(channels[c].name, names[c].c_str());

    EXRHeader header;
    InitEXRHeader(&header);
    header.num_channels = n;
    header.channels = channels.data();
    header.pixel_types = types.data();
    header.requested_pixel_types = stored.data();
    header.compression_type = compression;
    EXRImage image;
    InitEXRImage(&image);
    image.num_channels = n;
    image.width = width;
    image.height = height;

    std::vector<EXRTile> tiles;
    std::vector<std::vector<std::vector<float>>> tile_planes;
    std::vector<std::vector<unsigned char*>> tile_pointers;
    if (tiled) {
        // 2x2 tiles over the image, one level.
        header.tiled = 1;
        header.tile_size_x = 2;
        header.tile_size_y = 2;
        header.tile_level_mode = TINYEXR_TILE_ONE_LEVEL;
        header.data_window.max_x = width - 1;  // tinyexr counts the tiles from the data window
        header.data_window.max_y = height - 1;
        const int tx = (width + 1) / 2, ty = (height + 1) / 2;
        tile_planes.resize(tx * ty);
        tile_pointers.resize(tx * ty);
        for (int y = 0; y < ty; ++y)
            for (int x = 0; x < tx; ++x) {
                const int t = y * tx + x;
                tile_planes[t].assign(n, std::vector<float>(4, 0.5f));
                for (auto& p : tile_planes[t]) tile_pointers[t].push_back(reinterpret_cast<unsigned char*>(p.data()));
                EXRTile tile{};
                tile.offset_x = x;
                tile.offset_y = y;
                tile.width = std::min(2, width - 2 * x);
                tile.height = std::min(2, height - 2 * y);
                tile.images = tile_pointers[t].data();
                tiles.push_back(tile);
            }
        image.tiles = tiles.data();
        image.num_tiles = static_cast<int>(tiles.size());
    } else {
        image.images = pointers.data();
    }

    unsigned char* memory = nullptr;
    const char* error = nullptr;
    const std::size_t size = SaveEXRImageToMemory(&image, &header, &memory, &error);
    if (size == 0) {
        std::fprintf(stderr, "%s: %s\n", path.c_str(), error ? error : "?");
        if (error) FreeEXRErrorMessage(error);
        return;
    }
    write_seed(path, memory, keep > 0 && keep < size ? keep : size);
    std::free(memory);
}

}  // namespace

int main(int argc, char** argv) {
    const std::string folder = argc > 1 ? argv[1] : ".";
    const std::vector<std::string> bgr = {"B", "G", "R"};
    save(folder + "/exr-zip-float.bin", bgr, TINYEXR_PIXELTYPE_FLOAT, TINYEXR_COMPRESSIONTYPE_ZIP, 4, 3, false);
    save(folder + "/exr-none-half.bin", bgr, TINYEXR_PIXELTYPE_HALF, TINYEXR_COMPRESSIONTYPE_NONE, 3, 2, false);
    save(folder + "/exr-rle-half.bin", bgr, TINYEXR_PIXELTYPE_HALF, TINYEXR_COMPRESSIONTYPE_RLE, 5, 2, false);
    save(folder + "/exr-zips-float.bin", {"A", "B", "G", "R"}, TINYEXR_PIXELTYPE_FLOAT, TINYEXR_COMPRESSIONTYPE_ZIPS, 3, 3, false);
    save(folder + "/exr-piz-half.bin", bgr, TINYEXR_PIXELTYPE_HALF, TINYEXR_COMPRESSIONTYPE_PIZ, 8, 4, false);
    save(folder + "/exr-grey-y.bin", {"Y"}, TINYEXR_PIXELTYPE_FLOAT, TINYEXR_COMPRESSIONTYPE_NONE, 2, 2, false);
    save(folder + "/exr-uint.bin", bgr, TINYEXR_PIXELTYPE_UINT, TINYEXR_COMPRESSIONTYPE_NONE, 2, 2, false);
    save(folder + "/exr-tiled.bin", bgr, TINYEXR_PIXELTYPE_HALF, TINYEXR_COMPRESSIONTYPE_NONE, 3, 3, true);
    save(folder + "/exr-truncated.bin", bgr, TINYEXR_PIXELTYPE_FLOAT, TINYEXR_COMPRESSIONTYPE_ZIP, 4, 3, false, 300);
    return 0;
}
