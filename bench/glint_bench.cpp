/// glint-bench: Glint's mesh BVH next to Embree 3 on the same rays (shared/docs/bench-rays.md).
/// Prints millions of rays per second for both and their ratio, per mesh, ray set and
/// thread count (median of --reps runs, the two engines alternating so that load from
/// other processes hits both alike), and the build time and bytes per triangle. The sets
/// "primary8" and "shadow8" are the same rays traced in packets of eight consecutive rays
/// (TriangleBvh::intersect_packet/occluded_packet against rtcIntersect8/rtcOccluded8).
/// Built with a tinybvh checkout (cmake -DGLINT_TINYBVH_DIR=...), it traces the single-ray
/// sets with tinybvh's BVH8_CPU too, in the same alternation, and adds its Mrays/s.

#include "bench_rays.h"
#include "embree_scene.h"
#include "tinybvh_scene.h"

#include "glint/accel/ray_packet.h"
#include "glint/assets/mesh_loader.h"

#include <CLI/CLI.hpp>
#include <fmt/core.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace {

using namespace glint;
using namespace glint::bench;
using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

enum class Query { Closest, Any };

/// A ray set as --rays names it: which of the generated rays, the query traced with them,
/// and whether they go one at a time or in packets of eight consecutive rays.
struct RaySet {
    const char* name;
    enum class Rays { Primary, Shadow, Incoherent } rays;
    Query query;
    bool packets;
};
constexpr std::array kRaySets = {
    RaySet{"primary", RaySet::Rays::Primary, Query::Closest, false},
    RaySet{"shadow", RaySet::Rays::Shadow, Query::Any, false},
    RaySet{"incoherent", RaySet::Rays::Incoherent, Query::Closest, false},
    RaySet{"primary8", RaySet::Rays::Primary, Query::Closest, true},
    RaySet{"shadow8", RaySet::Rays::Shadow, Query::Any, true},
};

const RaySet& ray_set(const std::string& name) {
    return *std::find_if(kRaySets.begin(), kRaySets.end(), [&](const RaySet& s) { return name == s.name; });
}

/// Traces `rays` with `trace(ray) -> PrimaryHit` on `threads` threads, writing results.
template <typename Trace>
double run(const std::vector<BenchRay>& rays, int threads, std::vector<PrimaryHit>& out, Trace&& trace) {
    out.resize(rays.size());
    tbb::task_arena arena(threads);
    const auto start = Clock::now();
    arena.execute([&] {
        tbb::parallel_for(tbb::blocked_range<size_t>(0, rays.size(), 1024), [&](const tbb::blocked_range<size_t>& r) {
            for (size_t i = r.begin(); i < r.end(); ++i) out[i] = trace(rays[i]);
        });
    });
    return ms_since(start);
}

/// Traces `rays` in packets of eight consecutive rays (fewer at the end) with
/// `trace(const BenchRay* first, int count, PrimaryHit* out)` on `threads` threads.
template <typename TracePacket>
double run_packets(const std::vector<BenchRay>& rays, int threads, std::vector<PrimaryHit>& out,
                   TracePacket&& trace) {
    out.resize(rays.size());
    const size_t packets = (rays.size() + 7) / 8;
    tbb::task_arena arena(threads);
    const auto start = Clock::now();
    arena.execute([&] {
        tbb::parallel_for(tbb::blocked_range<size_t>(0, packets, 128), [&](const tbb::blocked_range<size_t>& r) {
            for (size_t p = r.begin(); p < r.end(); ++p) {
                const size_t first = 8 * p;
                trace(&rays[first], static_cast<int>(std::min<size_t>(8, rays.size() - first)), &out[first]);
            }
        });
    });
    return ms_since(start);
}

/// A reference engine's answer to one ray: its closest hit, or for an any-hit query prim 0
/// when occluded and UINT32_MAX when free (the checksums count the former as hits).
template <typename Engine>
PrimaryHit query_one(const Engine& engine, Query query, const BenchRay& b) {
    if (query == Query::Any) return engine.occluded(b) ? PrimaryHit{0.0f, 0} : PrimaryHit{0.0f, UINT32_MAX};
    return engine.intersect(b);
}

Ray to_glint(const BenchRay& b) {
    return Ray(Vec3(b.org[0], b.org[1], b.org[2]), Vec3(b.dir[0], b.dir[1], b.dir[2]), b.tnear, b.tfar);
}

