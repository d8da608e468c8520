// texture-benchmark (chapter 08): lookups per second of a scene's textures in each layout, filter
// and texel format, on the lookups a render of the scene makes: every camera ray of every pixel,
// 16 x 16 pixel tiles in the renderer's order, and every texture lookup of its first hit (the
// material's textures and the alpha masks the ray met on its way), with the pixel footprint the
// renderer gives it. The scene is loaded once with a layout that notes each lookup (which
// texture, where, with which footprint); then every configuration stores the same images again
// and replays the same lookups, one after the other in one process, so that their ratios are
// measured side by side.
//
// Under `valgrind --tool=callgrind --instr-atstart=no` only the lookups are simulated: the timed
// passes, after a warm-up pass (callgrind's counts then start from zero), one dump per
// configuration. (`--toggle-collect='*run_lookups*'` counts the same loop with everything
// simulated.) Each configuration also replays its lookups through a model of the caches
// (cache_model.hpp) fed with the cache lines of the texels they read: lines per lookup, and
// misses per lookup of each level, the textures' own traffic and nothing else.
//
// --access-map FILE.png draws, for one 16 x 16 pixel tile (--map-tile), which texels its
// lookups read and which texels came into the caches with them (the rest of their lines), one
// panel per configuration side by side: the picture of what a layout wastes.
#include "cache_model.hpp"
#include "freezeray/ch08/mip_mapped_storage.hpp"
#include "freezeray/ch08/texture_footprint.hpp"
#include "freezeray/ch08/texture_layout_settings.hpp"
#include "freezeray/complete_renderer.hpp"
#include "freezeray/error.hpp"
#include "freezeray/false_colour.hpp"
#include "freezeray/image.hpp"
#include "freezeray/random.hpp"
#include "freezeray/scene.hpp"
#include "freezeray/scene_loader.hpp"
#include "freezeray/scratch_arena.hpp"

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
#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>
#include <set>
#include <string>
#include <vector>

using namespace freezeray;

namespace {

constexpr int PixelTileSize = 16;  // the renderer's tiles of pixels

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
        if (!ch08::is_valid_tile_size(c.settings.tile_size))
            throw InputError("--configs", "a tile is 2, 4, 8, 16 or 32 texels on a side, not '" + size + "' in '" + text + "'");
    }
    return c;
}

// One lookup the render made: of which texture (in the order the scene loaded them), where, with
// which wrap mode, and in which tile of pixels.
struct RecordedLookup {
    std::uint32_t texture;
    WrapMode wrap;
    TextureLookup lookup;
    std::uint32_t pixel_tile;  // tile_y * tiles_per_row + tile_x
};

// The scene's textures as decoded (each stored again by every configuration) and its lookups.
struct Recording {
    std::vector<Image> images;
    std::vector<RecordedLookup> lookups;
    bool on = false;
    std::uint32_t pixel_tile = 0;  // the tile being rendered
};

// The layout the scene is loaded with: it keeps a copy of each image and notes every lookup made
// while recording is on; the values it returns are a row-major bilinear lookup's (they only
// decide, for alpha masks, whether the ray goes on).
class RecordingStorage final : public TextureStorage {
public:
    RecordingStorage(const Image& image, Recording& recording)
        : TextureStorage(image), recording_(recording), index_(static_cast<std::uint32_t>(recording.images.size())),
          stored_(ch08::make_row_major_storage(image, point_settings())) {
        recording.images.push_back(image);
    }
    Spectrum lookup(const TextureLookup& lookup, WrapMode wrap) const override {
        if (recording_.on) recording_.lookups.push_back({index_, wrap, lookup, recording_.pixel_tile});
        return stored_->lookup(lookup, wrap);
    }
    Spectrum texel(int x, int y) const override { return stored_->texel(x, y); }
    std::size_t memory_bytes() const override { return stored_->memory_bytes(); }
    std::string description() const override { return "recording: " + stored_->description(); }

private:
    static ch08::TextureLayoutSettings point_settings() {
        ch08::TextureLayoutSettings settings;
        settings.filter = ch08::TextureFilter::Bilinear;
        return settings;
    }
    Recording& recording_;
    std::uint32_t index_;
    std::shared_ptr<const TextureStorage> stored_;
};

