// The Embree 3 yardstick: an Accelerator over Embree's BVH.
// API: the Embree 3 reference (rtcore_device.h, rtcore_scene.h, rtcore_geometry.h, rtcore_ray.h).
#include "embree_yardstick.hpp"

#include "freezeray/triangle_intersection.hpp"

#include <embree3/rtcore.h>

#include <atomic>
#include <cstring>
#include <limits>
#include <mutex>
#include <stdexcept>
#include <string>

namespace freezeray::benchmark {

namespace {

// The bytes Embree holds, counted by its memory monitor (called before each allocation with a
// positive count and after each release with a negative one).
std::atomic<long long> embree_bytes{0};

bool count_embree_memory(void* /*user*/, ssize_t bytes, bool /*post*/) {
    embree_bytes += static_cast<long long>(bytes);
    return true;  // never refuse an allocation
}

// Embree calls this on an API misuse or an allocation failure. An exception must not cross
// Embree's C interface, so the message is kept and thrown once Embree has returned.
std::mutex embree_error_mutex;
std::string embree_error_message;

void keep_embree_error(void* /*user*/, RTCError code, const char* message) {
    const std::lock_guard<std::mutex> lock(embree_error_mutex);
    if (embree_error_message.empty())
        embree_error_message = "Embree error " + std::to_string(static_cast<int>(code)) + ": " +
                               (message != nullptr ? message : "(no message)");
}

void throw_if_embree_failed(RTCDevice device) {
    if (rtcGetDeviceError(device) == RTC_ERROR_NONE) return;
    const std::lock_guard<std::mutex> lock(embree_error_mutex);
    throw std::runtime_error(embree_error_message.empty() ? "Embree reported an error" : embree_error_message);
}

// Our rays span (0, tmax); Embree's [tnear, tfar].
RTCRay embree_ray(const Ray& ray) {
    RTCRay query;
    query.org_x = ray.origin.x;
    query.org_y = ray.origin.y;
    query.org_z = ray.origin.z;
    query.tnear = 0.0f;
    query.dir_x = ray.direction.x;
    query.dir_y = ray.direction.y;
    query.dir_z = ray.direction.z;
    query.time = 0.0f;
    query.tfar = ray.tmax;
    query.mask = 0xFFFFFFFFu;
    query.id = 0;
    query.flags = 0;
    return query;
}

class EmbreeAccelerator final : public Accelerator {
public:
    EmbreeAccelerator() {
        // One build thread (see build_embree); tracing threads are the benchmark's own, and
        // rtcIntersect1 may be called from any thread.
        device_ = rtcNewDevice("threads=1");
        if (device_ == nullptr)
            throw std::runtime_error("Embree cannot start (error " +
                                     std::to_string(static_cast<int>(rtcGetDeviceError(nullptr))) + ")");
        rtcSetDeviceErrorFunction(device_, keep_embree_error, nullptr);
        rtcSetDeviceMemoryMonitorFunction(device_, count_embree_memory, nullptr);
        // Embree starts its task system at the first commit; committing an empty scene here keeps
        // that one-time cost (tens of milliseconds) out of the timed build.
        RTCScene warm_up = rtcNewScene(device_);
        rtcCommitScene(warm_up);
        rtcReleaseScene(warm_up);
        throw_if_embree_failed(device_);
    }
    ~EmbreeAccelerator() override {
        if (scene_ != nullptr) rtcReleaseScene(scene_);
        rtcReleaseDevice(device_);
    }
    EmbreeAccelerator(const EmbreeAccelerator&) = delete;
    EmbreeAccelerator& operator=(const EmbreeAccelerator&) = delete;

    void build(const std::vector<TriangleMesh>& meshes) override {
        meshes_ = &meshes;
        if (scene_ != nullptr) rtcReleaseScene(scene_);
        scene_ = rtcNewScene(device_);
        rtcSetSceneBuildQuality(scene_, RTC_BUILD_QUALITY_HIGH);
        for (const TriangleMesh& mesh : meshes) {
            RTCGeometry geometry = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
            rtcSetGeometryBuildQuality(geometry, RTC_BUILD_QUALITY_HIGH);
            // The same vertices and triangles, copied into buffers Embree allocates: it wants a
            // vertex buffer padded so that its last vertex can be read with one 16-byte load,
            // which a std::vector<Vec3> does not promise.
            static_assert(sizeof(Vec3) == 3 * sizeof(float));
            static_assert(sizeof(mesh.triangles[0]) == 3 * sizeof(std::uint32_t));
            void* vertices = rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                     sizeof(Vec3), mesh.positions.size());
            void* indices = rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                    sizeof(mesh.triangles[0]), mesh.triangles.size());
            throw_if_embree_failed(device_);
            std::memcpy(vertices, mesh.positions.data(), mesh.positions.size() * sizeof(Vec3));
            std::memcpy(indices, mesh.triangles.data(), mesh.triangles.size() * sizeof(mesh.triangles[0]));
            rtcCommitGeometry(geometry);
            rtcAttachGeometry(scene_, geometry);  // ids 0, 1, ... in the order of the meshes
            rtcReleaseGeometry(geometry);
        }
        rtcCommitScene(scene_);
        throw_if_embree_failed(device_);
    }

    std::optional<Hit> intersect(const Ray& ray) const override {
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        RTCRayHit query;
        query.ray = embree_ray(ray);
        query.hit.geomID = RTC_INVALID_GEOMETRY_ID;
        query.hit.primID = RTC_INVALID_GEOMETRY_ID;
        query.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
        rtcIntersect1(scene_, &context, &query);
        if (query.hit.geomID == RTC_INVALID_GEOMETRY_ID) return std::nullopt;
        // Embree's barycentrics: the hit is (1 - u - v) p0 + u p1 + v p2.
        const TriangleHit triangle_hit{query.ray.tfar, 1.0f - query.hit.u - query.hit.v, query.hit.u, query.hit.v};
        return make_hit(*meshes_, query.hit.geomID, query.hit.primID, triangle_hit);
    }

    bool occluded(const Ray& ray) const override {
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        RTCRay query = embree_ray(ray);
        rtcOccluded1(scene_, &context, &query);
        return query.tfar == -std::numeric_limits<float>::infinity();  // Embree's mark for "occluded"
    }

private:
    RTCDevice device_ = nullptr;
    RTCScene scene_ = nullptr;
    const std::vector<TriangleMesh>* meshes_ = nullptr;
};

}  // namespace

bool embree_is_available() { return true; }

std::string embree_description() { return std::string("Embree ") + RTC_VERSION_STRING; }

std::optional<BuiltAccelerator> build_embree(const std::vector<TriangleMesh>& meshes) {
    auto accelerator = std::make_unique<EmbreeAccelerator>();
    const long long bytes_before = embree_bytes.load();
    BuiltAccelerator built = build_timed("embree", std::move(accelerator), meshes);
    built.memory_bytes = static_cast<double>(embree_bytes.load() - bytes_before);
    return built;
}

}  // namespace freezeray::benchmark
