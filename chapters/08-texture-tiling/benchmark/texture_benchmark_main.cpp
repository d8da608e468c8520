// texture-benchmark (chapter 08): lookups per second of one texture in each layout, filter and
// texel format, on the lookups a render of a scene makes: every camera ray of every pixel, 16 x
// 16 pixel tiles in the renderer's order, the texture coordinates and pixel footprint of each
// hit on a textured surface. Every configuration runs the same lookups, one after the other in
// one process, so that their ratios are measured side by side. The timed loop is
// `run_lookups`: under `valgrind --tool=callgrind --cache-sim=yes
// --toggle-collect='*run_lookups*'` its cache misses are counted apart from loading.
#include "freezeray/ch08/mip_mapped_storage.hpp"
#include "freezeray/ch08/texture_layout_settings.hpp"
#include "freezeray/complete_renderer.hpp"
#include "freezeray/error.hpp"
#include "freezeray/image.hpp"
#include "freezeray/random.hpp"
#include "freezeray/scene.hpp"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

using namespace freezeray;

namespace {

struct Configuration {
    std::string layout;  // linear or tiled
    ch08::TextureLayoutSettings settings;
    std::string name() const {
        std::string n = layout + "/" + (settings.filter == ch08::TextureFilter::Trilinear ? "trilinear" : "bilinear");
        if (layout == "tiled" && settings.tile_size != 4) n += "/" + std::to_string(settings.tile_size);
        return n;
    }
};

// "linear/bilinear", "tiled/trilinear", "tiled/trilinear/8".
Configuration parse_configuration(const std::string& text, ch08::TexelFormatChoice format) {
    Configuration c;
    c.settings.format = format;
    const std::size_t slash = text.find('/');
    c.layout = text.substr(0, slash);
    if (c.layout != "linear" && c.layout != "tiled") throw InputError("--configs", "unknown layout in '" + text + "'");
    if (slash == std::string::npos) return c;
    std::string rest = text.substr(slash + 1);
    const std::size_t second = rest.find('/');
    const std::string filter = rest.substr(0, second);
    if (filter == "bilinear") c.settings.filter = ch08::TextureFilter::Bilinear;
    else if (filter != "trilinear") throw InputError("--configs", "unknown filter in '" + text + "'");
    if (second != std::string::npos) {
        if (c.layout != "tiled") throw InputError("--configs", "only tiled textures have a tile size: '" + text + "'");
        c.settings.tile_size = std::stoi(rest.substr(second + 1));
    }
    return c;
}

// The lookups of every camera ray (spp per pixel, jittered) that hits a textured surface, in the
// renderer's order of 16 x 16 pixel tiles.
std::vector<TextureLookup> record_lookups(const Scene& scene, int spp, bool with_footprint) {
    std::vector<TextureLookup> lookups;
    const PinholeCamera& camera = *scene.camera;
    PCG32 random(1, 1);
    constexpr int TileSize = 16;
    for (int ty = 0; ty < camera.height(); ty += TileSize)
        for (int tx = 0; tx < camera.width(); tx += TileSize)
            for (int y = ty; y < std::min(ty + TileSize, camera.height()); ++y)
                for (int x = tx; x < std::min(tx + TileSize, camera.width()); ++x)
                    for (int s = 0; s < spp; ++s) {
                        const Vec2 film(static_cast<float>(x) + random.next_float(), static_cast<float>(y) + random.next_float());
                        const std::optional<Hit> hit = scene.intersect(camera.generate_ray(film));
                        if (!hit || !scene.material(*hit).is_textured()) continue;
                        TextureLookup lookup = hit->texture_lookup();
                        if (!with_footprint) lookup.duv_dx = lookup.duv_dy = Vec2(0.0f);
                        lookups.push_back(lookup);
                    }
    return lookups;
}

// The timed loop (named for callgrind's --toggle-collect): every lookup once; the sum keeps the
// compiler from dropping them.
[[gnu::noinline]] Spectrum run_lookups(const TextureStorage& storage, const std::vector<TextureLookup>& lookups) {
    Spectrum sum(0.0f);
    for (const TextureLookup& lookup : lookups) sum += storage.lookup(lookup, WrapMode::Repeat);
    return sum;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"texture-benchmark: lookups per second of one texture in chapter 08's layouts, on a scene's camera rays"};
    std::string scene_path, texture_path, format = "auto";
    std::vector<std::string> configurations{"linear/bilinear", "tiled/bilinear", "linear/trilinear", "tiled/trilinear"};
    int spp = 4, repetitions = 5;
    app.add_option("scene", scene_path, "the scene whose camera rays make the lookups")->required();
    app.add_option("texture", texture_path, "the image file looked up (decoded as an sRGB colour map)")->required();
    app.add_option("--configs", configurations,
                   "layout/filter[/tile size], comma-separated (default: linear/bilinear,tiled/bilinear,"
                   "linear/trilinear,tiled/trilinear); the first is the ratios' reference")
        ->delimiter(',');
    app.add_option("--texel-format", format, "auto or float (default: auto)");
    app.add_option("--spp", spp, "camera rays per pixel (default: 4)");
    app.add_option("--reps", repetitions, "timed passes over the lookups per configuration, after one warm-up (default: 5)");
    CLI11_PARSE(app, argc, argv);

