// texture-benchmark (chapter 08): lookups per second of one texture in each layout, filter and
// texel format, on the lookups a render of a scene makes: every camera ray of every pixel, 16 x
// 16 pixel tiles in the renderer's order, the texture coordinates and pixel footprint of each
// hit on a textured surface. Every configuration runs the same lookups, one after the other in
// one process, so that their ratios are measured side by side. Under
// `valgrind --tool=callgrind --instr-atstart=no` only the lookups are simulated: the timed
// passes, after a warm-up pass (callgrind's counts then start from zero), one dump per
// configuration. (`--toggle-collect='*run_lookups*'` counts the same loop with everything
// simulated.) Each
// configuration also replays its lookups through a model of the caches (cache_model.hpp) fed
// with the cache lines of the texels they read: lines per lookup, and misses per lookup of each
// level, the texture's own traffic and nothing else.
#include "cache_model.hpp"
#include "freezeray/ch08/mip_mapped_storage.hpp"
#include "freezeray/ch08/texture_layout_settings.hpp"
#include "freezeray/complete_renderer.hpp"
#include "freezeray/error.hpp"
#include "freezeray/image.hpp"
#include "freezeray/random.hpp"
#include "freezeray/scene.hpp"

#include <CLI/CLI.hpp>

// Under valgrind's callgrind, only the timed passes are simulated (see the top of this file);
// elsewhere these requests do nothing. Without valgrind's header they are left out.
#if __has_include(<valgrind/callgrind.h>)
#include <valgrind/callgrind.h>
#else
#define CALLGRIND_START_INSTRUMENTATION
#define CALLGRIND_STOP_INSTRUMENTATION
#define CALLGRIND_ZERO_STATS
#define CALLGRIND_DUMP_STATS_AT(name)
#endif

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
        const std::string size = rest.substr(second + 1);
        c.settings.tile_size = size.empty() || size.find_first_not_of("0123456789") != std::string::npos || size.size() > 3
                                   ? 0
                                   : std::stoi(size);
        if (c.settings.tile_size != 2 && c.settings.tile_size != 4 && c.settings.tile_size != 8 &&
            c.settings.tile_size != 16 && c.settings.tile_size != 32)
            throw InputError("--configs", "a tile is 2, 4, 8, 16 or 32 texels on a side, not '" + size + "' in '" + text + "'");
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
    bool json = false;
    app.add_option("scene", scene_path, "the scene whose camera rays make the lookups")->required();
    app.add_option("texture", texture_path, "the image file looked up (decoded as an sRGB colour map)")->required();
    app.add_option("--configs", configurations,
                   "layout/filter[/tile size], comma-separated (default: linear/bilinear,tiled/bilinear,"
                   "linear/trilinear,tiled/trilinear); the first is the ratios' reference")
        ->delimiter(',');
    app.add_option("--texel-format", format, "auto or float (default: auto)");
    app.add_option("--spp", spp, "camera rays per pixel (default: 4)");
    app.add_option("--reps", repetitions, "timed passes over the lookups per configuration, after one warm-up (default: 5)");
    app.add_flag("--json", json, "one JSON object per configuration on standard output instead of the table");
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
        if (!json) std::printf("texture %s: %d x %d texels; %zu lookups (%d camera rays per pixel of %d x %d)\n", texture_path.c_str(),
                    image.width(), image.height(), with_footprint.size(), spp, scene.camera->width(), scene.camera->height());
        if (!json) std::printf("%-20s %-38s %8s %9s %8s %7s %7s %7s %7s %7s\n", "configuration", "storage", "MiB", "ns/lookup",
                    "ratio", "texels", "lines", "L1miss", "L2miss", "L3miss");

        double reference = 0.0;
        for (const Configuration& run : runs) {
            const std::shared_ptr<const TextureStorage> storage =
                run.layout == "linear" ? ch08::make_row_major_storage(image, run.settings)
                                       : ch08::make_tiled_storage(image, run.settings);
            const auto& texture = dynamic_cast<const ch08::MipMappedTexture&>(*storage);
            CALLGRIND_START_INSTRUMENTATION;
            Spectrum keep = run_lookups(*storage, with_footprint);  // warm-up
            CALLGRIND_ZERO_STATS;
            double best = 1e300;
            for (int r = 0; r < repetitions; ++r) {
                const auto start = std::chrono::steady_clock::now();
                keep += run_lookups(*storage, with_footprint);
                best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
            }
            CALLGRIND_DUMP_STATS_AT(run.name().c_str());
            CALLGRIND_STOP_INSTRUMENTATION;
            const double ns = best * 1e9 / static_cast<double>(with_footprint.size());
            if (reference == 0.0) reference = ns;

            // The same lookups through the cache model: per lookup, texels read, distinct lines.
            ch08::CacheHierarchyModel caches;
            std::vector<std::uintptr_t> lines;
            std::uint64_t texels = 0, distinct = 0;
            for (const TextureLookup& lookup : with_footprint) {
                lines.clear();
                keep += texture.lookup_recording_lines(lookup, WrapMode::Repeat, lines);
                texels += lines.size();
                for (const std::uintptr_t line : lines) caches.read(line);
                std::sort(lines.begin(), lines.end());
                distinct += static_cast<std::uint64_t>(std::unique(lines.begin(), lines.end()) - lines.begin());
            }
            const double n = static_cast<double>(with_footprint.size());
            if (json) {
                std::printf("{\"configuration\": \"%s\", \"storage\": \"%s\", \"format\": \"%s\", \"lookups\": %zu, "
                            "\"memory_mib\": %.3f, \"ns_per_lookup\": %.4f, \"speed_ratio\": %.5f, "
                            "\"texels_per_lookup\": %.4f, \"lines_per_lookup\": %.4f, \"l1_misses_per_lookup\": %.5f, "
                            "\"l2_misses_per_lookup\": %.5f, \"l3_misses_per_lookup\": %.5f}\n",
                            run.name().c_str(), texture.description().c_str(), format.c_str(), with_footprint.size(),
                            static_cast<double>(texture.memory_bytes()) / (1024.0 * 1024.0), ns, reference / ns,
                            static_cast<double>(texels) / n, static_cast<double>(distinct) / n,
                            static_cast<double>(caches.l1_misses) / n, static_cast<double>(caches.l2_misses) / n,
                            static_cast<double>(caches.l3_misses) / n);
                continue;
            }
            std::printf("%-20s %-38s %8.1f %9.2f %8.3f %7.2f %7.2f %7.3f %7.3f %7.3f%s\n", run.name().c_str(),
                        texture.description().c_str(), static_cast<double>(texture.memory_bytes()) / (1024.0 * 1024.0), ns,
                        reference / ns, static_cast<double>(texels) / n, static_cast<double>(distinct) / n,
                        static_cast<double>(caches.l1_misses) / n, static_cast<double>(caches.l2_misses) / n,
                        static_cast<double>(caches.l3_misses) / n, keep.r < 0.0f ? " (negative sum?)" : "");
        }
        if (!json) std::printf("ns/lookup: the fastest of %d passes; ratio: the first configuration's ns/lookup over this one's "
                    "(its speed relative to the first). Per lookup: texels read, distinct 64-byte lines among them, and "
                    "misses of a model of this processor's caches (L1 32 KiB 8-way, L2 1 MiB 8-way, L3 32 MiB 16-way, "
                    "LRU) fed with the texture's reads alone, in the lookups' order\n",
                    repetitions);
    } catch (const InputError& e) {
        std::cerr << "texture-benchmark: " << e.what() << "\n";
        return 1;
    }
    return 0;
}