struct Checksum {
    size_t hits = 0;
    double t_sum = 0.0;
};

Checksum checksum(const std::vector<PrimaryHit>& hits) {
    Checksum c;
    for (const PrimaryHit& h : hits)
        if (h.prim != UINT32_MAX) {
            ++c.hits;
            c.t_sum += h.t;
        }
    return c;
}

struct Record {
    std::string mesh, rays;
    int threads = 1;
    double glint = 0.0, embree = 0.0;  ///< Mrays/s, or build ms
    double glint_bytes = 0.0, embree_bytes = 0.0;
    Checksum glint_sum, embree_sum;
    /// tinybvh's Mrays/s and hits, when this glint-bench has it (single-ray sets only).
    std::optional<double> tinybvh;
    Checksum tinybvh_sum;
    /// Glint's wide nodes visited and triangles tested per ray (single-ray sets only).
    double nodes_per_ray = 0.0, triangles_per_ray = 0.0;
};

class MeshBench {
public:
    MeshBench(const std::filesystem::path& path, int reps, std::string embree_config)
        : name_(path.stem().string()), reps_(reps), embree_config_(std::move(embree_config)) {
        data_ = load_mesh_data(path);
    }

    /// Median build times for both engines with `threads` threads; keeps the last builds.
    Record build(int threads) {
        std::vector<double> glint_ms, embree_ms;
        tbb::task_arena arena(threads);
        for (int rep = 0; rep < reps_; ++rep) {
            auto mesh = std::make_shared<TriangleMesh>(data_, name_);
            const auto start = Clock::now();
            arena.execute([&] { mesh->prepare(); });
            glint_ms.push_back(ms_since(start));
            glint_ = mesh;
            embree_ = std::make_unique<EmbreeScene>(data_, threads, embree_config_);
            embree_ms.push_back(embree_->build());
        }
        const double tris = double(glint_->triangle_count());
        Record r;
        r.mesh = name_;
        r.rays = "build";
        r.threads = threads;
        r.glint = median(glint_ms);
        r.embree = median(embree_ms);
        r.glint_bytes = double(glint_->bvh().memory_bytes()) / tris;
        r.embree_bytes = double(embree_->bytes()) / tris;
        return r;
    }

    /// The three ray sets, generated once; the secondary rays start at Embree's primary hits.
    void make_rays() {
        primary_ = primary_rays(data_);
        std::vector<PrimaryHit> hits;
        run(primary_, 2, hits, [&](const BenchRay& b) { return embree_->intersect(b); });
        SecondaryRays secondary = secondary_rays(data_, primary_, hits);
        shadow_ = std::move(secondary.shadow);
        incoherent_ = std::move(secondary.incoherent);
        if (TinyBvhScene::available()) tinybvh_ = std::make_unique<TinyBvhScene>(data_);
    }

