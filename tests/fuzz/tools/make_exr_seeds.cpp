// Writes the OpenEXR seeds of tests/fuzz/corpus/image/ (each prefixed by the selector byte 0,
// which makes fuzz_image read it as .exr) through OpenEXR itself: every compression OpenEXR
// writes, half, float and uint, RGB, RGBA, a lone Y channel, tiled files (one level and a
// mipmap), and a truncated one. Run once by hand:
//   g++ -std=c++20 tests/fuzz/tools/make_exr_seeds.cpp $(pkg-config --cflags --libs OpenEXR) -o /tmp/make_exr_seeds
//   /tmp/make_exr_seeds tests/fuzz/corpus/image
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfIO.h>
#include <ImfOutputFile.h>
#include <ImfTiledOutputFile.h>
#include <half.h>

#include <cstdint>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

namespace {

// An OpenEXR output stream into memory, so that a seed can be cut short before it is written.
class MemoryStream : public Imf::OStream {
public:
    MemoryStream() : Imf::OStream("seed") {}
    void write(const char c[], int n) override {
        if (position_ + n > bytes.size()) bytes.resize(position_ + n);
        std::memcpy(bytes.data() + position_, c, static_cast<std::size_t>(n));
        position_ += static_cast<std::size_t>(n);
    }
    std::uint64_t tellp() override { return position_; }
    void seekp(std::uint64_t position) override { position_ = position; }
    std::vector<char> bytes;

private:
    std::size_t position_ = 0;
};

struct Seed {
    std::vector<std::string> channels;
    Imf::PixelType type = Imf::FLOAT;
    Imf::Compression compression = Imf::NO_COMPRESSION;
    int width = 4, height = 3;
    int tile_size = 0;                          // 0: scan lines
    Imf::LevelMode levels = Imf::ONE_LEVEL;
    std::size_t cut = 0;                        // drop this many bytes from the end
};

// Writes the seed's file: every channel holds small whole numbers (exact in half, float and uint).
void save(const std::string& path, const Seed& seed) {
    const std::size_t count = static_cast<std::size_t>(seed.width) * seed.height;
    const std::size_t element = seed.type == Imf::HALF ? sizeof(half) : 4;
    std::vector<std::vector<char>> planes(seed.channels.size(), std::vector<char>(count * element));
    Imf::Header header(seed.width, seed.height, 1.0f, Imath::V2f(0.0f, 0.0f), 1.0f, Imf::INCREASING_Y, seed.compression);
    Imf::FrameBuffer frame;
    for (std::size_t c = 0; c < seed.channels.size(); ++c) {
        for (std::size_t i = 0; i < count; ++i) {
            const int value = static_cast<int>((c + 1) * (i % 7));
            char* at = planes[c].data() + i * element;
            if (seed.type == Imf::HALF) *reinterpret_cast<half*>(at) = half(static_cast<float>(value));
            if (seed.type == Imf::FLOAT) *reinterpret_cast<float*>(at) = static_cast<float>(value);
            if (seed.type == Imf::UINT) *reinterpret_cast<std::uint32_t*>(at) = static_cast<std::uint32_t>(value);
        }
        header.channels().insert(seed.channels[c], Imf::Channel(seed.type));
        frame.insert(seed.channels[c], Imf::Slice::Make(seed.type, planes[c].data(), header.dataWindow()));
    }
    MemoryStream stream;
    if (seed.tile_size == 0) {
        Imf::OutputFile file(stream, header);
        file.setFrameBuffer(frame);
        file.writePixels(seed.height);
    } else {
        header.setTileDescription(Imf::TileDescription(seed.tile_size, seed.tile_size, seed.levels));
        Imf::TiledOutputFile file(stream, header);
        file.setFrameBuffer(frame);
        // Every level from the same planes (the smaller levels read only their top left part).
        for (int level = 0; level < file.numLevels(); ++level) {
            file.writeTiles(0, file.numXTiles(level) - 1, 0, file.numYTiles(level) - 1, level);
        }
    }
    std::ofstream out(path, std::ios::binary);
    out.put('\0');  // selector: .exr
    out.write(stream.bytes.data(), static_cast<std::streamsize>(stream.bytes.size() - seed.cut));
}

}  // namespace

int main(int argc, char** argv) {
    const std::string folder = argc > 1 ? argv[1] : ".";
    const std::vector<std::string> rgb = {"R", "G", "B"};
    save(folder + "/exr-zip-float.bin", {rgb, Imf::FLOAT, Imf::ZIP_COMPRESSION});
    save(folder + "/exr-none-half.bin", {rgb, Imf::HALF, Imf::NO_COMPRESSION, 3, 2});
    save(folder + "/exr-rle-half.bin", {rgb, Imf::HALF, Imf::RLE_COMPRESSION, 5, 2});
    save(folder + "/exr-zips-float.bin", {{"A", "B", "G", "R"}, Imf::FLOAT, Imf::ZIPS_COMPRESSION, 3, 3});
    save(folder + "/exr-piz-half.bin", {rgb, Imf::HALF, Imf::PIZ_COMPRESSION, 8, 4});
    save(folder + "/exr-pxr24-float.bin", {rgb, Imf::FLOAT, Imf::PXR24_COMPRESSION, 4, 4});
    save(folder + "/exr-b44-half.bin", {rgb, Imf::HALF, Imf::B44_COMPRESSION, 5, 5});
    save(folder + "/exr-b44a-half.bin", {rgb, Imf::HALF, Imf::B44A_COMPRESSION, 4, 4});
    save(folder + "/exr-dwaa-half.bin", {rgb, Imf::HALF, Imf::DWAA_COMPRESSION, 9, 9});
    save(folder + "/exr-dwab-float.bin", {rgb, Imf::FLOAT, Imf::DWAB_COMPRESSION, 9, 9});
    save(folder + "/exr-grey-y.bin", {{"Y"}, Imf::FLOAT, Imf::NO_COMPRESSION, 2, 2});
    save(folder + "/exr-uint.bin", {rgb, Imf::UINT, Imf::NO_COMPRESSION, 2, 2});
    save(folder + "/exr-tiled.bin", {rgb, Imf::HALF, Imf::NO_COMPRESSION, 3, 3, 2});
    save(folder + "/exr-mipmap-zip.bin", {rgb, Imf::FLOAT, Imf::ZIP_COMPRESSION, 5, 3, 2, Imf::MIPMAP_LEVELS});
    save(folder + "/exr-truncated.bin", {rgb, Imf::FLOAT, Imf::ZIP_COMPRESSION, 4, 3, 0, Imf::ONE_LEVEL, 20});
    return 0;
}
