#include "embree_scene.h"

#include <chrono>
#include <stdexcept>
#include <string>

namespace glint::bench {

bool EmbreeScene::monitor(void* self, ssize_t bytes, bool /*post*/) {
    static_cast<EmbreeScene*>(self)->allocated_ += bytes;
    return true;
}

EmbreeScene::EmbreeScene(const MeshData& mesh, int threads) {
    const std::string config = "threads=" + std::to_string(threads);
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

}  // namespace glint::bench