    /// `set` is one of kRaySets.
    Record trace(const RaySet& set, int threads) {
        const std::vector<BenchRay>& rays = set.rays == RaySet::Rays::Primary  ? primary_
                                            : set.rays == RaySet::Rays::Shadow ? shadow_
                                                                               : incoherent_;
        const Query query = set.query;
        const Shape& mesh = *glint_;
        auto glint_trace = [&](const BenchRay& b) -> PrimaryHit {
            Ray ray = to_glint(b);
            if (query == Query::Any) return mesh.occluded(ray) ? PrimaryHit{0.0f, 0} : PrimaryHit{0.0f, UINT32_MAX};
            Hit hit;
            return mesh.intersect(ray, hit) ? PrimaryHit{hit.t, hit.primitive} : PrimaryHit{0.0f, UINT32_MAX};
        };
        auto embree_trace = [&](const BenchRay& b) { return query_one(*embree_, query, b); };
        const TriangleBvh& bvh = glint_->bvh();
        auto glint_packet = [&](const BenchRay* b, int count, PrimaryHit* out) {
            RayPacket packet;
            for (int i = 0; i < count; ++i) packet.set(static_cast<uint32_t>(i), to_glint(b[i]));
            if (query == Query::Any) {
                const uint32_t hits = bvh.occluded_packet(packet);
                for (int i = 0; i < count; ++i) out[i] = {0.0f, (hits >> i & 1) ? 0u : UINT32_MAX};
                return;
            }
            PacketHits h;
            const uint32_t hits = bvh.intersect_packet(packet, h);
            for (int i = 0; i < count; ++i)
                out[i] = (hits >> i & 1) ? PrimaryHit{h.t[i], h.primitive[i]} : PrimaryHit{0.0f, UINT32_MAX};
        };
        auto embree_packet = [&](const BenchRay* b, int count, PrimaryHit* out) {
            if (query == Query::Any)
                embree_->occluded8(b, count, out);
            else
                embree_->intersect8(b, count, out);
        };
        auto tinybvh_trace = [&](const BenchRay& b) { return query_one(*tinybvh_, query, b); };
        const bool with_tinybvh = tinybvh_ && !set.packets;
        std::vector<double> glint_ms, embree_ms, tinybvh_ms;
        std::vector<PrimaryHit> glint_hits, embree_hits, tinybvh_hits;
        for (int rep = 0; rep < reps_; ++rep) {
            glint_ms.push_back(set.packets ? run_packets(rays, threads, glint_hits, glint_packet)
                                           : run(rays, threads, glint_hits, glint_trace));
            embree_ms.push_back(set.packets ? run_packets(rays, threads, embree_hits, embree_packet)
                                            : run(rays, threads, embree_hits, embree_trace));
            if (with_tinybvh) tinybvh_ms.push_back(run(rays, threads, tinybvh_hits, tinybvh_trace));
        }
        const double mrays = double(rays.size()) * 1e-3;
        Record r;
        r.mesh = name_;
        r.rays = set.name;
        r.threads = threads;
        r.glint = mrays / median(glint_ms);
        r.embree = mrays / median(embree_ms);
        r.glint_sum = checksum(glint_hits);
        r.embree_sum = checksum(embree_hits);
        if (with_tinybvh) {
            r.tinybvh = mrays / median(tinybvh_ms);
            r.tinybvh_sum = checksum(tinybvh_hits);
        }
        if (!set.packets) {
            // Counted once, outside the timed runs, through the traversal the viewer's
            // heatmaps use (the same code with a counting policy).
            TraversalStats stats;
            for (const BenchRay& b : rays) {
                Ray ray = to_glint(b);
                Hit hit;
                if (query == Query::Any)
                    (void)mesh.occluded_counted(ray, stats);
                else
                    mesh.intersect_counted(ray, hit, stats);
            }
            r.nodes_per_ray = double(stats.nodes) / double(rays.size());
            r.triangles_per_ray = double(stats.primitives) / double(rays.size());
        }
        return r;
    }

    [[nodiscard]] size_t triangles() const { return data_.indices.size() / 3; }
    [[nodiscard]] size_t ray_count(const std::string& set) const {
        return set.starts_with("primary") ? primary_.size()
               : set.starts_with("shadow") ? shadow_.size()
                                           : incoherent_.size();
    }

private:
    std::string name_;
    int reps_;
    std::string embree_config_;
    MeshData data_;
    std::shared_ptr<TriangleMesh> glint_;
    std::unique_ptr<EmbreeScene> embree_;
    std::unique_ptr<TinyBvhScene> tinybvh_;
    std::vector<BenchRay> primary_, shadow_, incoherent_;
};