    try {
        if (format != "auto" && format != "float") throw InputError("--texel-format", "expected auto or float, not '" + format + "'");
        const ch08::TexelFormatChoice format_choice =
            format == "float" ? ch08::TexelFormatChoice::Float : ch08::TexelFormatChoice::Auto;
        std::vector<Configuration> runs;
        for (const std::string& text : configurations) runs.push_back(parse_configuration(text, format_choice));
        if (spp < 1 || repetitions < 1) throw InputError("--spp/--reps", "must be at least 1");

        const Registry registry = make_complete_registry("texture-benchmark");
        SceneLoadOptions options;
        options.options.values["filter"] = "bilinear";  // the scene's own copy: no pyramid needed
        const Scene scene = load_scene(scene_path, registry, options);
        if (!scene.camera) throw InputError(scene_path, "has no camera");
        const Image image = read_image(texture_path);
        const std::vector<TextureLookup> with_footprint = record_lookups(scene, spp, true);
        if (with_footprint.empty()) throw InputError(scene_path, "no camera ray hits a textured surface");
        std::printf("texture %s: %d x %d texels; %zu lookups (%d camera rays per pixel of %d x %d)\n", texture_path.c_str(),
                    image.width(), image.height(), with_footprint.size(), spp, scene.camera->width(), scene.camera->height());
        std::printf("%-22s %-40s %10s %12s %12s %8s\n", "configuration", "storage", "memory MiB", "ns/lookup",
                    "Mlookups/s", "ratio");

        double reference = 0.0;
        for (const Configuration& run : runs) {
            const std::shared_ptr<const TextureStorage> storage =
                run.layout == "linear" ? ch08::make_row_major_storage(image, run.settings)
                                       : ch08::make_tiled_storage(image, run.settings);
            const auto& texture = dynamic_cast<const ch08::MipMappedTexture&>(*storage);
            Spectrum keep = run_lookups(*storage, with_footprint);  // warm-up
            double best = 1e300;
            for (int r = 0; r < repetitions; ++r) {
                const auto start = std::chrono::steady_clock::now();
                keep += run_lookups(*storage, with_footprint);
                best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
            }
            const double ns = best * 1e9 / static_cast<double>(with_footprint.size());
            if (reference == 0.0) reference = ns;
            std::printf("%-22s %-40s %10.1f %12.2f %12.2f %8.3f%s\n", run.name().c_str(), texture.description().c_str(),
                        static_cast<double>(texture.memory_bytes()) / (1024.0 * 1024.0), ns, 1e3 / ns, reference / ns,
                        keep.r < 0.0f ? " (negative sum?)" : "");
        }
        std::printf("ratio: speed relative to the first configuration (its ns/lookup over this one's); "
                    "the fastest of %d passes each\n", repetitions);
    } catch (const InputError& e) {
        std::cerr << "texture-benchmark: " << e.what() << "\n";
        return 1;
    }
    return 0;
}
