// Differential and invariant tests of the acceleration structures: the 8-wide mesh BVH
// against brute force on mesh files (one in the tree, the shared Stanford meshes when
// present), watertightness on closed meshes,
// instancing through the scene's top level, degenerate inputs.

#include "glint/accel/brute_force.h"
#include "glint/accel/triangle_bvh.h"
#include "glint/accel/wide_bvh.h"
#include "glint/assets/mesh_loader.h"
#include "glint/geometry/triangle_mesh.h"
#include "glint/scene/render_scene.h"
#include "glint/scene/scene.h"

#include "source_paths.h"
#include "test_rays.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <limits>
#include <map>
#include <memory>
#include <numeric>
#include <random>

#include <tbb/task_arena.h>

namespace glint {
namespace {

/// Closest hit by testing every triangle with the same watertight routine.
bool brute_force_intersect(const TriangleMesh& mesh, Ray& ray, Hit& hit) {
    const BruteForce all(static_cast<uint32_t>(mesh.triangle_count()));
    return all.traverse<false>(ray, [&](uint32_t tri, Ray& r) { return mesh.intersect_triangle(tri, r, hit); });
}

using glint_test::random_rays;

/// BVH and brute force agree on hit/miss, t (1e-6 relative) and the triangle; a different
/// triangle is only allowed at the same t (a ray through an edge shared by both).
void expect_agreement(const TriangleMesh& mesh, const std::vector<Ray>& rays) {
    int hits = 0;
    for (size_t i = 0; i < rays.size(); ++i) {
        Ray bvh_ray = rays[i], reference_ray = rays[i];
        Hit bvh_hit, reference_hit;
        const bool bvh = mesh.intersect(bvh_ray, bvh_hit);
        const bool reference = brute_force_intersect(mesh, reference_ray, reference_hit);
        ASSERT_EQ(bvh, reference) << "ray " << i;
        EXPECT_EQ(mesh.occluded(rays[i]), reference) << "any hit, ray " << i;
        if (!bvh) continue;
        ++hits;
        EXPECT_NEAR(bvh_hit.t, reference_hit.t, 1e-6f * reference_hit.t) << "ray " << i;
        if (bvh_hit.primitive != reference_hit.primitive) {
            EXPECT_EQ(bvh_hit.t, reference_hit.t) << "ray " << i << " hit another triangle at another t";
        }
    }
    EXPECT_GT(hits, int(rays.size()) / 10) << "the rays should mostly hit the mesh";
}

/// A mesh file by its full path (a string: gtest prints it in the test's parameters).
class MeshFile : public testing::TestWithParam<std::string> {};

TEST_P(MeshFile, BvhAgreesWithBruteForce) {
    const std::filesystem::path path = GetParam();
    if (!std::filesystem::exists(path)) GTEST_SKIP() << path << " not found (shared data absent)";
    TriangleMesh mesh(load_mesh_data(path), path.filename().string());
    mesh.prepare();
    // Brute force costs rays × triangles: 2,000 rays keep the three meshes under a few seconds.
    expect_agreement(mesh, random_rays(mesh.bounds(), 2000, 7));
}

// In every clone: a 320-triangle icosphere, so the test never depends on shared data alone.
INSTANTIATE_TEST_SUITE_P(InTree, MeshFile, testing::Values((glint_test::kTestDataDir / "icosphere.ply").string()));
// The 871k-triangle dragon is left to glint-bench, whose checksums compare it with Embree.
INSTANTIATE_TEST_SUITE_P(Stanford, MeshFile,
                         testing::Values((glint_test::kSharedMeshDir / "stanford_bunny.ply").string(),
                                         (glint_test::kSharedMeshDir / "stanford_lucy_100k.ply").string(),
                                         (glint_test::kSharedMeshDir / "stanford_dragon_res2.ply").string()));

/// An icosahedron subdivided `levels` times and pushed onto the unit sphere: closed,
/// every edge shared by two triangles.
MeshData icosphere(int levels) {
    const float g = (1.0f + std::sqrt(5.0f)) / 2.0f;
    MeshData m;
    m.positions = {{-1, g, 0}, {1, g, 0}, {-1, -g, 0}, {1, -g, 0}, {0, -1, g}, {0, 1, g},
                   {0, -1, -g}, {0, 1, -g}, {g, 0, -1}, {g, 0, 1}, {-g, 0, -1}, {-g, 0, 1}};
    m.indices = {0, 11, 5, 0, 5, 1, 0, 1, 7, 0, 7, 10, 0, 10, 11, 1, 5, 9, 5, 11, 4, 11, 10, 2, 10, 7, 6, 7, 1, 8,
                 3, 9, 4, 3, 4, 2, 3, 2, 6, 3, 6, 8, 3, 8, 9, 4, 9, 5, 2, 4, 11, 6, 2, 10, 8, 6, 7, 9, 8, 1};
    for (Vec3& p : m.positions) p = normalize(p);
    for (int level = 0; level < levels; ++level) {
        std::map<std::pair<uint32_t, uint32_t>, uint32_t> midpoints;
        auto midpoint = [&](uint32_t a, uint32_t b) {
            const auto key = std::minmax(a, b);
            auto [it, inserted] = midpoints.try_emplace(key, uint32_t(m.positions.size()));
            if (inserted) m.positions.push_back(normalize(m.positions[a] + m.positions[b]));
            return it->second;
        };
        std::vector<uint32_t> next;
        for (size_t t = 0; t < m.indices.size(); t += 3) {
            const uint32_t a = m.indices[t], b = m.indices[t + 1], c = m.indices[t + 2];
            const uint32_t ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
            next.insert(next.end(), {a, ab, ca, b, bc, ab, c, ca, bc, ab, bc, ca});
        }
        m.indices = std::move(next);
    }
    return m;
}

// In every clone, a tree big enough for the collapse's parallel tasks (2^14 binary nodes or
// more), whose subtrees are written into ranges computed ahead: a wrong range would lose or
// overwrite nodes and leaves.
TEST(Build, ATreeCollapsedInParallelAgreesWithBruteForce) {
    TriangleMesh mesh(icosphere(6));  // 81,920 triangles
    mesh.prepare();
    expect_agreement(mesh, random_rays(mesh.bounds(), 300, 11));
}

TEST(Watertight, RaysThroughEdgesAndVerticesOfAClosedMeshNeverEscape) {
    TriangleMesh mesh(icosphere(3));
    mesh.prepare();
    const std::vector<Vec3> targets = glint_test::vertices_and_edge_points(mesh.data());
    // From inside (several origins) the closed surface must stop every ray, in both queries.
    int escaped = 0;
    for (const Vec3 origin : {Vec3(0.0f), Vec3(0.1f, -0.2f, 0.05f), Vec3(-0.31f, 0.17f, 0.4f)})
        for (const Vec3& target : targets) {
            const Ray ray(origin, target - origin);
            Ray r = ray;
            Hit hit;
            if (!mesh.intersect(r, hit) || !mesh.occluded(ray)) ++escaped;
        }
    EXPECT_EQ(escaped, 0) << "of " << 3 * targets.size() << " rays";
}

TEST(Watertight, RaysThroughTheSharedDiagonalOfASquareHit) {
    // Two triangles share the diagonal from (0,0) to (1,1); rays through points of the
    // diagonal (exactly representable), the open square's corners aside, must hit.
    MeshData m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    m.indices = {0, 1, 2, 0, 2, 3};
    TriangleMesh mesh(std::move(m));
    mesh.prepare();
    for (int i = 1; i < 1024; ++i) {
        const float x = float(i) / 1024.0f;
        for (const Vec3 dir : {Vec3(0, 0, -1), Vec3(0.3f, -0.2f, -1), Vec3(-0.01f, 0.02f, -1)}) {
            const Vec3 origin = Vec3(x, x, 0) - dir * 2.0f;
            Ray ray(origin, dir);
            Hit hit;
            EXPECT_TRUE(mesh.intersect(ray, hit)) << "x = " << x;
            EXPECT_TRUE(mesh.occluded(Ray(origin, dir))) << "x = " << x;
        }
    }
}

TEST(Instancing, TransformedInstancesShareOneBlasAndMatchBakedGeometry) {
    auto shape = std::make_shared<TriangleMesh>(icosphere(2));
    const Transform placements[] = {
        Transform::translate(Vec3(3, 0, 0)) * Transform::rotate(30.0f, Vec3(0, 1, 1)),
        Transform::translate(Vec3(-2, 1, 0.5f)) * Transform::scale(Vec3(0.5f, 2.0f, 1.0f)),
        Transform::scale(Vec3(-1.0f, 1.0f, 1.0f)),  // mirrored: swaps handedness
    };
    Scene scene;
    scene.add_material(Material{});
    MeshData baked;
    for (const Transform& t : placements) {
        scene.add_object(shape, 0, t);
        const auto base = static_cast<uint32_t>(baked.positions.size());
        for (const Vec3& p : shape->data().positions) baked.positions.push_back(t.point(p));
        for (uint32_t i : shape->data().indices) baked.indices.push_back(base + i);
    }
    const RenderScene prepared(std::move(scene));
    TriangleMesh reference(std::move(baked));
    const size_t per_instance = shape->triangle_count();
    for (const Ray& ray : random_rays(prepared.bounds(), 3000, 11)) {
        Ray world = ray, ref_ray = ray;
        Hit hit, ref_hit;
        const bool found = prepared.intersect(world, hit);
        const bool expected = brute_force_intersect(reference, ref_ray, ref_hit);
        ASSERT_EQ(found, expected);
        EXPECT_EQ(prepared.occluded(ray), expected);
        if (!found) continue;
        EXPECT_NEAR(hit.t, ref_hit.t, 1e-4f * ref_hit.t);
        EXPECT_EQ(hit.object, ref_hit.primitive / per_instance);
    }
}

TEST(Degenerate, ZeroAreaTrianglesAreNeverHitAndDoNotDisturbTheRest) {
    MeshData m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {2, 2, 0}, {3, 3, 0}, {4, 4, 0}, {5, 5, 0}};
    m.indices = {0, 1, 2,   // a proper triangle
                 3, 4, 5,   // collinear
                 6, 6, 6,   // a point
                 3, 3, 4};  // coincident corners
    TriangleMesh mesh(std::move(m));
    mesh.prepare();
    for (const Vec3 through : {Vec3(3, 3, 0), Vec3(3.5f, 3.5f, 0), Vec3(5, 5, 0), Vec3(4, 4, 0)}) {
        for (const Vec3 dir : {Vec3(0, 0, -1), Vec3(1, -1, 0), Vec3(1, 1, 0.001f)}) {
            Ray ray(through - dir * 3.0f, dir);
            Hit hit;
            EXPECT_FALSE(mesh.intersect(ray, hit)) << through << dir;
            EXPECT_FALSE(mesh.occluded(Ray(through - dir * 3.0f, dir)));
        }
    }
    Ray ray(Vec3(0.25f, 0.25f, 1.0f), Vec3(0, 0, -1));
    Hit hit;
    ASSERT_TRUE(mesh.intersect(ray, hit));
    EXPECT_EQ(hit.primitive, 0u);
    EXPECT_FLOAT_EQ(hit.t, 1.0f);
    expect_agreement(mesh, random_rays(Bounds3(Vec3(0, 0, -0.1f), Vec3(1, 1, 0.1f)), 500, 3));
}

TEST(Degenerate, EmptyInputsHitNothing) {
    Scene scene;
    const RenderScene prepared(std::move(scene));
    Ray ray(Vec3(0.0f), Vec3(0, 0, 1));
    Hit hit;
    EXPECT_FALSE(prepared.intersect(ray, hit));
    EXPECT_FALSE(prepared.occluded(ray));

    const std::vector<Bounds3> nothing_to_hit(3);  // empty boxes only
    WideBvh of_empty_boxes;
    of_empty_boxes.build(nothing_to_hit);
    EXPECT_FALSE(of_empty_boxes.traverse<false>(ray, [](uint32_t, Ray&) { return true; }));
    WideBvh wide;
    wide.build({});
    EXPECT_FALSE(wide.traverse<true>(ray, [](uint32_t, Ray&) { return true; }));
    TriangleBvh triangles;
    triangles.build({}, {});
    EXPECT_TRUE(triangles.empty());
    EXPECT_FALSE(triangles.intersect<false>(ray, hit));
}

TEST(Degenerate, OnePrimitive) {
    MeshData m;
    m.positions = {{-1, -1, 2}, {1, -1, 2}, {0, 1, 2}};
    m.indices = {0, 1, 2};
    TriangleMesh mesh(std::move(m));
    mesh.prepare();
    Ray ray(Vec3(0.0f), Vec3(0, 0, 1));
    Hit hit;
    ASSERT_TRUE(mesh.intersect(ray, hit));
    EXPECT_FLOAT_EQ(hit.t, 2.0f);
    EXPECT_FLOAT_EQ(ray.tmax, 2.0f);
    EXPECT_EQ(hit.primitive, 0u);
    EXPECT_FALSE(mesh.occluded(Ray(Vec3(0.0f), Vec3(0, 0, 1), 0.0f, 1.5f))) << "the triangle is beyond tmax";
    EXPECT_FALSE(mesh.occluded(Ray(Vec3(0.0f), Vec3(0, 0, -1)))) << "behind the origin";
    EXPECT_FALSE(mesh.occluded(Ray(Vec3(0.0f), Vec3(1, 0, 1)))) << "beside the triangle";
    WideBvh one_box;
    const Bounds3 box(Vec3(-1.0f), Vec3(1.0f));
    one_box.build(std::span(&box, 1));
    Ray probe(Vec3(0, 0, -5), Vec3(0, 0, 1));
    EXPECT_TRUE(one_box.traverse<true>(
        probe, [&](uint32_t leaf, Ray&) { return one_box.primitive_order()[one_box.leaves()[leaf].first] == 0; }));
}

/// An alpha texture that is transparent where u < 0.5.
class HalfTransparent final : public Texture {
public:
    Color evaluate(const TextureQuery&) const override { return Color(1.0f); }
    float alpha(const Vec2& uv) const override { return uv.x < 0.5f ? 0.0f : 1.0f; }
    std::string_view type_name() const override { return "half"; }
};

TEST(AlphaMask, CutOutHitsAreSkippedByEveryQuery) {
    // Two parallel quads; the near one is transparent on its left half.
    MeshData m;
    m.positions = {{0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}, {0, 0, 2}, {1, 0, 2}, {1, 1, 2}, {0, 1, 2}};
    m.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {1, 0}, {1, 0}, {1, 1}, {1, 1}};  // the far quad is opaque
    m.indices = {0, 1, 2, 0, 2, 3, 4, 5, 6, 4, 6, 7};
    TriangleMesh mesh(std::move(m));
    const HalfTransparent alpha;
    mesh.set_alpha_mask(&alpha, 0.5f);
    mesh.prepare();
    Ray left(Vec3(0.25f, 0.5f, 0.0f), Vec3(0, 0, 1));
    Hit hit;
    ASSERT_TRUE(mesh.intersect(left, hit));
    EXPECT_FLOAT_EQ(hit.t, 2.0f) << "the cut-out near quad is skipped";
    Ray right(Vec3(0.75f, 0.5f, 0.0f), Vec3(0, 0, 1));
    ASSERT_TRUE(mesh.intersect(right, hit));
    EXPECT_FLOAT_EQ(hit.t, 1.0f);
    EXPECT_FALSE(mesh.occluded(Ray(Vec3(0.25f, 0.5f, 0.0f), Vec3(0, 0, 1), 0.0f, 1.5f)));
    EXPECT_TRUE(mesh.occluded(Ray(Vec3(0.75f, 0.5f, 0.0f), Vec3(0, 0, 1), 0.0f, 1.5f)));
}

