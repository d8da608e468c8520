// Making chapter 08's storage: the format chosen from the image, the tile size from the settings.
#include "freezeray/ch08/mip_mapped_storage.hpp"

#include "freezeray/ch08/texel_addressing.hpp"
#include "freezeray/ch08/texel_format.hpp"

#include <memory>
#include <stdexcept>
#include <string>

namespace freezeray::ch08 {

namespace {

template <typename Addressing>
std::shared_ptr<const TextureStorage> make_storage(const Image& image, const TextureLayoutSettings& settings) {
    if (settings.format == TexelFormatChoice::Auto)
        for (const ByteDecoding* decoding : byte_decodings())
            if (auto level0 = TexelLevel<Addressing, ByteTexels>::encode_exactly(image, ByteTexels{decoding}))
                return std::make_shared<MipMappedStorage<Addressing, ByteTexels>>(image, std::move(*level0), settings.filter);
    return std::make_shared<MipMappedStorage<Addressing, FloatTexels>>(
        image, TexelLevel<Addressing, FloatTexels>(image, FloatTexels{}), settings.filter);
}

}  // namespace

std::shared_ptr<const TextureStorage> make_row_major_storage(const Image& image, const TextureLayoutSettings& settings) {
    return make_storage<RowMajorAddressing>(image, settings);
}

std::shared_ptr<const TextureStorage> make_tiled_storage(const Image& image, const TextureLayoutSettings& settings) {
    switch (settings.tile_size) {
        case 2: return make_storage<TiledAddressing<1>>(image, settings);
        case 4: return make_storage<TiledAddressing<2>>(image, settings);
        case 8: return make_storage<TiledAddressing<3>>(image, settings);
        case 16: return make_storage<TiledAddressing<4>>(image, settings);
        case 32: return make_storage<TiledAddressing<5>>(image, settings);
        default: throw std::logic_error("tile size " + std::to_string(settings.tile_size) + " was not checked");
    }
}

}  // namespace freezeray::ch08
