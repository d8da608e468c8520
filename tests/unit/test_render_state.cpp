// Render states: exact round trips, refusal of foreign or truncated files, exact merging, and
// resuming an interrupted render in-process.
#include "freezeray/error.hpp"
#include "freezeray/scene_loader.hpp"
#include "freezeray/progress.hpp"
#include "freezeray/random.hpp"
#include "freezeray/render_state.hpp"

#include "test_scenes.hpp"

#include <catch2/catch.hpp>

#include <cstring>
#include <fstream>
#include <thread>

using namespace freezeray;
using freezeray::testing::TemporaryFolder;

namespace {

Film random_film(int width, int height, int samples, std::uint64_t seed) {
    Film film(width, height);
    PCG32 random(seed, 1);
    for (int s = 0; s < samples; ++s)
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < width; ++x) film.add_sample(x, y, Spectrum(random.next_float(), 2 * random.next_float(), 0.5f));
    return film;
}

bool same_images(const Image& a, const Image& b) {
    return a.pixel_count() == b.pixel_count() &&
           std::memcmp(a.pixels().data(), b.pixels().data(), a.pixel_count() * sizeof(Spectrum)) == 0;
}

}  // namespace

TEST_CASE("a render state round-trips exactly and refuses foreign or truncated files", "[unit][state]") {
    TemporaryFolder folder;
    const Film film = random_film(5, 3, 7, 1);
    const RenderStateInfo info{"scene.json", "pt-mis", "independent", 42, 16, 10, 5, 3, "bvh", 12.5};
    write_render_state(folder.file("a.state"), info, film);
    const RenderState read = read_render_state(folder.file("a.state"));
    CHECK(read.info.seed == 42u);
    CHECK(read.info.seconds == 12.5);  // the time spent so far: a resumed render's image records the total
    CHECK(read.info.first_sample == 16u);
    CHECK(read.info.light_sampler == "bvh");
    CHECK(same_images(read.film->mean(), film.mean()));
    CHECK(same_images(read.film->variance_of_mean(), film.variance_of_mean()));
    CHECK(read.film->minimum_sample_count() == 7u);

    std::ofstream(folder.file("foreign.state")) << "hello\n";
    CHECK_THROWS_AS(read_render_state(folder.file("foreign.state")), InputError);
    std::ifstream in(folder.file("a.state"), std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::ofstream(folder.file("cut.state"), std::ios::binary) << bytes.substr(0, bytes.size() - 10);
    CHECK_THROWS_WITH(read_render_state(folder.file("cut.state")), Catch::Contains("truncated"));

    RenderStateInfo other = info;
    other.seed = 43;
    CHECK_THROWS_WITH(check_resumable(info, other), Catch::Contains("seed"));
    CHECK_NOTHROW(check_resumable(info, info));
}

TEST_CASE("merging two films equals one film of all their samples", "[unit][state]") {
    // The same samples added to one film in order, or to two films then merged.
    Film whole(4, 4), first(4, 4), second(4, 4);
    PCG32 random(9, 9);
    for (int s = 0; s < 40; ++s)
        for (int y = 0; y < 4; ++y)
            for (int x = 0; x < 4; ++x) {
                const Spectrum v(random.next_float() * 10.0f, random.next_float(), 0.0f);
                whole.add_sample(x, y, v);
                (s < 15 ? first : second).add_sample(x, y, v);
            }
    const Film merged = merge_films(first, second);
    CHECK(merged.minimum_sample_count() == 40u);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x)
            for (int c = 0; c < 2; ++c) {
                CHECK(merged.mean().at(x, y)[c] == Approx(whole.mean().at(x, y)[c]).epsilon(1e-6));
                CHECK(merged.variance_of_mean().at(x, y)[c] == Approx(whole.variance_of_mean().at(x, y)[c]).epsilon(1e-5));
            }
    CHECK_THROWS_AS(merge_films(first, Film(3, 4)), InputError);
}

TEST_CASE("the samples a film gained since an earlier copy form the film of those samples alone", "[unit][state]") {
    // Per pixel 5 samples, then 27 more: samples_added(total, earlier) must equal a film of the
    // 27 alone (the inverse of merge_films), including a pixel whose added samples are all equal.
    PCG32 random(21, 4);
    Film total(4, 4), alone(4, 4);
    for (int s = 0; s < 32; ++s)
        for (int y = 0; y < 4; ++y)
            for (int x = 0; x < 4; ++x) {
                const bool constant = x == 0 && y == 0 && s >= 5;
                const Spectrum v = constant ? Spectrum(0.25f) : Spectrum(random.next_float() * 10.0f, random.next_float(), 0.0f);
                total.add_sample(x, y, v);
                if (s >= 5) alone.add_sample(x, y, v);
            }
    Film earlier(4, 4);  // the same first 5 samples
    PCG32 replay(21, 4);
    for (int s = 0; s < 5; ++s)
        for (int y = 0; y < 4; ++y)
            for (int x = 0; x < 4; ++x)
                earlier.add_sample(x, y, Spectrum(replay.next_float() * 10.0f, replay.next_float(), 0.0f));
    const Film added = samples_added(total, earlier);
    CHECK(added.minimum_sample_count() == 27u);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x)
            for (int c = 0; c < 3; ++c) {
                CHECK(added.mean().at(x, y)[c] == Approx(alone.mean().at(x, y)[c]).epsilon(1e-6).margin(1e-9));
                CHECK(added.variance_of_mean().at(x, y)[c] ==
                      Approx(alone.variance_of_mean().at(x, y)[c]).epsilon(1e-5).margin(1e-9));
            }
    CHECK(added.variance_of_mean().at(0, 0)[0] >= 0.0f);  // all 27 equal: zero, not a rounding below it
    CHECK_THROWS_AS(samples_added(total, Film(3, 4)), InputError);
    CHECK_THROWS_AS(samples_added(earlier, total), InputError);  // the earlier film has more samples
}

TEST_CASE("a render interrupted mid-pass and resumed equals the uninterrupted render bit for bit", "[unit][state]") {
    // The stop flag is raised from another thread at an arbitrary moment, so some pixels of the
    // interrupted pass have more samples than others; the resumed render goes on per pixel.
    SceneLoadOptions options;
    options.width = options.height = 24;
    const Scene scene = load_scene(testing::scene_path("cornell-box/scene.json"), testing::full_registry(), options);
    RenderSettings settings;
    settings.samples_per_pixel = 200;
    settings.seed = 8;
    const auto integrator = testing::full_registry().integrators.make("pt-naive", "test", settings, Parameters::none());
    Progress quiet(true);
    const RenderResult whole = integrator->render(scene, settings, quiet);

    for (int delay_ms : {5, 20, 60}) {
        std::atomic<bool> stop{false};
        RenderSettings interrupted_settings = settings;
        interrupted_settings.stop_requested = &stop;
        std::thread stopper([&] {
            std::this_thread::sleep_for(std::chrono::milliseconds(delay_ms));
            stop = true;
        });
        const RenderResult interrupted = integrator->render(scene, interrupted_settings, quiet);
        stopper.join();
        RenderSettings resumed_settings = settings;
        resumed_settings.resume = interrupted.film;
        const RenderResult resumed = integrator->render(scene, resumed_settings, quiet);
        INFO("stopped after " << delay_ms << " ms at " << interrupted.samples_per_pixel << " spp");
        CHECK(same_images(resumed.image, whole.image));
        CHECK(same_images(resumed.variance, whole.variance));
    }
}