/// Boxes as primitives: the BVH knows only bounds and a leaf callback, so any primitive works.
TEST(ShapeAgnostic, WideBvhAgreesWithBruteForceOverBoxes) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> uniform(-10.0f, 10.0f), size(0.05f, 1.5f);
    std::vector<Bounds3> boxes(3000);
    for (Bounds3& b : boxes) {
        const Vec3 lo(uniform(rng), uniform(rng), uniform(rng));
        b = Bounds3(lo, lo + Vec3(size(rng), size(rng), size(rng)));
    }
    boxes[7] = Bounds3{};  // an empty box is left out
    WideBvh wide;
    wide.build(boxes);
    auto hit_box = [&](uint32_t i, Ray& ray) {
        float enter, exit;
        const Vec3 inv(1.0f / ray.direction.x, 1.0f / ray.direction.y, 1.0f / ray.direction.z);
        if (!boxes[i].intersect(ray.origin, inv, ray.tmin, ray.tmax, enter, exit) || enter <= ray.tmin) return false;
        ray.tmax = enter;
        return true;
    };
    for (const Ray& ray : random_rays(Bounds3(Vec3(-10.0f), Vec3(10.0f)), 2000, 9)) {
        Ray reference = ray, via_wide = ray;
        const bool expected = BruteForce(uint32_t(boxes.size())).traverse<false>(reference, hit_box);
        const bool wide_hit = wide.traverse<false>(via_wide, [&](uint32_t leaf, Ray& r) {
            bool any = false;
            const WideLeaf l = wide.leaves()[leaf];
            for (uint32_t k = l.first; k < l.first + l.count; ++k) any |= hit_box(wide.primitive_order()[k], r);
            return any;
        });
        EXPECT_EQ(wide_hit, expected);
        EXPECT_EQ(via_wide.tmax, reference.tmax);
    }
}