// Renders the first hits of every camera ray (spp per pixel, jittered) in the renderer's order of
// 16 x 16 pixel tiles, with recording on: the materials build their BSDFs, which look their
// textures up.
void record_lookups(const Scene& scene, int spp, Recording& recording) {
    const Camera& camera = *scene.camera;
    PCG32 random(1, 1);
    ScratchArena arena;
    const int tiles_per_row = (camera.width() + PixelTileSize - 1) / PixelTileSize;
    recording.on = true;
    for (int ty = 0; ty < camera.height(); ty += PixelTileSize)
        for (int tx = 0; tx < camera.width(); tx += PixelTileSize) {
            recording.pixel_tile = static_cast<std::uint32_t>((ty / PixelTileSize) * tiles_per_row + tx / PixelTileSize);
            for (int y = ty; y < std::min(ty + PixelTileSize, camera.height()); ++y)
                for (int x = tx; x < std::min(tx + PixelTileSize, camera.width()); ++x)
                    for (int s = 0; s < spp; ++s) {
                        const Vec2 film(static_cast<float>(x) + random.next_float(), static_cast<float>(y) + random.next_float());
                        const std::optional<Hit> hit = scene.intersect(camera.generate_ray(film));
                        if (!hit) continue;
                        const Material& material = scene.material(*hit);
                        if (material.is_textured()) material.bsdf(*hit, arena);
                        arena.reset();
                    }
        }
    recording.on = false;
}

// The timed loop (named for callgrind's --toggle-collect): every lookup once; the sum keeps the
// compiler from dropping them.
[[gnu::noinline]] Spectrum run_lookups(const std::vector<std::shared_ptr<const TextureStorage>>& textures,
                                       const std::vector<RecordedLookup>& lookups) {
    Spectrum sum(0.0f);
    for (const RecordedLookup& r : lookups) sum += textures[r.texture]->lookup(r.lookup, r.wrap);
    return sum;
}

const ch08::MipMappedTexture& as_mip_mapped(const std::shared_ptr<const TextureStorage>& storage) {
    return dynamic_cast<const ch08::MipMappedTexture&>(*storage);
}

// "tiled (4 x 4), 8-bit sRGB, 14 levels" for one texture; for several, the layout and how many
// are kept in bytes: "tiled (4 x 4): 36 textures, 30 in 8-bit".
std::string storage_summary(const std::vector<std::shared_ptr<const TextureStorage>>& textures) {
    if (textures.size() == 1) return as_mip_mapped(textures.front()).description();
    int bytes = 0;
    for (const auto& t : textures) bytes += as_mip_mapped(t).description().find("8-bit") != std::string::npos ? 1 : 0;
    const std::string first = as_mip_mapped(textures.front()).description();
    return first.substr(0, first.find(',')) + ": " + std::to_string(textures.size()) + " textures, " +
           std::to_string(bytes) + " in 8-bit";
}

// One panel of the access map: the level of `texture` that `reads` (one pixel tile's) read most,
// cropped around them; each texel dark (its cache line was not read), grey (its line was read,
// the texel was not: bytes fetched for nothing) or coloured by how often it was read (viridis,
// once: dark blue, the most: yellow).
struct AccessPanel {
    Image image;
    std::size_t texels_read = 0, lines = 0;  // on the level shown; lines: on all levels
    int level = 0, x0 = 0, y0 = 0, width = 0, height = 0;  // the texels shown
};

