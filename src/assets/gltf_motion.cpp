#include "gltf_motion.h"

#include "gltf_geometry.h"

#include "glint/math/constants.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace glint::gltf {

namespace {

/// Samples over a whole shutter, at least. Motion keys interpolate rotation by slerp and
/// translation linearly (math/animated_transform.h), so between two samples a child of a
/// turning parent moves on a chord instead of its arc: short steps keep that small. The
/// chord of a 5° step falls short of the arc by r·(1 − cos 2.5°) ≈ 0.1 % of the radius,
/// below what a blurred streak shows; 16 samples cover shutters without fast turns.
constexpr double kMinSamples = 16.0;
constexpr double kMaxStepTurn = radians(5.0f);
/// At most this many samples between two key times, whatever a node chain's turn adds up
/// to (36 cover one channel's half-turn, the most a LINEAR slerp turns between keys).
constexpr double kMaxPerInterval = 64.0;

/// `count` times evenly over [open, close].
std::vector<float> uniform_times(const Shutter& shutter, std::size_t count) {
    std::vector<float> times;
    for (std::size_t i = 0; i < count; ++i) {
        // In double: close − open can overflow a float (--shutter -3e38,3e38).
        const double open = shutter.open, close = shutter.close;
        const float t = i + 1 == count ? shutter.close : float(open + (close - open) * double(i) / double(count - 1));
        if (times.empty() || t > times.back()) times.push_back(t);
    }
    return times;
}

/// The largest turn of any placed node's chain (its own local rotation and its ancestors')
/// from pose `a` to pose `b`, in radians: the sum of the local turns bounds the world turn.
double largest_chain_turn(const std::vector<PlacedNode>& nodes, const NodePose& a, const NodePose& b) {
    std::vector<double> chain(nodes.size(), 0.0);
    double largest = 0.0;
    for (std::size_t p = 0; p < nodes.size(); ++p) {  // parents come before their children
        const auto n = std::size_t(nodes[p].node);
        chain[p] = angle_between(a.rotation[n], b.rotation[n]) +
                   (nodes[p].parent >= 0 ? chain[std::size_t(nodes[p].parent)] : 0.0);
        largest = std::max(largest, chain[p]);
    }
    return largest;
}

/// NodeMotion::times(); `thinned` is set when the shutter held too many key times.
std::vector<float> sample_times(const NodeAnimation& animation, const std::vector<PlacedNode>& nodes,
                                const Shutter& shutter, bool& thinned) {
    if (!(shutter.close > shutter.open)) return {shutter.open};
    std::vector<float> breaks{shutter.open};
    auto inside = [&](float t) { return t > shutter.open && t < shutter.close; };
    const std::vector<float> step_keys = animation.key_times(true);
    for (float t : animation.key_times()) {
        if (!inside(t)) continue;
        // A STEP channel jumps at its key: the float before it still holds the old value,
        // so the blur shows two poses rather than a slide from one to the other.
        if (const float before = std::nextafter(t, shutter.open);
            inside(before) && before > breaks.back() && std::binary_search(step_keys.begin(), step_keys.end(), t))
            breaks.push_back(before);
        breaks.push_back(t);
    }
    breaks.push_back(shutter.close);
    thinned = breaks.size() > NodeMotion::kMaxSamples;
    if (thinned) return uniform_times(shutter, NodeMotion::kMaxSamples);

    std::vector<float> times{shutter.open};
    NodePose a = animation.pose(breaks.front());
    for (std::size_t i = 1; i < breaks.size(); ++i) {
        NodePose b = animation.pose(breaks[i]);
        const double t0 = breaks[i - 1], t1 = breaks[i];
        const double by_time = std::ceil(kMinSamples * (t1 - t0) / (double(shutter.close) - double(shutter.open)));
        const double by_turn = std::ceil(largest_chain_turn(nodes, a, b) / kMaxStepTurn);
        const auto steps = std::size_t(std::clamp(std::max(by_time, by_turn), 1.0, kMaxPerInterval));
        for (std::size_t j = 1; j <= steps; ++j) {
            const float t = j == steps ? breaks[i] : float(t0 + (t1 - t0) * double(j) / double(steps));
            if (t > times.back()) times.push_back(t);
        }
        a = std::move(b);
    }
    thinned = times.size() > NodeMotion::kMaxSamples;
    return thinned ? uniform_times(shutter, NodeMotion::kMaxSamples) : times;
}

}  // namespace

