#pragma once
/// \file A glTF 2.0 file (.gltf or .glb) rendered as a whole scene: geometry and node
/// hierarchy through assimp, cameras, KHR_lights_punctual and materials from the file's
/// JSON. docs/assets.md lists what maps to what; docs/units.md the light units.

#include "glint/scene/asset_defaults.h"
#include "glint/scene/loaded_scene.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace glint {

struct GltfOptions {
    /// Camera to render through: its name or its index in the file's "cameras" array
    /// (the first placed camera when empty). A name that matches nothing is an error.
    std::string camera;
    /// When the camera's shutter is open, in seconds of the file's animations: nodes are
    /// posed by them, and objects that move while it is open get motion keys (blur). Without
    /// one, animations are ignored and nodes keep their rest transforms.
    std::optional<Shutter> shutter = std::nullopt;
    /// The up axis of the automatic camera, for a file without cameras (glTF says +y).
    UpAxis up = UpAxis::Y;
};

/// A camera the file places in its scene.
struct GltfCamera {
    int index = 0;
    /// The node that places it.
    int node = 0;
    std::string name;
    Camera camera;
    /// glTF aspectRatio (0 when the file leaves it to the viewport).
    float aspect = 0.0f;
};

/// What the file held and what became of it (for `glint info` and the tests).
struct GltfReport {
    std::size_t meshes = 0;       ///< distinct glTF meshes placed
    std::size_t primitives = 0;   ///< distinct triangle primitives (Glint meshes) placed
    std::size_t objects = 0;      ///< placements (instances) in the scene
    std::size_t triangles = 0;    ///< triangles stored
    std::size_t instanced_triangles = 0;
    std::size_t materials = 0;    ///< the file's materials, all converted
    bool default_material = false;  ///< some primitive had no material
    std::size_t textures = 0;     ///< distinct textures the materials use
    std::size_t lights = 0;       ///< KHR_lights_punctual lights placed by nodes
    std::vector<GltfCamera> cameras;
    int selected_camera = -1;     ///< index into `cameras`; -1 = automatic framing camera
    bool default_lighting = false;
    std::vector<std::string> mapped;   ///< one line per mapped feature
    std::vector<std::string> ignored;  ///< one line per ignored feature (also in the warnings)
};

struct GltfScene {
    LoadedScene loaded;
    GltfReport report;
};

/// Load a glTF 2.0 file as a scene. Throws SceneError naming the file and the problem when
/// nothing can be rendered (unreadable file, missing buffer, no triangles, unknown camera).
[[nodiscard]] GltfScene load_gltf_scene(const std::filesystem::path& path, const GltfOptions& options = {});

}  // namespace glint
