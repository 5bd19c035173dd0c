#include "embree_scene.h"

#include <chrono>
#include <stdexcept>
#include <string>

namespace glint::bench {

bool EmbreeScene::monitor(void* self, ssize_t bytes, bool /*post*/) {
    static_cast<EmbreeScene*>(self)->allocated_ += bytes;
    return true;
}

EmbreeScene::EmbreeScene(const MeshData& mesh, int threads, const std::string& extra_config) {
    const std::string config = "threads=" + std::to_string(threads) + (extra_config.empty() ? "" : "," + extra_config);
    device_ = rtcNewDevice(config.c_str());
    if (!device_) throw std::runtime_error("rtcNewDevice failed");
    rtcSetDeviceMemoryMonitorFunction(device_, &EmbreeScene::monitor, this);
    scene_ = rtcNewScene(device_);
    rtcSetSceneBuildQuality(scene_, RTC_BUILD_QUALITY_HIGH);
    RTCGeometry geometry = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
    rtcSetGeometryBuildQuality(geometry, RTC_BUILD_QUALITY_HIGH);
    // Embree reads vertices with 16-byte loads: MeshData's vector has room behind the last
    // vertex only by chance, so the caller's arrays are shared through padded copies.
    vertices_.resize(mesh.positions.size() + 1);
    std::copy(mesh.positions.begin(), mesh.positions.end(), vertices_.begin());
    rtcSetSharedGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, vertices_.data(), 0,
                               sizeof(Vec3), mesh.positions.size());
    rtcSetSharedGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, mesh.indices.data(), 0,
                               3 * sizeof(uint32_t), mesh.indices.size() / 3);
    rtcCommitGeometry(geometry);
    rtcAttachGeometry(scene_, geometry);
    rtcReleaseGeometry(geometry);
}

EmbreeScene::~EmbreeScene() {
    rtcReleaseScene(scene_);
    rtcReleaseDevice(device_);
}

double EmbreeScene::build() {
    const long long before = allocated_.load();
    const auto start = std::chrono::steady_clock::now();
    rtcCommitScene(scene_);
    const auto stop = std::chrono::steady_clock::now();
    retained_ = allocated_.load() - before;
    if (rtcGetDeviceError(device_) != RTC_ERROR_NONE) throw std::runtime_error("Embree build failed");
    return std::chrono::duration<double, std::milli>(stop - start).count();
}

PrimaryHit EmbreeScene::intersect(const BenchRay& ray) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRayHit rh;
    rh.ray.org_x = ray.org[0];
    rh.ray.org_y = ray.org[1];
    rh.ray.org_z = ray.org[2];
    rh.ray.tnear = ray.tnear;
    rh.ray.dir_x = ray.dir[0];
    rh.ray.dir_y = ray.dir[1];
    rh.ray.dir_z = ray.dir[2];
    rh.ray.time = 0.0f;
    rh.ray.tfar = ray.tfar;
    rh.ray.mask = 0xffffffffu;
    rh.ray.id = 0;
    rh.ray.flags = 0;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.primID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(scene_, &context, &rh);
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return {0.0f, UINT32_MAX};
    return {rh.ray.tfar, rh.hit.primID};
}

bool EmbreeScene::occluded(const BenchRay& ray) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRay r;
    r.org_x = ray.org[0];
    r.org_y = ray.org[1];
    r.org_z = ray.org[2];
    r.tnear = ray.tnear;
    r.dir_x = ray.dir[0];
    r.dir_y = ray.dir[1];
    r.dir_z = ray.dir[2];
    r.time = 0.0f;
    r.tfar = ray.tfar;
    r.mask = 0xffffffffu;
    r.id = 0;
    r.flags = 0;
    rtcOccluded1(scene_, &context, &r);
    return r.tfar < 0.0f;
}

namespace {

/// Embree's eight-lane ray layout filled from `count` rays; `valid` marks the lanes in use.
void fill_packet(const BenchRay* rays, int count, RTCRay8& r, int* valid) {
    for (int i = 0; i < 8; ++i) {
        const BenchRay& b = rays[i < count ? i : 0];
        valid[i] = i < count ? -1 : 0;
        r.org_x[i] = b.org[0];
        r.org_y[i] = b.org[1];
        r.org_z[i] = b.org[2];
        r.tnear[i] = b.tnear;
        r.dir_x[i] = b.dir[0];
        r.dir_y[i] = b.dir[1];
        r.dir_z[i] = b.dir[2];
        r.time[i] = 0.0f;
        r.tfar[i] = b.tfar;
        r.mask[i] = 0xffffffffu;
        r.id[i] = 0;
        r.flags[i] = 0;
    }
}

RTCIntersectContext coherent_context() {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
    return context;
}

}  // namespace

void EmbreeScene::intersect8(const BenchRay* rays, int count, PrimaryHit* out) const {
    RTCIntersectContext context = coherent_context();
    alignas(32) int valid[8];
    RTCRayHit8 rh;
    fill_packet(rays, count, rh.ray, valid);
    for (int i = 0; i < 8; ++i) {
        rh.hit.geomID[i] = RTC_INVALID_GEOMETRY_ID;
        rh.hit.primID[i] = RTC_INVALID_GEOMETRY_ID;
        rh.hit.instID[0][i] = RTC_INVALID_GEOMETRY_ID;
    }
    rtcIntersect8(valid, scene_, &context, &rh);
    for (int i = 0; i < count; ++i)
        out[i] = rh.hit.geomID[i] == RTC_INVALID_GEOMETRY_ID ? PrimaryHit{0.0f, UINT32_MAX}
                                                             : PrimaryHit{rh.ray.tfar[i], rh.hit.primID[i]};
}

void EmbreeScene::occluded8(const BenchRay* rays, int count, PrimaryHit* out) const {
    RTCIntersectContext context = coherent_context();
    alignas(32) int valid[8];
    RTCRay8 r;
    fill_packet(rays, count, r, valid);
    rtcOccluded8(valid, scene_, &context, &r);
    for (int i = 0; i < count; ++i) out[i] = r.tfar[i] < 0.0f ? PrimaryHit{0.0f, 0} : PrimaryHit{0.0f, UINT32_MAX};
}

}  // namespace glint::bench