NodeMotion::NodeMotion(const Document& doc, const NodeAnimation& animation, const Shutter& shutter) {
    const NodePose at_open = animation.pose(shutter.open);
    open_ = placed_nodes(doc, &at_open.local);
    times_ = sample_times(animation, open_, shutter, thinned_);
    paths_.resize(open_.size());
    // The hierarchy is the same at every time; only the local matrices change.
    for (std::size_t i = 1; i < times_.size(); ++i) {
        const NodePose pose = animation.pose(times_[i]);
        const std::vector<PlacedNode> now = placed_nodes(doc, &pose.local);
        for (std::size_t p = 0; p < now.size(); ++p) {
            std::vector<Matrix4>& path = paths_[p];
            if (path.empty() && now[p].world_from_node != open_[p].world_from_node)
                path.assign(i, open_[p].world_from_node);
            if (!path.empty()) path.push_back(now[p].world_from_node);
        }
    }
}

PlacedMeshes place_posed_meshes(Scene& scene, const Document& doc, const MeshFile& file, const NodeMotion& motion,
                                const std::function<uint32_t(uint32_t mesh)>& material, ImportNotes& notes,
                                std::size_t& moving) {
    const auto& json = doc.json;
    std::vector<std::size_t> first_primitive;  // per glTF mesh, its first primitive in `file`
    std::size_t primitives = 0;
    for (const auto& mesh : json.value("meshes", nlohmann::json::array())) {
        first_primitive.push_back(primitives);
        primitives += mesh.value("primitives", nlohmann::json::array()).size();
    }
    if (primitives != file.meshes.size())
        fail(doc.path, "the geometry has " + std::to_string(file.meshes.size()) + " meshes for " +
                           std::to_string(primitives) + " primitives (expected one each)");
    // What each placement is made of: its placed node and node-from-mesh matrix.
    struct Source {
        std::size_t placed;
        Matrix4 node_from_mesh;
    };
    std::vector<MeshPlacement> placements;
    std::vector<Source> sources;
    const std::vector<PlacedNode>& nodes = motion.at_open();
    for (std::size_t p = 0; p < nodes.size(); ++p) {
        const auto& node = json.at("nodes").at(std::size_t(nodes[p].node));
        if (!node.contains("mesh")) continue;
        const auto mesh = integer<std::size_t>(node.at("mesh"));
        if (mesh >= first_primitive.size()) continue;
        const std::vector<Matrix4> instances = gpu_instances(doc, node);
        // Named as without a shutter: assimp's name for an unnamed node, expand_gpu_instancing's
        // for an instance.
        const std::string index = std::to_string(nodes[p].node);
        const std::string name = node.value("name", instances.empty() ? "nodes[" + index + "]" : "node" + index);
        const std::size_t lo = first_primitive[mesh], hi = lo + json.at("meshes").at(mesh).at("primitives").size();
        for (std::size_t i = 0; i < std::max<std::size_t>(instances.size(), 1); ++i) {
            const Matrix4 local = instances.empty() ? Matrix4::identity() : instances[i];
            const Matrix4 world = instances.empty() ? nodes[p].world_from_node : nodes[p].world_from_node * local;
            for (std::size_t m = lo; m < hi; ++m) {
                if (!file.meshes[m]) continue;
                placements.push_back({uint32_t(m), world, instances.empty() ? name : name + "#" + std::to_string(i)});
                sources.push_back({p, local});
            }
        }
    }

    PlacedMeshes placed = place_meshes(scene, placements, file.meshes, Transform(), material, notes);
    moving = 0;
    for (std::size_t k = 0; k < placements.size(); ++k) {
        const std::optional<uint32_t> object = placed.objects_by_placement[k];
        if (!object || !motion.moves(sources[k].placed)) continue;
        const std::string& name = placements[k].node;
        if (scene.emits_light(scene.objects()[*object])) {
            notes.ignored(
                "animation of an object that lights the scene (drawn where it is at the shutter's open time: "
                "lights cannot move)",
                name);
            continue;
        }
        const Bounds3 mesh_bounds = file.meshes[placements[k].mesh]->bounds();
        std::vector<MotionKey> keys;
        for (std::size_t i = 0; i < motion.times().size(); ++i) {
            const Matrix4 world = motion.path(sources[k].placed)[i] * sources[k].node_from_mesh;
            try {
                const Transform world_from_mesh(world);
                const Bounds3 b = world_from_mesh.bounds(mesh_bounds);
                if (!is_finite(b.lo) || !is_finite(b.hi)) break;
                keys.push_back({motion.times()[i], world_from_mesh});
            } catch (const std::invalid_argument&) {
                break;
            }
        }
        if (keys.size() != motion.times().size()) {
            notes.ignored(
                "animation through a singular or huge transform (drawn where it is at the shutter's open time)", name);
            continue;
        }
        try {
            scene.set_motion(*object, AnimatedTransform(std::move(keys)));
            ++moving;
        } catch (const std::invalid_argument& e) {
            notes.ignored(std::string("animation with unusable transforms (") + e.what() + ")", name);
        }
    }
    return placed;
}

}  // namespace glint::gltf
