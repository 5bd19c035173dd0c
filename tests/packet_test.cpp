// Packet queries of the mesh BVH against the single-ray queries they stand for: every lane
// of every packet must find what its ray finds alone, for coherent packets (rows of camera
// rays) and incoherent ones (random rays, mixed directions in one packet), with finite
// tmax, partly filled packets, and rays through the edges of a closed mesh.

#include "glint/accel/ray_packet.h"
#include "glint/accel/triangle_bvh.h"
#include "glint/assets/mesh_loader.h"
#include "glint/geometry/quad.h"
#include "glint/geometry/sphere.h"
#include "glint/geometry/triangle_mesh.h"
#include "glint/scene/render_scene.h"
#include "glint/scene/scene.h"

#include "source_paths.h"
#include "test_rays.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <filesystem>
#include <memory>
#include <vector>

namespace glint {
namespace {

using glint_test::random_rays;

/// A pinhole camera's rays, row-major, looking at the box from `from` (rows of eight make
/// coherent packets).
std::vector<Ray> camera_rays(const Bounds3& box, const Vec3& from, int size) {
    const Vec3 eye = box.center() + from * length(box.diagonal());
    const Vec3 forward = normalize(box.center() - eye);
    const Vec3 right = normalize(cross(forward, std::abs(forward.y) > 0.9f ? Vec3(1, 0, 0) : Vec3(0, 1, 0)));
    const Vec3 up = cross(right, forward);
    std::vector<Ray> rays;
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            const float sx = (2.0f * (float(x) + 0.5f) / float(size) - 1.0f) * 0.5f;
            const float sy = (1.0f - 2.0f * (float(y) + 0.5f) / float(size)) * 0.5f;
            rays.emplace_back(eye, normalize(forward + right * sx + up * sy));
        }
    return rays;
}

/// Rays from the points where `camera` rays hit the mesh (lifted off it a little) toward
/// one point light, ending there: packets of them share a direction octant but start at
/// spread-out points, and their tmax is finite.
std::vector<Ray> shadow_rays(const TriangleBvh& bvh, const std::vector<Ray>& camera, const Vec3& light) {
    std::vector<Ray> rays;
    for (Ray ray : camera) {
        Hit hit;
        if (!bvh.intersect<false>(ray, hit)) continue;
        const Vec3 p = ray.at(hit.t * 0.9999f);
        rays.emplace_back(p, normalize(light - p), 0.0f, length(light - p));
    }
    return rays;
}

/// Traces `rays` in packets of eight (lanes in `lanes` only) and one by one; every active
/// lane agrees with its single ray on hit or miss, t and the triangle (another triangle
/// only at the same t, a ray through a shared edge), and on any hit; inactive lanes are
/// left as they were. Returns the number of closest hits.
int expect_packets_agree(const TriangleBvh& bvh, const std::vector<Ray>& rays, uint32_t lanes = RayPacket::kAllLanes) {
    int hits = 0;
    for (size_t first = 0; first + RayPacket::kSize <= rays.size(); first += RayPacket::kSize) {
        // Inactive lanes hold their rays too, so that a query leaking into them would hit.
        RayPacket packet;
        for (uint32_t lane = 0; lane < RayPacket::kSize; ++lane) packet.set(lane, rays[first + lane]);
        packet.active = lanes;
        RayPacket shadow = packet;
        PacketHits packet_hits;
        for (uint32_t lane = 0; lane < RayPacket::kSize; ++lane) packet_hits.primitive[lane] = kNoHit;
        const uint32_t hit_lanes = bvh.intersect_packet(packet, packet_hits);
        const uint32_t occluded_lanes = bvh.occluded_packet(shadow);
        for (uint32_t lane = 0; lane < RayPacket::kSize; ++lane) {
            const size_t i = first + lane;
            if (!(lanes >> lane & 1)) {
                EXPECT_EQ(packet.tmax[lane], rays[first + lane].tmax) << "inactive lane " << lane << ", ray " << first;
                EXPECT_EQ(packet_hits.primitive[lane], kNoHit) << "inactive lane " << lane;
                EXPECT_FALSE((hit_lanes | occluded_lanes) >> lane & 1) << "inactive lane " << lane;
                continue;
            }
            Ray ray = rays[i];
            Hit hit;
            const bool single = bvh.intersect<false>(ray, hit);
            Ray any = rays[i];
            Hit any_hit;
            EXPECT_EQ(bool(occluded_lanes >> lane & 1), bvh.intersect<true>(any, any_hit)) << "any hit, ray " << i;
            EXPECT_EQ(bool(hit_lanes >> lane & 1), single) << "ray " << i;
            if (!single || !(hit_lanes >> lane & 1)) continue;
            ++hits;
            EXPECT_EQ(packet_hits.t[lane], hit.t) << "ray " << i;
            EXPECT_EQ(packet.tmax[lane], hit.t) << "ray " << i;
            if (packet_hits.primitive[lane] != hit.primitive) {
                EXPECT_EQ(packet_hits.t[lane], hit.t) << "ray " << i << " hit another triangle at another t";
                continue;
            }
            EXPECT_EQ(packet_hits.u[lane], hit.u) << "ray " << i;
            EXPECT_EQ(packet_hits.v[lane], hit.v) << "ray " << i;
        }
    }
    return hits;
}

class PacketMesh : public testing::TestWithParam<std::string> {
protected:
    void SetUp() override {
        const std::filesystem::path path = GetParam();
        if (!std::filesystem::exists(path)) GTEST_SKIP() << path << " not found (shared data absent)";
        mesh_ = std::make_unique<TriangleMesh>(load_mesh_data(path), path.filename().string());
        mesh_->prepare();
    }
    std::unique_ptr<TriangleMesh> mesh_;
};

TEST_P(PacketMesh, CoherentPacketsAgreeWithSingleRays) {
    const Bounds3 box = mesh_->bounds();
    // Views along an axis, a diagonal and from below: the lanes' dominant axes differ
    // between views, and within the diagonal view's packets as well.
    int hits = 0, traced = 0;
    for (const Vec3 from : {Vec3(0, 0, 1), Vec3(0.6f, 0.5f, 0.62f), Vec3(-0.3f, -1.0f, 0.2f)}) {
        const std::vector<Ray> rays = camera_rays(box, from, 64);
        hits += expect_packets_agree(mesh_->bvh(), rays);
        traced += int(rays.size());
    }
    EXPECT_GT(hits, traced / 10) << "the views should mostly see the mesh";
}

TEST_P(PacketMesh, ShadowRayPacketsAgreeWithSingleRays) {
    const Bounds3 box = mesh_->bounds();
    const std::vector<Ray> camera = camera_rays(box, Vec3(0.3f, 0.4f, 1.0f), 64);
    const float size = length(box.diagonal());
    for (const Vec3 light : {box.center() + Vec3(1.0f, 1.5f, 0.5f) * size, box.center() + Vec3(-0.2f, 0.1f, 2.0f) * size}) {
        const std::vector<Ray> rays = shadow_rays(mesh_->bvh(), camera, light);
        ASSERT_GT(rays.size(), camera.size() / 20);
        // Closest hits too: some of these rays hit the mesh again on their way.
        EXPECT_GT(expect_packets_agree(mesh_->bvh(), rays), 0);
    }
}

TEST_P(PacketMesh, IncoherentPacketsAgreeWithSingleRays) {
    const std::vector<Ray> rays = random_rays(mesh_->bounds(), 4000, 11);
    EXPECT_GT(expect_packets_agree(mesh_->bvh(), rays), int(rays.size()) / 10);
}

TEST_P(PacketMesh, PartlyFilledPacketsLeaveTheOtherLanesAlone) {
    const std::vector<Ray> rays = camera_rays(mesh_->bounds(), Vec3(0.2f, 0.3f, 1.0f), 32);
    for (const uint32_t lanes : {0x01u, 0x80u, 0x5au, 0x7eu}) expect_packets_agree(mesh_->bvh(), rays, lanes);
}

INSTANTIATE_TEST_SUITE_P(InTree, PacketMesh, testing::Values((glint_test::kTestDataDir / "icosphere.ply").string()));
INSTANTIATE_TEST_SUITE_P(Stanford, PacketMesh,
                         testing::Values((glint_test::kSharedMeshDir / "stanford_bunny.ply").string(),
                                         (glint_test::kSharedMeshDir / "stanford_lucy_100k.ply").string()));

TEST(PacketWatertight, PacketsThroughEdgesAndVerticesOfAClosedMeshNeverEscape) {
    // The in-tree icosphere is closed; rays from inside through its vertices and points on
    // its edges, eight of them (in all directions) to a packet, must all hit.
    TriangleMesh mesh(load_mesh_data(glint_test::kTestDataDir / "icosphere.ply"));
    mesh.prepare();
    const std::vector<Vec3> targets = glint_test::vertices_and_edge_points(mesh.data());
    int escaped = 0, traced = 0;
    for (const Vec3 origin : {Vec3(0.0f), Vec3(0.1f, -0.2f, 0.05f)})
        for (size_t first = 0; first + RayPacket::kSize <= targets.size(); first += RayPacket::kSize) {
            RayPacket packet;
            for (uint32_t lane = 0; lane < RayPacket::kSize; ++lane)
                packet.set(lane, Ray(origin, targets[first + lane] - origin));
            RayPacket shadow = packet;
            PacketHits hits;
            escaped += std::popcount(~mesh.bvh().intersect_packet(packet, hits) & RayPacket::kAllLanes);
            escaped += std::popcount(~mesh.bvh().occluded_packet(shadow) & RayPacket::kAllLanes);
            traced += 2 * RayPacket::kSize;
        }
    EXPECT_EQ(escaped, 0) << "of " << traced << " lanes";
}

TEST(PacketDegenerate, AnEmptyBvhHitsNothing) {
    TriangleBvh triangles;
    triangles.build({}, {});
    RayPacket packet;
    for (uint32_t lane = 0; lane < RayPacket::kSize; ++lane) packet.set(lane, Ray(Vec3(0.0f), Vec3(0, 0, 1)));
    PacketHits hits;
    EXPECT_EQ(triangles.intersect_packet(packet, hits), 0u);
    EXPECT_EQ(triangles.occluded_packet(packet), 0u);
}

/// Every active lane of packets of `rays` (`lanes` of each) gets from the shape's packet
/// queries what its ray gets alone, to the bit; inactive lanes keep what they held. Returns
/// the hits.
int expect_shape_packets_agree(const Shape& shape, const std::vector<Ray>& rays, uint32_t lanes) {
    int hits = 0;
    for (size_t first = 0; first + RayPacket::kSize <= rays.size(); first += RayPacket::kSize) {
        RayPacket packet;
        for (uint32_t lane = 0; lane < RayPacket::kSize; ++lane) packet.set(lane, rays[first + lane]);
        packet.active = lanes;
        const uint32_t occluded_lanes = shape.occluded_packet(packet);
        PacketHits packet_hits;
        std::fill(std::begin(packet_hits.t), std::end(packet_hits.t), -1.0f);
        const uint32_t hit_lanes = shape.intersect_packet(packet, packet_hits);
        for (uint32_t lane = 0; lane < RayPacket::kSize; ++lane) {
            const size_t i = first + lane;
            if (!(lanes >> lane & 1)) {
                EXPECT_FALSE((hit_lanes | occluded_lanes) >> lane & 1) << "inactive lane " << lane;
                EXPECT_EQ(packet.tmax[lane], rays[i].tmax) << "inactive lane " << lane;
                EXPECT_EQ(packet_hits.t[lane], -1.0f) << "inactive lane " << lane;
                continue;
            }
            Ray ray = rays[i];
            Hit hit;
            const bool single = shape.intersect(ray, hit);
            EXPECT_EQ(bool(occluded_lanes >> lane & 1), shape.occluded(rays[i])) << "any hit, ray " << i;
            EXPECT_EQ(bool(hit_lanes >> lane & 1), single) << "ray " << i;
            if (bool(hit_lanes >> lane & 1) != single) continue;
            if (!single) {
                EXPECT_EQ(packet.tmax[lane], rays[i].tmax) << "ray " << i;
                continue;
            }
            ++hits;
            EXPECT_EQ(packet_hits.t[lane], hit.t) << "ray " << i;
            EXPECT_EQ(packet.tmax[lane], hit.t) << "ray " << i;
            EXPECT_EQ(packet_hits.primitive[lane], hit.primitive) << "ray " << i;
            EXPECT_EQ(packet_hits.u[lane], hit.u) << "ray " << i;
            EXPECT_EQ(packet_hits.v[lane], hit.v) << "ray " << i;
        }
    }
    return hits;
}

TEST(QuadPackets, EveryLaneGetsWhatItsRayGetsAlone) {
    // A floor and a tilted parallelogram; rays from a camera, from everywhere around, through
    // the floor's corners and edges and ending there or just before, segments above it, and
    // a packet of rays in each quad's own plane.
    struct Placed {
        Vec3 corner, edge_u, edge_v;
    };
    for (const Placed& q : {Placed{Vec3(-2.0f, 0.0f, 2.0f), Vec3(4.0f, 0.0f, 0.0f), Vec3(0.0f, 0.0f, -4.0f)},
                            Placed{Vec3(0.3f, -0.2f, 0.1f), Vec3(1.1f, 0.4f, -0.3f), Vec3(0.2f, 0.9f, 0.7f)}}) {
        const Quad quad(q.corner, q.edge_u, q.edge_v);
        const Bounds3 box = quad.bounds();
        std::vector<Ray> rays = camera_rays(box, Vec3(0.2f, 0.7f, 0.6f), 32);
        for (const Ray& r : random_rays(box, 2000, 3)) rays.push_back(r);
        for (const Vec3& p : {Vec3(-2, 0, 2), Vec3(2, 0, 2), Vec3(-2, 0, -2), Vec3(0, 0, 2), Vec3(2, 0, 0.5f)})
            for (const Vec3& d : {Vec3(0, -1, 0), Vec3(0.3f, -1, 0.2f), Vec3(0, 1, 0), Vec3(1, 0, 0), Vec3(0, 0, -1)}) {
                const Vec3 dir = normalize(d);
                rays.emplace_back(p - dir * 3.0f, dir);                    // through a corner or edge point
                rays.emplace_back(p - dir * 3.0f, dir, 0.0f, 3.0f);        // ending there
                rays.emplace_back(p - dir * 3.0f, dir, 0.0f, 2.9999f);     // ending just before
                rays.emplace_back(p + Vec3(0, 0.5f, 0), dir, 0.1f, 0.4f);  // a segment above
            }
        rays.resize(rays.size() / RayPacket::kSize * RayPacket::kSize);
        const Vec3 centre = q.corner + (q.edge_u + q.edge_v) * 0.5f;
        for (const Vec3& from : {centre, q.corner})
            for (const Vec3& along : {q.edge_u, -q.edge_u, q.edge_v, -q.edge_v})
                rays.emplace_back(from, normalize(along));  // in the plane: never a hit
        const int hits = expect_shape_packets_agree(quad, rays, RayPacket::kAllLanes);
        EXPECT_GT(hits, int(rays.size()) / 10);
        EXPECT_LT(hits, int(rays.size()) * 9 / 10);
        for (const uint32_t lanes : {0x01u, 0x80u, 0x5au}) expect_shape_packets_agree(quad, rays, lanes);
    }
}

TEST(SpherePackets, EveryShadowLaneGetsWhatItsRayGetsAlone) {
    // Rays from a camera and from everywhere around; shadow rays leaving the surface (from
    // just off it, as the integrators start them) toward points all around, some ending just
    // before the far side; rays grazing the sphere (tangent at distance r) and rays along a
    // tangent from a point on it (both roots at or within rounding of 0, q near 0), with
    // segments that hold t = 0 and segments that do not.
    const Sphere sphere(Vec3(0.4f, -0.3f, 1.2f), 0.8f);
    const Bounds3 box = sphere.bounds();
    std::vector<Ray> rays = camera_rays(box, Vec3(0.3f, 0.5f, 0.8f), 32);
    for (const Ray& r : random_rays(box, 2000, 5)) rays.push_back(r);
    const Vec3 c = sphere.center();
    const float r = sphere.radius();
    for (int i = 0; i < 200; ++i) {
        const float theta = 0.7f * float(i), phi = 0.31f * float(i);
        const Vec3 n(std::sin(phi) * std::cos(theta), std::cos(phi), std::sin(phi) * std::sin(theta));
        const Vec3 tangent = normalize(cross(n, std::abs(n.y) < 0.9f ? Vec3(0, 1, 0) : Vec3(1, 0, 0)));
        const Vec3 on_surface = c + n * r;
        const Vec3 target =
            c + Vec3(std::cos(0.9f * float(i)), std::sin(1.3f * float(i)), std::cos(2.1f * float(i))) * 3.0f;
        const Vec3 to_target = target - on_surface;
        rays.emplace_back(on_surface + n * 1e-4f, to_target, 1e-4f, 0.9999f);  // a shadow ray
        rays.emplace_back(on_surface, -n, 1e-4f, 2.0f * r * 0.9999f);          // to just before the far side
        rays.emplace_back(on_surface + n * 2.0f - tangent * 3.0f, tangent, 0.0f, kInfinity);  // outside, passing by
        rays.emplace_back(on_surface - tangent * 3.0f, tangent, 0.0f, kInfinity);             // grazing
        rays.emplace_back(on_surface, tangent, -1.0f, 1.0f);                // along a tangent, holding t = 0
        rays.emplace_back(on_surface, tangent, 0.0f, 1.0f);                 // the same, not holding it
        rays.emplace_back(c + n * (0.5f * r), to_target, 0.0f, kInfinity);  // from inside
    }
    rays.resize(rays.size() / RayPacket::kSize * RayPacket::kSize);
    const int hits = expect_shape_packets_agree(sphere, rays, RayPacket::kAllLanes);
    EXPECT_GT(hits, int(rays.size()) / 10);
    EXPECT_LT(hits, int(rays.size()) * 9 / 10);
    for (const uint32_t lanes : {0x01u, 0x80u, 0x5au}) expect_shape_packets_agree(sphere, rays, lanes);
    // q exactly 0: a unit sphere at the origin, rays from points exactly on it along exact
    // tangents (b = 0, discriminant 0), whose roots are both t = 0.
    const Sphere unit(Vec3(0.0f), 1.0f);
    std::vector<Ray> tangents;
    for (const auto& [p, d] : {std::pair{Vec3(1, 0, 0), Vec3(0, 1, 0)}, std::pair{Vec3(0, -1, 0), Vec3(0, 0, 1)},
                               std::pair{Vec3(0, 0, 1), Vec3(-1, 0, 0)}, std::pair{Vec3(-1, 0, 0), Vec3(0, 0, -2)}})
        for (const float tmin : {-1.0f, 0.0f}) tangents.emplace_back(p, d, tmin, 1.0f);
    EXPECT_EQ(expect_shape_packets_agree(unit, tangents, RayPacket::kAllLanes), 4) << "t = 0 lies in (-1, 1) only";
}

/// A scene of `copies` placements of the icosphere (turned, stretched, one mirrored; the
/// first of glass, which shadow rays pass under DielectricShadows::None), a sphere if
/// `sphere`, an icosphere of its own (carried into world space when prepared) and a floor
/// quad placed twice (as it is, and turned); with `moving`, one placement moves during the
/// shutter.
RenderScene placed_scene(int copies, bool moving, bool sphere = true) {
    auto mesh = std::make_shared<TriangleMesh>(load_mesh_data(glint_test::kTestDataDir / "icosphere.ply"));
    Scene scene;
    const uint32_t matte = scene.add_material(Material{});
    Material glass;
    glass.transparency = 1.0f;
    const uint32_t clear = scene.add_material(glass);
    for (int i = 0; i < copies; ++i) {
        const float x = 2.5f * float(i % 4) - 4.0f, y = 2.5f * float(i / 4) - 1.0f;
        Transform t = Transform::translate(Vec3(x, y, 0.0f)) * Transform::rotate(20.0f * float(i), Vec3(0, 1, 1));
        if (i % 3 == 1) t = t * Transform::scale(Vec3(0.7f, 1.3f, 1.0f));
        if (i % 3 == 2) t = t * Transform::scale(Vec3(-1.0f, 1.0f, 1.0f));
        const uint32_t object = scene.add_object(mesh, i == 0 ? clear : matte, t);
        if (moving && i == 1)
            scene.set_motion(object, AnimatedTransform({{0.0f, t}, {1.0f, Transform::translate(Vec3(0.4f, 0, 0)) * t}}));
    }
    if (sphere) scene.add_object(std::make_shared<Sphere>(Vec3(0.5f, 0.3f, -2.0f), 1.2f), matte);
    // A mesh of its own, which the render scene carries into world space
    // (Scene::place_meshes_in_world): packets reach its BVH without a transform.
    scene.add_object(std::make_shared<TriangleMesh>(load_mesh_data(glint_test::kTestDataDir / "icosphere.ply")), matte,
                     Transform::translate(Vec3(-1.5f, 0.5f, -1.0f)) * Transform::scale(Vec3(1.2f, 0.8f, 1.0f)));
    // A floor under them, once as it is and once turned and moved.
    const auto floor =
        std::make_shared<Quad>(Vec3(-6.0f, -2.5f, 3.0f), Vec3(12.0f, 0.0f, 0.0f), Vec3(0.0f, 0.0f, -6.0f));
    scene.add_object(floor, matte);
    scene.add_object(floor, matte,
                     Transform::translate(Vec3(0, -1.0f, -4.0f)) * Transform::rotate(70.0f, Vec3(1, 0, 0)));
    return RenderScene(std::move(scene));
}

/// Rays from a camera in front of the scene (rows of eight: coherent packets) and random
/// ones, each with a time in the shutter.
std::vector<Ray> scene_rays(const RenderScene& scene) {
    const Bounds3 box = scene.bounds();
    std::vector<Ray> rays = camera_rays(box, Vec3(0.1f, 0.2f, 1.0f), 48);
    for (const Ray& r : random_rays(box, 800, 5)) rays.push_back(r);
    for (size_t i = 0; i < rays.size(); ++i) rays[i].time = float(i % 7) / 6.0f;
    return rays;
}

/// Every lane of every packet of `rays` agrees with the scene's single-ray queries: hit or
/// miss, t, object, primitive (another one only at the same t) and any hit under both
/// dielectric-shadow modes. Returns the closest hits.
int expect_scene_packets_agree(const RenderScene& scene, const std::vector<Ray>& rays) {
    int hits = 0;
    for (size_t first = 0; first + RayPacket::kSize <= rays.size(); first += RayPacket::kSize) {
        RayPacket packet;
        for (uint32_t lane = 0; lane < RayPacket::kSize; ++lane) packet.set(lane, rays[first + lane]);
        const uint32_t blocked = scene.occluded_packet(packet, DielectricShadows::Opaque);
        const uint32_t blocked_but_glass = scene.occluded_packet(packet, DielectricShadows::None);
        PacketHits packet_hits;
        const uint32_t hit_lanes = scene.intersect_packet(packet, packet_hits);
        for (uint32_t lane = 0; lane < RayPacket::kSize; ++lane) {
            const size_t i = first + lane;
            EXPECT_EQ(bool(blocked >> lane & 1), scene.occluded(rays[i], DielectricShadows::Opaque)) << "ray " << i;
            EXPECT_EQ(bool(blocked_but_glass >> lane & 1), scene.occluded(rays[i], DielectricShadows::None))
                << "ray " << i;
            Ray ray = rays[i];
            Hit hit;
            const bool single = scene.intersect(ray, hit);
            EXPECT_EQ(bool(hit_lanes >> lane & 1), single) << "ray " << i;
            if (!single || !(hit_lanes >> lane & 1)) continue;
            ++hits;
            const Hit h = packet_hits.hit(lane);
            EXPECT_EQ(h.t, hit.t) << "ray " << i;
            EXPECT_EQ(packet.tmax[lane], hit.t) << "ray " << i;
            EXPECT_EQ(h.object, hit.object) << "ray " << i;  // the objects do not touch: no ties between them
            if (h.primitive != hit.primitive) continue;      // a tie at a shared edge, same t
            EXPECT_EQ(h.u, hit.u) << "ray " << i;
            EXPECT_EQ(h.v, hit.v) << "ray " << i;
        }
    }
    return hits;
}

TEST(ScenePackets, FewObjectsAgreeWithSingleRays) {
    // Four objects: no top level, a loop over their boxes (RenderScene::kFewObjects).
    const RenderScene scene = placed_scene(1, false, false);
    ASSERT_EQ(scene.description().objects().size(), 4u);
    const std::vector<Ray> rays = scene_rays(scene);
    EXPECT_GT(expect_scene_packets_agree(scene, rays), int(rays.size()) / 10);
}

TEST(ScenePackets, ManyObjectsThroughTheTopLevelAgreeWithSingleRays) {
    const RenderScene scene = placed_scene(12, false);
    const std::vector<Ray> rays = scene_rays(scene);
    EXPECT_GT(expect_scene_packets_agree(scene, rays), int(rays.size()) / 10);
}

TEST(ScenePackets, AMovingObjectIsWhereEachLanesTimePutsIt) {
    const RenderScene scene = placed_scene(12, true);
    ASSERT_TRUE(scene.has_motion());
    const std::vector<Ray> rays = scene_rays(scene);
    EXPECT_GT(expect_scene_packets_agree(scene, rays), int(rays.size()) / 10);
}

TEST(ScenePackets, AMovingObjectPlacedOnceForLanesThatShareATime) {
    // Shadow rays toward one light leave one point at one time: a moving object is placed
    // once for such a packet and takes its lanes together. A sphere and an icosphere travel
    // 3 units along x during the shutter; bundles of eight rays, each bundle at one time, aim
    // at where the pair is then (and where it was at the start, which it has left).
    Scene description;
    const uint32_t matte = description.add_material(Material{});
    const Transform sphere_start = Transform::translate(Vec3(0.0f, 0.0f, 0.0f));
    const Transform mesh_start = Transform::translate(Vec3(0.0f, 1.5f, 0.0f)) * Transform::scale(Vec3(0.6f));
    const Transform travel = Transform::translate(Vec3(3.0f, 0.0f, 0.0f));
    const uint32_t sphere = description.add_object(std::make_shared<Sphere>(Vec3(0.0f), 0.5f), matte, sphere_start);
    const uint32_t mesh = description.add_object(
        std::make_shared<TriangleMesh>(load_mesh_data(glint_test::kTestDataDir / "icosphere.ply")), matte, mesh_start);
    description.set_motion(sphere, AnimatedTransform({{0.0f, sphere_start}, {1.0f, travel * sphere_start}}));
    description.set_motion(mesh, AnimatedTransform({{0.0f, mesh_start}, {1.0f, travel * mesh_start}}));
    const RenderScene scene(std::move(description));
    std::vector<Ray> rays;
    for (int bundle = 0; bundle < 64; ++bundle) {
        const float time = float(bundle % 9) / 8.0f;
        const float x = bundle % 2 ? 3.0f * time : 0.0f;  // where the pair is, or where it was
        const Vec3 from(x + 0.3f * std::sin(float(bundle)), 0.7f, 6.0f);
        for (uint32_t lane = 0; lane < RayPacket::kSize; ++lane) {
            const Vec3 at(x + 0.12f * float(lane) - 0.42f, lane % 2 ? 1.5f : 0.1f * float(lane % 3), 0.0f);
            Ray ray(from, at - from, 0.0f, lane % 3 ? kInfinity : 0.99f);
            ray.time = time;
            rays.push_back(ray);
        }
    }
    EXPECT_GT(expect_scene_packets_agree(scene, rays), int(rays.size()) / 4);
}

TEST(ScenePackets, AnEmptySceneHitsNothing) {
    const RenderScene scene{Scene{}};
    RayPacket packet;
    for (uint32_t lane = 0; lane < RayPacket::kSize; ++lane) packet.set(lane, Ray(Vec3(0.0f), Vec3(0, 0, 1)));
    PacketHits hits;
    EXPECT_EQ(scene.intersect_packet(packet, hits), 0u);
    EXPECT_EQ(scene.occluded_packet(packet), 0u);
}

}  // namespace
}  // namespace glint
