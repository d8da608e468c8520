// ray-benchmark: ray throughput of the registry's accelerators on one mesh, side by side with
// Embree 3 when it is installed. See chapters/06-kd-tree/benchmark/README.md.
#include "benchmark_mesh.hpp"
#include "benchmark_report.hpp"
#include "binary_file.hpp"
#include "built_accelerator.hpp"
#include "embree_yardstick.hpp"
#include "hit_file.hpp"
#include "ray_batch.hpp"
#include "ray_batch_generator.hpp"
#include "ray_order.hpp"
#include "throughput.hpp"

#include "freezeray/chapter_options_cli.hpp"
#include "freezeray/error.hpp"
#include "freezeray/options.hpp"

#include "freezeray/complete_renderer.hpp"

#include <CLI/CLI.hpp>

#include <array>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace freezeray::benchmark {
namespace {

struct Options {
    std::string mesh;
    std::string rays;
    std::vector<std::string> accelerators;  // empty: every registered accelerator
    std::vector<int> threads{1};
    int repetitions = 5;
    std::string hits_out;
    bool json = false;
    std::string write_rays;
    std::string camera;      // "ex,ey,ez,lx,ly,lz,fov"
    std::string resolution;  // "W" or "WxH"
    std::uint64_t seed = 1;
    std::size_t limit = std::numeric_limits<std::size_t>::max();
    std::string order = "file";  // or "coherent"
    OptionValues accelerator_options;  // the chapters' accelerator settings (--kdtree-...)
};

// Parses "ex,ey,ez,lx,ly,lz,fov" into the camera (up stays +y).
void parse_camera(const std::string& text, CameraDescription& camera) {
    float v[7];
    char extra = 0;
    if (std::sscanf(text.c_str(), "%f,%f,%f,%f,%f,%f,%f%c", &v[0], &v[1], &v[2], &v[3], &v[4], &v[5], &v[6], &extra) != 7)
        throw InputError("--camera", "'" + text + "' is not seven numbers ex,ey,ez,lx,ly,lz,fov");
    for (float x : v)
        if (!std::isfinite(x)) throw InputError("--camera", "'" + text + "' has a value that is not finite");
    camera.position = Vec3(v[0], v[1], v[2]);
    camera.look_at = Vec3(v[3], v[4], v[5]);
    camera.fov_vertical_degrees = v[6];
    if (!(camera.fov_vertical_degrees > 0.0f && camera.fov_vertical_degrees < 180.0f))
        throw InputError("--camera", "the field of view " + std::to_string(v[6]) + " is not between 0 and 180 degrees");
    const Vec3 forward = camera.look_at - camera.position;
    if (glm::length(glm::cross(forward, camera.up)) <= 1e-6f * glm::length(forward))
        throw InputError("--camera", "the eye and look-at points coincide, or the view is along the up axis (+y)");
}

// Parses "W" (a square image) or "WxH".
void parse_resolution(const std::string& text, CameraDescription& camera) {
    int width = 0, height = 0;
    char separator = 0, extra = 0;
    const int read = std::sscanf(text.c_str(), "%d%c%d%c", &width, &separator, &height, &extra);
    if (read == 1) height = width;
    if (!((read == 1) || (read == 3 && separator == 'x')) || width <= 0 || height <= 0 || width > 16384 ||
        height > 16384)
        throw InputError("--resolution", "'" + text + "' is not W or WxH with sizes from 1 to 16384");
    camera.width = width;
    camera.height = height;
}

// Messages for people go to standard output with the table, or to standard error when standard
// output carries JSON lines.
std::ostream& notes(const Options& options) { return options.json ? std::cerr : std::cout; }

// The name by which --accel asks for Embree; never a registry name.
const std::string EmbreeName = "embree";

// Builds the accelerator called `name`: Embree, or one of the registry's.
BuiltAccelerator build_named(const std::string& name, const Registry& registry, const Parameters& settings,
                             const std::vector<TriangleMesh>& meshes) {
    if (name == EmbreeName) return *build_embree(meshes);
    return build_registry_accelerator(registry, name, settings, meshes);
}

RayBatches make_batches(const Options& options, const Registry& registry, const Parameters& accelerator_settings,
                        const std::vector<TriangleMesh>& meshes, const std::string& generating_accelerator) {
    if (!options.rays.empty()) {
        RayBatches batches = read_ray_batches(options.rays);
        batches.keep_first(options.limit);
        notes(options) << "rays: " << options.rays << "\n";
        return batches;
    }
    RayGenerationSettings settings;
    if (!options.camera.empty()) parse_camera(options.camera, settings.camera);
    if (!options.resolution.empty()) parse_resolution(options.resolution, settings.camera);
    settings.seed = options.seed;
    settings.limit = options.limit;
    const BuiltAccelerator built = build_named(generating_accelerator, registry, accelerator_settings, meshes);
    RayBatches batches = generate_ray_batches(*built.accelerator, meshes.front().bounds(), settings);
    if (batches.of(RayKind::Diffuse).empty())
        throw InputError("--camera", "none of the primary rays hits the mesh; give a --camera that sees it");
    const CameraDescription& c = settings.camera;
    notes(options) << "rays: generated with " << generating_accelerator << ", seed " << settings.seed
                   << ", camera eye (" << c.position.x << ", " << c.position.y << ", " << c.position.z
                   << ") look-at (" << c.look_at.x << ", " << c.look_at.y << ", " << c.look_at.z << ") fov "
                   << c.fov_vertical_degrees << ", " << c.width << "x" << c.height << "\n";
    return batches;
}

// Measures one accelerator on every kind and thread count, printing each row as it is done.
// Returns the answers of the first thread count, by kind. `reference`: Embree's, when known.
std::map<RayKind, RayAnswers> measure_accelerator(const BuiltAccelerator& built, const RayBatches& batches,
                                                  const Options& options,
                                                  const std::map<RayKind, RayAnswers>* reference) {
    std::map<RayKind, RayAnswers> first_answers;
    for (RayKind kind : all_ray_kinds) {
        const std::vector<Ray>& rays = batches.of(kind);
        if (rays.empty()) continue;
        for (int threads : options.threads) {
            ThroughputMeasurement measurement =
                measure_throughput(*built.accelerator, rays, kind, threads, options.repetitions);
            MeasurementRow row;
            row.accel = built.name;
            row.kind = kind;
            row.threads = threads;
            row.rays = rays.size();
            row.mrays_per_second = measurement.mrays_per_second(rays.size());
            row.median_milliseconds = 1e3 * measurement.median_seconds;
            row.repetitions = options.repetitions;
            row.build_milliseconds = built.build_milliseconds;
            if (built.memory_bytes) row.memory_megabytes = *built.memory_bytes / (1024.0 * 1024.0);
            if (reference != nullptr) {
                const Disagreements disagreements = compare_answers(measurement.answers, reference->at(kind));
                row.differ_from_embree = disagreements.differ;
                if (asks_for_closest_hit(kind)) row.ties = disagreements.ties;
            }
            if (options.json)
                std::cout << json_line(row) << std::endl;
            else
                print_table_row(std::cout, row);
            if (!first_answers.contains(kind)) first_answers[kind] = std::move(measurement.answers);
        }
    }
    return first_answers;
}

// The hits of the closest-hit batches, for --hits-out.
HitFile hit_file_of(std::map<RayKind, RayAnswers>& answers, const TriangleMesh& mesh) {
    HitFile hits;
    hits.triangle_count = static_cast<std::uint32_t>(mesh.triangle_count());
    hits.primary = std::move(answers[RayKind::Primary].closest);
    hits.diffuse = std::move(answers[RayKind::Diffuse].closest);
    return hits;
}

int run(const Options& options, const Registry& registry) {
    for (int threads : options.threads)
        if (threads < 1) throw InputError("--threads", "thread counts must be at least 1, found " + std::to_string(threads));
    if (options.repetitions < 1) throw InputError("--reps", "at least one timed run is needed");
    if (options.limit < 1) throw InputError("--limit", "at least one ray of each kind is needed");
    if (!options.hits_out.empty()) check_output_path(options.hits_out);
    if (!options.write_rays.empty()) check_output_path(options.write_rays);

    std::vector<std::string> accelerators = options.accelerators;
    if (accelerators.empty())
        for (const Registry::Entry& entry : registry.list(CapabilityKind::Accelerator)) accelerators.push_back(entry.name);
    // Unknown names and settings out of range are refused now, before minutes of loading and tracing.
    // A setting that none of the measured accelerators reads would be silently dropped.
    check_options_apply(options.accelerator_options, registry.options(), OptionTarget::Accelerator, accelerators,
                        "the accelerators measured, --accel");
    const OptionParameters settings(nullptr, "", "", ".", options.accelerator_options, registry.options(),
                                    OptionTarget::Accelerator);
    for (const std::string& name : accelerators) {
        if (name != EmbreeName)
            registry.accelerators.make(name, "--accel", settings.parameters());
        else if (!embree_is_available())
            throw InputError("--accel", "'embree': this ray-benchmark was built without Embree 3 (libembree-dev)");
    }

    const std::vector<TriangleMesh> meshes{load_benchmark_mesh(options.mesh)};
    notes(options) << "mesh: " << options.mesh << ", " << meshes.front().triangle_count() << " triangles, "
                   << meshes.front().positions.size() << " vertices\n";

    RayBatches batches = make_batches(options, registry, settings.parameters(), meshes, accelerators.front());
    if (options.order == "coherent") {
        sort_for_coherence(batches, meshes.front().bounds());
        notes(options) << "order: coherent (each kind sorted by direction octant, then the origin's Morton code)\n";
    }
    notes(options) << "batches: " << batches.of(RayKind::Primary).size() << " primary, "
                   << batches.of(RayKind::Diffuse).size() << " diffuse, " << batches.of(RayKind::Shadow).size()
                   << " shadow rays"
                   << (options.limit < std::numeric_limits<std::size_t>::max()
                           ? " (at most " + std::to_string(options.limit) + " of each kind, --limit)"
                           : std::string())
                   << "\n";
    if (!options.write_rays.empty()) {
        write_ray_batches(options.write_rays, batches);
        notes(options) << "wrote " << options.write_rays << "\n";
    }

    notes(options) << "times: median of " << options.repetitions << " timed run" << (options.repetitions > 1 ? "s" : "")
                   << " after one warm-up run\n";
    if (embree_is_available())
        notes(options) << "yardstick: " << embree_description()
                       << " (one build thread, RTC_BUILD_QUALITY_HIGH, rtcIntersect1/rtcOccluded1)\n";
    else
        notes(options) << embree_description() << ": no yardstick, differ and ties unknown\n";
    if (!options.json) print_table_header(std::cout);

    // Embree first: its answers are the reference the others are compared with.
    std::map<std::string, std::map<RayKind, RayAnswers>> answers;
    const std::map<RayKind, RayAnswers>* reference = nullptr;
    if (std::optional<BuiltAccelerator> embree = build_embree(meshes)) {
        answers[EmbreeName] = measure_accelerator(*embree, batches, options, nullptr);
        reference = &answers[EmbreeName];
    }
    std::set<std::string> done{EmbreeName};
    for (const std::string& name : accelerators) {
        if (!done.insert(name).second) continue;  // Embree, or a name given twice
        const BuiltAccelerator built = build_registry_accelerator(registry, name, settings.parameters(), meshes);
        std::map<RayKind, RayAnswers> measured = measure_accelerator(built, batches, options, reference);
        // Only the first accelerator's answers are kept (for --hits-out); the others' are done with.
        if (name == accelerators.front()) answers[name] = std::move(measured);
    }
    if (!options.hits_out.empty()) {
        write_hit_file(options.hits_out, hit_file_of(answers[accelerators.front()], meshes.front()));
        notes(options) << "wrote " << options.hits_out << " (the hits of " << accelerators.front() << ")\n";
    }
    return 0;
}

}  // namespace
}  // namespace freezeray::benchmark