/// Eight boxes in a row along each octant's diagonal: a closest-hit ray along the row that
/// hits nothing visits all of them, nearest first (the precomputed per-octant child order).
TEST(ShapeAgnostic, ClosestHitTraversalVisitsChildrenFrontToBackInEveryOctant) {
    for (uint32_t octant = 0; octant < 8; ++octant) {
        const Vec3 d = normalize(Vec3(octant & 1 ? -1.0f : 1.0f, octant & 2 ? -1.0f : 1.0f, octant & 4 ? -1.0f : 1.0f));
        std::vector<Bounds3> boxes;
        for (int k = 0; k < 8; ++k) {
            const Vec3 centre = d * (2.0f * float(k));
            boxes.emplace_back(centre - Vec3(0.5f), centre + Vec3(0.5f));
        }
        std::reverse(boxes.begin(), boxes.end());  // slot order is not distance order
        WideBvh wide;
        wide.build(boxes, BvhBuildConfig{.max_leaf_size = 1});
        ASSERT_EQ(wide.nodes().size(), 1u);
        std::vector<uint32_t> visited;
        Ray ray(d * -4.0f, d, 0.0f, 100.0f);
        EXPECT_FALSE(wide.traverse<false>(ray, [&](uint32_t leaf, Ray&) {
            visited.push_back(wide.primitive_order()[wide.leaves()[leaf].first]);
            return false;
        }));
        EXPECT_EQ(visited, (std::vector<uint32_t>{7, 6, 5, 4, 3, 2, 1, 0})) << "octant " << octant;
    }
}