AccessPanel access_panel(const ch08::MipMappedTexture& texture, const std::vector<ch08::TexelRead>& reads) {
    // The level read most (the finer of two equally read), cropped to its reads' bounds.
    std::map<int, std::size_t> per_level;
    for (const ch08::TexelRead& read : reads) ++per_level[read.level];
    int level = per_level.begin()->first;
    for (const auto& [l, n] : per_level)
        if (n > per_level[level]) level = l;
    int x0 = texture.level_width(level), y0 = texture.level_height(level), x1 = 0, y1 = 0;
    for (const ch08::TexelRead& read : reads)
        if (read.level == level) {
            x0 = std::min(x0, read.x), y0 = std::min(y0, read.y);
            x1 = std::max(x1, read.x), y1 = std::max(y1, read.y);
        }
    // A margin of a line's worth (16 texels of bytes) around the reads, the crop's edges on
    // multiples of 16 so that every panel cuts tiles and lines at their edges; at most 192 texels
    // a side, drawn about 384 pixels tall.
    constexpr int Margin = 16, MaxSide = 192;
    x0 = std::max(0, (x0 - Margin) / 16 * 16), y0 = std::max(0, (y0 - Margin) / 16 * 16);
    x1 = (x1 + Margin + 16) / 16 * 16, y1 = (y1 + Margin + 16) / 16 * 16;  // one past the crop
    const int width = std::min(MaxSide, x1 - x0), height = std::min(MaxSide, y1 - y0);
    const int scale = std::max(1, 384 / std::max(width, height));

    std::map<std::pair<int, int>, int> count;
    std::set<std::uintptr_t> lines;
    for (const ch08::TexelRead& read : reads) {
        lines.insert(texture.cache_line(read.level, read.x, read.y));
        if (read.level == level) ++count[{read.x, read.y}];
    }
    int most = 1;
    for (const auto& [texel, n] : count) most = std::max(most, n);
    AccessPanel panel{Image(width * scale, height * scale), count.size(), lines.size(), level, x0, y0, width, height};
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const int tx = x0 + x, ty = y0 + y;
            Spectrum colour(0.003f);  // not fetched
            if (tx < texture.level_width(level) && ty < texture.level_height(level)) {
                const auto read = count.find({tx, ty});
                if (read != count.end())
                    colour = viridis_linear(0.15 + 0.85 * std::log(static_cast<double>(read->second)) /
                                                       std::max(1e-9, std::log(static_cast<double>(most))));
                else if (lines.contains(texture.cache_line(level, tx, ty)))
                    colour = Spectrum(0.12f);
            }
            for (int sy = 0; sy < scale; ++sy)
                for (int sx = 0; sx < scale; ++sx) panel.image.at(x * scale + sx, y * scale + sy) = colour;
        }
    return panel;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"texture-benchmark: lookups per second of a scene's textures in chapter 08's layouts, on its camera rays"};
    std::string scene_path, format = "auto", access_map;
    std::vector<std::string> configurations{"linear/bilinear", "tiled/bilinear", "linear/trilinear", "tiled/trilinear"};
    std::vector<int> map_tile;
    int spp = 4, repetitions = 5;
    bool json = false;
    app.add_option("scene", scene_path, "the scene whose camera rays make the lookups")->required();
    app.add_option("--configs", configurations,
                   "layout/filter[/tile size], comma-separated (default: linear/bilinear,tiled/bilinear,"
                   "linear/trilinear,tiled/trilinear); the first is the ratios' reference")
        ->delimiter(',');
    app.add_option("--texel-format", format, "auto or float (default: auto)");
    app.add_option("--spp", spp, "camera rays per pixel (default: 4)");
    app.add_option("--reps", repetitions, "timed passes over the lookups per configuration, after one warm-up (default: 5)");
    app.add_flag("--json", json, "one JSON object per configuration on standard output instead of the table");
    app.add_option("--access-map", access_map,
                   "write a PNG of the texels one tile of pixels reads and the cache lines that brings in, a panel "
                   "per configuration");
    app.add_option("--map-tile", map_tile, "the tile of 16 x 16 pixels the access map shows: column,row (default 0,0)")
        ->delimiter(',')
        ->expected(2);
    CLI11_PARSE(app, argc, argv);

    try {
        if (format != "auto" && format != "float") throw InputError("--texel-format", "expected auto or float, not '" + format + "'");
        const ch08::TexelFormatChoice format_choice =
            format == "float" ? ch08::TexelFormatChoice::Float : ch08::TexelFormatChoice::Auto;
        std::vector<Configuration> runs;
        for (const std::string& text : configurations) runs.push_back(parse_configuration(text, format_choice));
        if (spp < 1 || repetitions < 1) throw InputError("--spp/--reps", "must be at least 1");
        if (map_tile.empty()) map_tile = {0, 0};
        if (!access_map.empty()) check_image_writable(access_map);

        // The scene loaded with the recording layout (footprints on, as the trilinear filter has them).
        Recording recording;
        Registry registry = make_complete_registry("texture-benchmark");
        registry.texture_layouts.add("recording", 8, "texture-benchmark's: notes every lookup",
                                    [&recording](const Parameters&) -> TextureStorageMaker {
                                        return {[&recording](const Image& image) {
                                                    return std::make_shared<RecordingStorage>(image, recording);
                                                },
                                                &ch08::add_texture_footprint};
                                    });
        SceneLoadOptions options;
        options.selections[CapabilityKind::TextureLayout] = "recording";
        const Scene scene = load_scene(scene_path, registry, options);
        if (!scene.camera) throw InputError(scene_path, "has no camera");
        if (recording.images.empty()) throw InputError(scene_path, "has no image textures");
        const int tiles_per_row = (scene.camera->width() + PixelTileSize - 1) / PixelTileSize;
        const int tile_rows = (scene.camera->height() + PixelTileSize - 1) / PixelTileSize;
        if (map_tile[0] < 0 || map_tile[1] < 0 || map_tile[0] >= tiles_per_row || map_tile[1] >= tile_rows)
            throw InputError("--map-tile", "the image has " + std::to_string(tiles_per_row) + " x " +
                                               std::to_string(tile_rows) + " tiles of 16 x 16 pixels; no tile " +
                                               std::to_string(map_tile[0]) + "," + std::to_string(map_tile[1]));
        record_lookups(scene, spp, recording);
        const std::vector<RecordedLookup>& lookups = recording.lookups;
        if (lookups.empty()) throw InputError(scene_path, "no camera ray's hit looks up a texture");
        if (!json)
            std::printf("%s: %zu textures; %zu lookups (%d camera rays per pixel of %d x %d)\n", scene_path.c_str(),
                        recording.images.size(), lookups.size(), spp, scene.camera->width(), scene.camera->height());
        if (!json)
            std::printf("%-20s %-38s %8s %9s %8s %7s %7s %7s %7s %7s\n", "configuration", "storage", "MiB", "ns/lookup",
                        "ratio", "texels", "lines", "L1miss", "L2miss", "L3miss");

        // The access map's tile: how many lookups of each texture it makes, and the one it reads most.
        const std::uint32_t chosen_tile = static_cast<std::uint32_t>(map_tile[1] * tiles_per_row + map_tile[0]);
        std::size_t tile_lookups = 0;
        std::map<std::uint32_t, std::size_t> per_texture;
        for (const RecordedLookup& r : lookups)
            if (r.pixel_tile == chosen_tile) {
                ++tile_lookups;
                ++per_texture[r.texture];
            }
        if (!access_map.empty() && tile_lookups == 0)
            throw InputError("--map-tile", "tile " + std::to_string(map_tile[0]) + "," + std::to_string(map_tile[1]) +
                                               " looks up no texture");
        std::uint32_t map_texture = per_texture.empty() ? 0 : per_texture.begin()->first;
        for (const auto& [texture, n] : per_texture)
            if (n > per_texture[map_texture]) map_texture = texture;
        std::vector<AccessPanel> panels;

        double reference = 0.0;
        for (const Configuration& run : runs) {
            std::vector<std::shared_ptr<const TextureStorage>> textures;
            std::size_t memory = 0;
            for (const Image& image : recording.images) {
                textures.push_back(run.layout == "linear" ? ch08::make_row_major_storage(image, run.settings)
                                                          : ch08::make_tiled_storage(image, run.settings));
                memory += as_mip_mapped(textures.back()).memory_bytes();
            }
            CALLGRIND_START_INSTRUMENTATION;
            Spectrum keep = run_lookups(textures, lookups);  // warm-up
            CALLGRIND_ZERO_STATS;
            double best = 1e300;
            for (int r = 0; r < repetitions; ++r) {
                const auto start = std::chrono::steady_clock::now();
                keep += run_lookups(textures, lookups);
                best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
            }
            const std::string name = run.name();  // alive while callgrind reads it
            CALLGRIND_DUMP_STATS_AT(name.c_str());
            CALLGRIND_STOP_INSTRUMENTATION;
            const double ns = best * 1e9 / static_cast<double>(lookups.size());
            if (reference == 0.0) reference = ns;

            // The same lookups through the cache model: per lookup, texels read, distinct lines; and
            // the access map's tile's reads of its texture.
            ch08::CacheHierarchyModel caches;
            std::vector<ch08::TexelRead> reads, tile_reads;
            std::vector<std::uintptr_t> lines;
            std::uint64_t texels = 0, distinct = 0;
            for (const RecordedLookup& r : lookups) {
                reads.clear();
                lines.clear();
                const ch08::MipMappedTexture& texture = as_mip_mapped(textures[r.texture]);
                keep += texture.lookup_recording_reads(r.lookup, r.wrap, reads);
                if (r.pixel_tile == chosen_tile && r.texture == map_texture)
                    tile_reads.insert(tile_reads.end(), reads.begin(), reads.end());
                for (const ch08::TexelRead& read : reads) lines.push_back(texture.cache_line(read.level, read.x, read.y));
                texels += lines.size();
                for (const std::uintptr_t line : lines) caches.read(line);
                std::sort(lines.begin(), lines.end());
                distinct += static_cast<std::uint64_t>(std::unique(lines.begin(), lines.end()) - lines.begin());
            }

            if (!access_map.empty()) {
                const AccessPanel& panel = panels.emplace_back(access_panel(as_mip_mapped(textures[map_texture]), tile_reads));
                std::fprintf(stderr,
                             "access map, %s: tile %d,%d, texture %u (%zu of the tile's %zu lookups), level %d, texels "
                             "[%d, %d] x [%d, %d]: %zu texels read, %zu cache lines (all levels)\n",
                             name.c_str(), map_tile[0], map_tile[1], map_texture, per_texture[map_texture], tile_lookups,
                             panel.level, panel.x0, panel.x0 + panel.width - 1, panel.y0, panel.y0 + panel.height - 1,
                             panel.texels_read, panel.lines);
            }

            const double n = static_cast<double>(lookups.size());
            const std::string storage = storage_summary(textures);
            if (json) {
                std::printf("{\"configuration\": \"%s\", \"storage\": \"%s\", \"format\": \"%s\", \"textures\": %zu, "
                            "\"lookups\": %zu, \"memory_mib\": %.3f, \"ns_per_lookup\": %.4f, \"speed_ratio\": %.5f, "
                            "\"texels_per_lookup\": %.4f, \"lines_per_lookup\": %.4f, \"l1_misses_per_lookup\": %.5f, "
                            "\"l2_misses_per_lookup\": %.5f, \"l3_misses_per_lookup\": %.5f}\n",
                            run.name().c_str(), storage.c_str(), format.c_str(), textures.size(), lookups.size(),
                            static_cast<double>(memory) / (1024.0 * 1024.0), ns, reference / ns,
                            static_cast<double>(texels) / n, static_cast<double>(distinct) / n,
                            static_cast<double>(caches.l1_misses) / n, static_cast<double>(caches.l2_misses) / n,
                            static_cast<double>(caches.l3_misses) / n);
                continue;
            }
            std::printf("%-20s %-38s %8.1f %9.2f %8.3f %7.2f %7.2f %7.3f %7.3f %7.3f%s\n", run.name().c_str(),
                        storage.c_str(), static_cast<double>(memory) / (1024.0 * 1024.0), ns, reference / ns,
                        static_cast<double>(texels) / n, static_cast<double>(distinct) / n,
                        static_cast<double>(caches.l1_misses) / n, static_cast<double>(caches.l2_misses) / n,
                        static_cast<double>(caches.l3_misses) / n, keep.r < 0.0f ? " (negative sum?)" : "");
        }
        if (!json)
            std::printf("ns/lookup: the fastest of %d passes; ratio: the first configuration's ns/lookup over this one's "
                        "(its speed relative to the first). Per lookup: texels read, distinct 64-byte lines among them, and "
                        "misses of a model of a common server core's caches (L1 32 KiB 8-way, L2 1 MiB 8-way, L3 32 MiB 16-way, "
                        "LRU) fed with the textures' reads alone, in the lookups' order\n",
                        repetitions);

        if (!access_map.empty()) {
            // The panels side by side, in the order of --configs, 8 pixels of white between them.
            constexpr int Gap = 8;
            int width = 0, height = 0;
            for (const AccessPanel& p : panels) width += p.image.width() + (width > 0 ? Gap : 0), height = std::max(height, p.image.height());
            Image map(width, height);
            for (Spectrum& pixel : map.pixels()) pixel = Spectrum(1.0f);
            int left = 0;
            for (const AccessPanel& p : panels) {
                for (int y = 0; y < p.image.height(); ++y)
                    for (int x = 0; x < p.image.width(); ++x) map.at(left + x, y) = p.image.at(x, y);
                left += p.image.width() + Gap;
            }
            write_image(access_map, map);
            std::fprintf(stderr, "access map: %s\n", access_map.c_str());
        }
    } catch (const InputError& e) {
        std::cerr << "texture-benchmark: " << e.what() << "\n";
        return 1;
    }
    return 0;
}
