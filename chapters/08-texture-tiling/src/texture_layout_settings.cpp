// Reading the texture layouts' settings.
#include "freezeray/ch08/texture_layout_settings.hpp"

#include "freezeray/error.hpp"

namespace freezeray::ch08 {

TextureLayoutSettings read_texture_layout_settings(const Parameters& parameters) {
    TextureLayoutSettings settings;
    const std::string filter = parameters.get_string("filter", "trilinear");
    if (filter == "bilinear") {
        settings.filter = TextureFilter::Bilinear;
    } else if (filter != "trilinear") {
        throw InputError(parameters.where("filter"), "unknown texture filter '" + filter + "'; valid: bilinear, trilinear");
    }
    const std::string format = parameters.get_string("texel_format", "auto");
    if (format == "float") {
        settings.format = TexelFormatChoice::Float;
    } else if (format != "auto") {
        throw InputError(parameters.where("texel_format"), "unknown texel format '" + format + "'; valid: auto, float");
    }
    settings.tile_size = parameters.get_int("tile_size", settings.tile_size);
    if (!is_valid_tile_size(settings.tile_size))
        throw InputError(parameters.where("tile_size"),
                         "a tile is 2, 4, 8, 16 or 32 texels on a side, not " + std::to_string(settings.tile_size));
    return settings;
}

}  // namespace freezeray::ch08
