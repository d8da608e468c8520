// The splatting film: its normalisation, its half-buffer variance, invalid splats, and a splatting
// render's refusal to resume.
#include "freezeray/ch04/splat_film.hpp"

#include "freezeray/error.hpp"
#include "freezeray/integrator.hpp"
#include "freezeray/progress.hpp"
#include "freezeray/scene.hpp"
#include "freezeray/scene_loader.hpp"

#include "test_scenes.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace freezeray;
using namespace freezeray::ch04;

TEST_CASE("a splatted pixel is the sum of its splats divided by the light paths per pixel", "[unit][film][ch04]") {
    // 2x2 pixels, 8 light paths (2 per pixel): pixel (1, 0) receives 3 and 5 from paths 0 and 1
    // (one per half), pixel (0, 1) receives 4 twice from path 2 (even half).
    SplatFilm film(2, 2);
    SplatBuffer buffer(2, 2);
    for (std::uint64_t path = 0; path < 8; ++path) {
        buffer.begin_light_path(path);
        if (path == 0) buffer.add_splat(Vec2(1.5f, 0.2f), Spectrum(3.0f));
        if (path == 1) buffer.add_splat(Vec2(1.0f, 0.0f), Spectrum(5.0f));
        if (path == 2) {
            buffer.add_splat(Vec2(0.0f, 1.99f), Spectrum(4.0f));
            buffer.add_splat(Vec2(0.5f, 1.5f), Spectrum(4.0f, 0.0f, 2.0f));
            buffer.add_splat(Vec2(2.0f, 0.5f), Spectrum(100.0f));   // outside the film: ignored
            buffer.add_splat(Vec2(-0.1f, 0.5f), Spectrum(100.0f));  // outside the film: ignored
        }
    }
    film.add(buffer);
    CHECK(film.light_paths() == 8u);
    CHECK(film.light_paths_per_pixel() == 2.0);
    const Image mean = film.mean();
    CHECK(mean[1] == Spectrum(4.0f));                 // (3 + 5) / 2
    CHECK(mean[2] == Spectrum(4.0f, 2.0f, 3.0f));     // (4 + 4, 4 + 0, 4 + 2) / 2
    CHECK(mean[0] == Spectrum(0.0f));
    // Half-images (4 paths each, 4 pixels: scale 1): pixel 1 is 3 (even) and 5 (odd):
    // Var = (3 - 5)^2 * 4 * 4 / 8^2 = 1.
    const Image variance = film.variance_of_mean();
    CHECK(variance[1].r == Approx(1.0f));
    // Pixel 2 is all in the even half: (8 - 0)^2 / 4 = 16 in red.
    CHECK(variance[2].r == Approx(16.0f));
    CHECK(variance[0] == Spectrum(0.0f));

    const Film as_film = film.to_film(2);
    CHECK(as_film.mean()[1] == Spectrum(4.0f));
    CHECK(as_film.variance_of_mean()[1].r == Approx(1.0f));
    CHECK(as_film.minimum_sample_count() == 2u);
}

TEST_CASE("invalid splats are counted and enter as zero, and the error estimate needs both halves", "[unit][film][ch04]") {
    SplatFilm film(1, 1);
    SplatBuffer buffer(1, 1);
    buffer.begin_light_path(0);
    buffer.add_splat(Vec2(0.5f), Spectrum(std::nanf(""), 1.0f, 1.0f));
    buffer.add_splat(Vec2(0.5f), Spectrum(-1.0f));
    buffer.add_splat(Vec2(0.5f), Spectrum(2.0f));
    film.add(buffer);
    CHECK(film.invalid_splat_count() == 2u);
    CHECK(film.mean()[0] == Spectrum(2.0f));
    CHECK(film.estimated_relative_mse() < 0.0);  // one path: no odd half yet
    buffer.clear();
    buffer.begin_light_path(1);
    buffer.add_splat(Vec2(0.5f), Spectrum(4.0f));
    film.add(buffer);
    CHECK(film.mean()[0] == Spectrum(3.0f));
    // (2 - 4)^2 / 4 = 1, relMSE 1 / (9 + 0.01).
    CHECK(film.estimated_relative_mse() == Approx(1.0 / 9.01));
}

TEST_CASE("a splatting render refuses to resume instead of producing a wrong image", "[unit][film][ch04]") {
    SceneLoadOptions options;
    options.width = options.height = 8;
    const Scene scene = load_scene(testing::scene_path("cornell-box/scene.json"), testing::full_registry(), options);
    RenderSettings settings;
    settings.samples_per_pixel = 2;
    settings.threads = 1;
    const auto integrator = testing::full_registry().integrators.make("light-tracing", "test", settings, Parameters::none());
    CHECK_FALSE(testing::full_registry().integrator_traits("light-tracing", "test").resumable);
    Progress quiet(true);
    const RenderResult first = integrator->render(scene, settings, quiet);
    CHECK(first.samples_per_pixel == 2u);
    settings.resume = first.film;
    CHECK_THROWS_AS(integrator->render(scene, settings, quiet), InputError);
}
