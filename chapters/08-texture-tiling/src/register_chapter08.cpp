// Chapter 08's registrations: two texture layouts with MIP maps and compact texels, and their
// settings (the scene's "textures" block, or the command line).
#include "freezeray/ch08/register_chapter08.hpp"
#include "freezeray/ch07/register_chapter07.hpp"

#include "freezeray/ch08/mip_mapped_storage.hpp"
#include "freezeray/ch08/texture_footprint.hpp"
#include "freezeray/ch08/texture_layout_settings.hpp"

namespace freezeray {

namespace {

// A layout of this chapter: its settings read once, then `make` for every image.
using MakeStorage = std::shared_ptr<const TextureStorage> (*)(const Image&, const ch08::TextureLayoutSettings&);
TextureLayoutFactory layout_factory(MakeStorage make) {
    return [make](const Parameters& parameters) -> TextureStorageMaker {
        const ch08::TextureLayoutSettings settings = ch08::read_texture_layout_settings(parameters);
        return {[make, settings](const Image& image) { return make(image, settings); },
                settings.filter == ch08::TextureFilter::Trilinear ? &ch08::add_texture_footprint : nullptr};
    };
}

}  // namespace

void register_chapter08(Registry& registry) {
    register_chapter07(registry);  // chapters 01 to 07 first
    registry.texture_layouts.add("linear", 8,
                                "rows of texels one after another, as the image file stores them, with MIP levels "
                                "and 8-bit texels where the file had them",
                                layout_factory(ch08::make_row_major_storage));
    registry.texture_layouts.add("tiled", 8,
                                "square tiles of texels (4 x 4 by default) that keep neighbours in one cache line, "
                                "with MIP levels and 8-bit texels where the file had them",
                                layout_factory(ch08::make_tiled_storage));
    registry.texture_layouts.set_default("tiled");
    registry.add_option({"--texture-filter", "filter", OptionType::Text, OptionTarget::Textures,
                         "textures: bilinear (level 0, as chapter 02) or trilinear (MIP levels chosen from the "
                         "pixel's footprint); default trilinear",
                         {"linear", "tiled"}, 8});
    registry.add_option({"--texel-format", "texel_format", OptionType::Text, OptionTarget::Textures,
                         "textures: auto (4 bytes a texel for images from 8-bit files, else floats) or float "
                         "(12 bytes a texel); default auto",
                         {"linear", "tiled"}, 8});
    registry.add_option({"--texture-tile-size", "tile_size", OptionType::Integer, OptionTarget::Textures,
                         "tiled textures: texels on a tile's side, 2, 4, 8, 16 or 32; default 4",
                         {"tiled"}, 8});
}

}  // namespace freezeray