int main(int argc, char** argv) {
    using namespace freezeray;
    using namespace freezeray::benchmark;
    const Registry registry = make_complete_registry("ray-benchmark");  // every chapter's accelerators

    std::string accelerator_names;
    for (const Registry::Entry& entry : registry.list(CapabilityKind::Accelerator))
        accelerator_names += (accelerator_names.empty() ? "" : ", ") + entry.name;

    Options options;
    CLI::App app{"ray-benchmark: ray throughput of the accelerators (and Embree, when installed) on one OBJ mesh"};
    app.add_option("mesh", options.mesh, "the OBJ file (triangles numbered in tinyobjloader's order)")->required();
    auto* rays = app.add_option("--rays", options.rays, "an FRRAYS01 ray file (default: rays made from --camera)");
    app.add_option("--accel", options.accelerators,
                   "accelerators, comma-separated: " + accelerator_names +
                       ", or embree (default: all but embree; Embree is measured whenever it is installed)")
        ->delimiter(',');
    app.add_option("--threads", options.threads, "thread counts, comma-separated (default: 1)")->delimiter(',');
    app.add_option("--reps", options.repetitions, "timed runs per measurement, after one warm-up run (default: 5)");
    app.add_option("--hits-out", options.hits_out, "write the first accelerator's closest hits here (FRHITS01)");
    app.add_flag("--json", options.json, "one JSON object per line and measurement instead of the table");
    app.add_option("--write-rays", options.write_rays, "write the measured batches here (FRRAYS01)");
    app.add_option("--camera", options.camera,
                   "ex,ey,ez,lx,ly,lz,fov: eye, look-at, vertical fov in degrees, up +y "
                   "(default: 1150,180,-40,0,300,-40,75, the shared Sponza batches' camera)")
        ->excludes(rays);
    app.add_option("--resolution", options.resolution, "W or WxH pixels for the primary rays (default: 512)")
        ->excludes(rays);
    app.add_option("--seed", options.seed, "random seed of the diffuse and shadow rays (default: 1)")->excludes(rays);
    app.add_option("--limit", options.limit, "trace only the first N rays of each kind");
    app.add_option("--order", options.order,
                   "file (as read or made) or coherent (each kind sorted by direction octant, then the Morton code of the "
                   "origin: how much of the time is spent waiting for memory; default: file)")
        ->check(CLI::IsMember({"file", "coherent"}));
    ChapterOptions accelerator_settings;  // each accelerator's own settings, as the renderer offers them
    accelerator_settings.declare(app, registry.options(), OptionTarget::Accelerator);

    try {
        app.parse(argc, argv);
        options.accelerator_options = accelerator_settings.values();
    } catch (const CLI::ParseError& error) {
        const int status = app.exit(error);
        return status == 0 ? 0 : 1;  // --help is a success; every mistake is exit status 1
    }
    try {
        return run(options, registry);
    } catch (const InputError& error) {
        std::cerr << "error: " << error.what() << "\n";
    } catch (const std::bad_alloc&) {
        std::cerr << "error: out of memory\n";
    } catch (const std::exception& error) {
        std::cerr << "error: " << error.what() << "\n";
    }
    return 1;
}