/// A box of NaN (a hostile mesh's triangle) in a node with seven others, in random places:
/// it is never hit, and in no octant's child order may it take the place of a box that can
/// be (its key in the order is NaN, which compares with nothing).
TEST(ShapeAgnostic, ANaNBoxHidesNoNeighbourFromTraversal) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    std::mt19937 rng(3);
    int missed = 0;
    for (int trial = 0; trial < 40; ++trial) {
        // Eight cells of a 4 x 4 x 4 grid, one box in each, the NaN box first or last.
        std::vector<int> cells(64);
        std::iota(cells.begin(), cells.end(), 0);
        std::shuffle(cells.begin(), cells.end(), rng);
        std::vector<Bounds3> boxes;
        for (int k = 0; k < 8; ++k) {
            const Vec3 lo(3.0f * float(cells[k] % 4), 3.0f * float(cells[k] / 4 % 4), 3.0f * float(cells[k] / 16));
            boxes.emplace_back(lo, lo + Vec3(1.0f));
        }
        const uint32_t nan_box = trial % 2 ? 7 : 0;
        boxes[nan_box] = Bounds3(Vec3(nan), Vec3(nan));
        WideBvh wide;
        wide.build(boxes, BvhBuildConfig{.max_leaf_size = 1});
        ASSERT_EQ(wide.nodes().size(), 1u);
        for (uint32_t octant = 0; octant < 8; ++octant)
            for (uint32_t k = 0; k < 8; ++k) {
                if (k == nan_box) continue;
                const Vec3 d =
                    normalize(Vec3(octant & 1 ? -1.0f : 1.0f, octant & 2 ? -1.0f : 1.0f, octant & 4 ? -1.0f : 1.0f));
                Ray ray(boxes[k].center() - d * 0.1f, d, 0.0f, 0.2f);  // inside box k only
                bool found = false;
                wide.traverse<false>(ray, [&](uint32_t leaf, Ray&) {
                    found |= wide.primitive_order()[wide.leaves()[leaf].first] == k;
                    return false;
                });
                missed += !found;
            }
    }
    EXPECT_EQ(missed, 0);
}