void print_json(const std::vector<Record>& records) {
    fmt::print("[\n");
    for (size_t i = 0; i < records.size(); ++i) {
        const Record& r = records[i];
        if (r.rays == "build")
            fmt::print(R"(  {{"mesh": "{}", "rays": "build", "threads": {}, "glint_ms": {:.3f}, "embree_ms": {:.3f}, )"
                       R"("glint_bytes_per_tri": {:.2f}, "embree_bytes_per_tri": {:.2f}}})",
                       r.mesh, r.threads, r.glint, r.embree, r.glint_bytes, r.embree_bytes);
        else
            fmt::print(
                R"(  {{"mesh": "{}", "rays": "{}", "threads": {}, "glint_mrays": {:.4f}, "embree_mrays": {:.4f}, )"
                R"("glint_hits": {}, "embree_hits": {}, "glint_nodes_per_ray": {:.2f}, )"
                R"("glint_triangles_per_ray": {:.2f}{}}})",
                r.mesh, r.rays, r.threads, r.glint, r.embree, r.glint_sum.hits, r.embree_sum.hits, r.nodes_per_ray,
                r.triangles_per_ray,
                r.tinybvh ? fmt::format(R"(, "tinybvh_version": "{}", "tinybvh_mrays": {:.4f}, "tinybvh_hits": {})",
                                        TinyBvhScene::version(), *r.tinybvh, r.tinybvh_sum.hits)
                          : std::string());
        fmt::print("{}\n", i + 1 < records.size() ? "," : "");
    }
    fmt::print("]\n");
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"glint-bench: Glint's BVH next to Embree 3 on the rays of shared/docs/bench-rays.md"};
    std::vector<std::string> meshes;
    std::vector<int> threads;
    std::vector<std::string> sets;
    int reps = 5;
    bool json = false;
    std::string embree_config;
    app.add_option("--mesh", meshes, "Mesh file (repeatable); default: the shared bunny, dragon and Lucy");
    std::vector<std::string> set_names;
    for (const RaySet& s : kRaySets) set_names.emplace_back(s.name);
    app.add_option("--rays", sets, "Ray set (repeatable); default: all")->check(CLI::IsMember(set_names));
    app.add_option("--threads", threads, "Thread count (repeatable); default: 1 and 2")->check(CLI::PositiveNumber);
    app.add_option("--reps", reps, "Repetitions per measurement (the median is reported)")->check(CLI::PositiveNumber);
    app.add_flag("--json", json, "Print one JSON array of records instead of the table");
    app.add_option("--embree-config", embree_config,
                   "Added to Embree's device configuration, e.g. isa=avx2 (default: Embree picks the best kernels)");
    CLI11_PARSE(app, argc, argv);
    if (meshes.empty()) {
        const std::filesystem::path dir = std::filesystem::path(GLINT_SHARED_DATA_DIR) / "meshes";
        for (const char* f : {"stanford_bunny.ply", "stanford_dragon.ply", "stanford_lucy_100k.ply"})
            meshes.push_back((dir / f).string());
    }
    if (threads.empty()) threads = {1, 2};
    if (sets.empty()) sets = set_names;

    std::vector<Record> records;
    try {
        for (const std::string& path : meshes) {
            MeshBench bench(path, reps, embree_config);
            if (!json) fmt::print("{}: {} triangles\n", std::filesystem::path(path).stem().string(), bench.triangles());
            std::vector<Record> builds;
            for (int t : threads) builds.push_back(bench.build(t));
            bench.make_rays();
            for (const std::string& set : sets)
                for (int t : threads) {
                    const Record r = bench.trace(ray_set(set), t);
                    records.push_back(r);
                    if (json) continue;
                    fmt::print(
                        "  {:<10} {:>7} rays  {} thr  glint {:8.2f} Mrays/s  embree {:8.2f} Mrays/s  ratio {:.2f}"
                        "  (hits {} / {}, sum t {:.6g} / {:.6g})",
                        set, bench.ray_count(set), t, r.glint, r.embree, r.glint / r.embree, r.glint_sum.hits,
                        r.embree_sum.hits, r.glint_sum.t_sum, r.embree_sum.t_sum);
                    if (r.tinybvh)
                        fmt::print("  tinybvh {} {:.2f} Mrays/s, Glint/tinybvh {:.2f} (hits {})",
                                   TinyBvhScene::version(), *r.tinybvh, r.glint / *r.tinybvh, r.tinybvh_sum.hits);
                    if (r.nodes_per_ray > 0.0)
                        fmt::print("  glint per ray: {:.1f} nodes, {:.1f} triangles", r.nodes_per_ray,
                                   r.triangles_per_ray);
                    fmt::print("\n");
                }
            for (const Record& b : builds) {
                records.push_back(b);
                if (!json)
                    fmt::print("  build      {} thr  glint {:8.1f} ms  embree {:8.1f} ms  ratio {:.2f}   "
                               "bytes/tri glint {:.1f}  embree {:.1f}\n",
                               b.threads, b.glint, b.embree, b.glint / b.embree, b.glint_bytes, b.embree_bytes);
            }
        }
    } catch (const std::exception& e) {
        fmt::print(stderr, "glint-bench: {}\n", e.what());
        return 1;
    }
    if (json) print_json(records);
    return 0;
}
