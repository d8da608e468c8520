// sampler-points (chapter 09): the 2-D points a sampler gives one pixel, one "x,y" line per
// sample, for the book's figures of point sets (qmc_figures.py point-sets). Besides the
// registered samplers, "sobol-unscrambled" prints Sobol dimensions 0 and 1 themselves.
#include "freezeray/ch09/sobol_matrices.hpp"
#include "freezeray/complete_renderer.hpp"
#include "freezeray/error.hpp"
#include "freezeray/sampler.hpp"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <iostream>
#include <memory>
#include <string>

using namespace freezeray;

int main(int argc, char** argv) {
    CLI::App app{"sampler-points: the 2-D points a sampler gives one pixel, as CSV lines x,y"};
    std::string sampler_name = "sobol";
    std::string draw = "pixel";
    std::uint64_t count = 256;
    int vertex = 1, x = 0, y = 0, width = 64, height = 64;
    std::uint64_t seed = 0;
    app.add_option("--sampler", sampler_name, "a registered sampler, or sobol-unscrambled (default sobol)");
    app.add_option("--count", count, "samples, numbered from 0 (default 256)");
    app.add_option("--draw", draw, "pixel (the position in the pixel, dimensions 0 and 1) or bsdf (a vertex's BSDF direction)")
        ->check(CLI::IsMember({"pixel", "bsdf"}));
    app.add_option("--vertex", vertex, "the path vertex of --draw bsdf (1: the camera ray's hit; default 1)");
    app.add_option("--pixel-x", x, "the pixel's column (default 0)");
    app.add_option("--pixel-y", y, "the pixel's row (default 0)");
    app.add_option("--width", width, "the image's width, for samplers that plan over it (default 64)");
    app.add_option("--height", height, "the image's height (default 64)");
    app.add_option("--seed", seed, "the render's seed (default 0)");
    CLI11_PARSE(app, argc, argv);
    try {
        if (count < 1 || count > (1u << 24)) throw InputError("--count", "must be between 1 and 2^24");
        if (vertex < 1 || vertex > 64) throw InputError("--vertex", "must be between 1 and 64");
        if (width < 1 || height < 1) throw InputError("--width/--height", "must be at least 1");
        if (x < 0 || x >= width || y < 0 || y >= height) throw InputError("--pixel-x/--pixel-y", "lies outside the image");
        if (sampler_name == "sobol-unscrambled") {
            // Sobol's first two dimensions (a (0, 2)-sequence), as the scrambles receive them.
            for (std::uint64_t i = 0; i < count; ++i)
                std::printf("%.9g,%.9g\n", ch09::sobol_sample(static_cast<std::uint32_t>(i), 0),
                            ch09::sobol_sample(static_cast<std::uint32_t>(i), 1));
            return 0;
        }
        const Registry registry = make_complete_registry("sampler-points");
        const std::unique_ptr<Sampler> sampler = registry.samplers.make(sampler_name, "--sampler", Parameters::none());
        sampler->set_seed(seed);
        sampler->plan_render(width, height, count);
        const auto pixel_index = static_cast<std::uint32_t>(y * width + x);
        for (std::uint64_t i = 0; i < count; ++i) {
            sampler->start_pixel_sample(x, y, pixel_index, i);
            Vec2 p;
            if (draw == "pixel") {
                p = sampler->pixel_2d();
            } else {
                sampler->start_vertex(vertex);
                p = sampler->get_2d(VertexDimension::BsdfDirection);
            }
            std::printf("%.9g,%.9g\n", p.x, p.y);
        }
    } catch (const InputError& e) {
        std::cerr << "sampler-points: " << e.what() << "\n";
        return 1;
    }
    return 0;
}
