#pragma once
/// \file What a type's factory may use while a scene file is built: the scene so far, the
/// named textures, images read once, and the folder relative file names resolve against.

#include "glint/image/image_io.h"
#include "glint/scene_format/param_table.h"

#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace glint {

struct Image;
class MeshCache;
class Scene;
class Texture;

/// Shared by the sections of one scene file while it is built (a loader owns one per load;
/// nothing in it outlives the load but what it put into `scene`).
class BuildContext {
public:
    BuildContext(std::filesystem::path base_dir, Scene& scene, MeshCache& meshes, std::vector<std::string>& warnings)
        : base_dir_(std::move(base_dir)), scene_(scene), meshes_(meshes), warnings_(warnings) {}

    [[nodiscard]] Scene& scene() const { return scene_; }
    /// The mesh files read so far (each file is read once per scene).
    [[nodiscard]] MeshCache& meshes() const { return meshes_; }
    /// Problems the build works around; the render goes on.
    void warn(std::string message) const { warnings_.push_back(std::move(message)); }

    /// The file named by the string `key` of `table`, resolved against the scene file's
    /// folder. Throws SceneError at the value if there is no such file. A name is looked up
    /// on disk once per load (a scene may place one mesh file 100,000 times).
    [[nodiscard]] std::filesystem::path input_file(const ParamTable& table, std::string_view key) const;
    /// The image named by `key`, read once however many textures or backgrounds use it.
    /// Throws SceneError at the value if it cannot be read.
    [[nodiscard]] std::shared_ptr<const Image> image(const ParamTable& table, std::string_view key,
                                                     ColorEncoding encoding);
    /// The texture of `[[textures]]` named by `key` (null when the key is absent). Throws
    /// SceneError at the value, suggesting the closest name, if there is none of that name.
    [[nodiscard]] const Texture* texture(const ParamTable& table, std::string_view key) const;
    [[nodiscard]] bool has_texture(std::string_view name) const { return textures_.count(name) != 0; }
    /// Give a texture of `[[textures]]` its name, by which materials refer to it.
    void name_texture(std::string name, const Texture* texture) { textures_.emplace(std::move(name), texture); }
    /// The index of the scene material named by the string `value`. Throws SceneError at
    /// the value, suggesting the closest name, if there is none.
    [[nodiscard]] uint32_t material(const ParamValue& value, const ValueName& what) const;

private:
    std::filesystem::path base_dir_;
    Scene& scene_;
    MeshCache& meshes_;
    std::vector<std::string>& warnings_;
    std::map<std::string, std::shared_ptr<const Image>> images_;
    /// Names given to input_file() that were found to be files, resolved.
    mutable std::map<std::string, std::filesystem::path, std::less<>> found_files_;
    std::map<std::string, const Texture*, std::less<>> textures_;
};

}  // namespace glint
