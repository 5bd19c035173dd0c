#pragma once
/// \file The default scene's glTF nodes posed by their animation (glTF 2.0 §3.11) over the
/// camera's shutter, and the mesh objects they place: moving ones get the world transforms
/// sampled over the shutter as motion keys (math/animated_transform.h). Internal: the
/// scene loader uses it when a shutter is given (--time, --shutter).

#include "gltf_animation.h"
#include "mesh_file.h"
#include "place_meshes.h"

#include "glint/scene/scene.h"

#include <functional>
#include <vector>

namespace glint::gltf {

class NodeMotion {
public:
    /// Most sample times over one shutter; a shutter holding more key times than this is
    /// sampled uniformly instead (thinned()).
    static constexpr std::size_t kMaxSamples = 256;

    /// Pose the nodes of `doc` by `animation` at the times of `shutter` (times()).
    NodeMotion(const Document& doc, const NodeAnimation& animation, const Shutter& shutter);

    /// The open time alone for an instant; else open, close, every key time in between
    /// (and, before a STEP key, the float just before it), and more between those: at least
    /// 16 samples over the shutter, and so many that between two of them no node chain turns
    /// by more than 5°.
    [[nodiscard]] const std::vector<float>& times() const { return times_; }
    /// The placed nodes (placed_nodes() order) at the shutter's open time.
    [[nodiscard]] const std::vector<PlacedNode>& at_open() const { return open_; }
    /// Whether placed node `p` moves while the shutter is open.
    [[nodiscard]] bool moves(std::size_t p) const { return !paths_[p].empty(); }
    /// World-from-node of a moving placed node `p` at each of times().
    [[nodiscard]] const std::vector<Matrix4>& path(std::size_t p) const { return paths_[p]; }
    [[nodiscard]] bool thinned() const { return thinned_; }

private:
    std::vector<float> times_;
    std::vector<PlacedNode> open_;
    std::vector<std::vector<Matrix4>> paths_;
    bool thinned_ = false;
};

/// Add one object per primitive of every placed node's mesh (and per EXT_mesh_gpu_instancing
/// instance; `file` holds the primitives' meshes in glTF order), placed where the node is at
/// the shutter's open time, with scene material `material(primitive)`. An object whose node
/// moves gets its path as motion keys, and counts in `moving`; one that lights the scene, or
/// whose path passes a singular or huge transform, stays where it is at open (noted).
PlacedMeshes place_posed_meshes(Scene& scene, const Document& doc, const MeshFile& file, const NodeMotion& motion,
                                const std::function<uint32_t(uint32_t mesh)>& material, ImportNotes& notes,
                                std::size_t& moving);

}  // namespace glint::gltf