/// Two hit children are taken by where the ray enters them: here the large box, whose centre
/// lies farther along the ray than the small one's, is entered first.
TEST(ShapeAgnostic, TwoHitChildrenAreVisitedByEntryDistance) {
    const std::vector<Bounds3> boxes{Bounds3(Vec3(2.9f), Vec3(3.1f)), Bounds3(Vec3(0.0f), Vec3(10.0f))};
    WideBvh wide;
    wide.build(boxes, BvhBuildConfig{.max_leaf_size = 1});
    ASSERT_EQ(wide.nodes().size(), 1u);
    std::vector<uint32_t> visited;
    Ray ray(Vec3(-1.0f), normalize(Vec3(1.0f)), 0.0f, 100.0f);
    EXPECT_FALSE(wide.traverse<false>(ray, [&](uint32_t leaf, Ray&) {
        visited.push_back(wide.primitive_order()[wide.leaves()[leaf].first]);
        return false;
    }));
    EXPECT_EQ(visited, (std::vector<uint32_t>{1, 0}));
}

TEST(Build, TheTreeDoesNotDependOnTheThreadCount) {
    // 81,920 triangles: big enough for the binary build's parallel tasks and for the
    // collapse's (a tree of 2^14 binary nodes or more).
    const MeshData sphere = icosphere(6);
    auto build_with = [&](int threads) {
        TriangleBvh bvh;
        tbb::task_arena(threads).execute([&] { bvh.build(sphere.positions, sphere.indices); });
        return bvh;
    };
    const TriangleBvh one = build_with(1), two = build_with(2);
    ASSERT_EQ(one.blocks().size(), two.blocks().size());
    for (size_t i = 0; i < one.blocks().size(); ++i)
        for (uint32_t lane = 0; lane < TriangleBlock::kWidth; ++lane)
            ASSERT_EQ(one.blocks()[i].triangle[lane], two.blocks()[i].triangle[lane]) << "block " << i;
    // Every byte of every wide node: boxes, children (their numbering is the layout) and
    // child orders.
    const std::span<const WideNode> a = one.wide_bvh().nodes(), b = two.wide_bvh().nodes();
    ASSERT_EQ(a.size(), b.size());
    for (size_t i = 0; i < a.size(); ++i) ASSERT_EQ(std::memcmp(&a[i], &b[i], sizeof(WideNode)), 0) << "node " << i;
}

}  // namespace
}  // namespace glint
