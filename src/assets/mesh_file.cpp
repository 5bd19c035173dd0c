#include "mesh_file.h"

#include "assimp_module.h"
#include "gltf_geometry.h"
#include "isolated_import.h"
#include "mesh_file_bytes.h"
#include "name_list.h"
#include "ply_header.h"
#include "ply_triangles.h"

#include "glint/diagnostics.h"
#include "glint/util/file_extension.h"
#include "glint/util/module_loader.h"

#include <cctype>
#include <fstream>
#include <stdexcept>

namespace glint {

std::vector<std::string> animation_warnings(const std::filesystem::path& path, const MeshFile& file) {
    std::vector<std::string> lines;
    auto names = [](const std::vector<std::string>& list) { return quoted_names(list, list.size()); };
    if (!file.skinned_meshes.empty())
        lines.push_back(path.string() + ": ignored skins: meshes drawn in their bind pose (" +
                        names(file.skinned_meshes) + ")");
    if (!file.morphed_meshes.empty())
        lines.push_back(path.string() + ": ignored morph targets: meshes drawn with their base shape (" +
                        names(file.morphed_meshes) + ")");
    if (file.animations > 0)
        lines.push_back(path.string() + ": ignored " + std::to_string(file.animations) +
                        " animation(s): nodes drawn at their rest transforms");
    return lines;
}

namespace {

/// assimp reads an OBJ whose `mtllib` file is missing without a word, and draws its
/// materials in a default grey; one warning per missing library says why.
std::vector<std::string> missing_material_libraries(const std::filesystem::path& obj) {
    std::vector<std::string> warnings;
    std::ifstream in(obj, std::ios::binary);
    std::string line;
    while (std::getline(in, line)) {
        if (line.rfind("mtllib", 0) != 0 || line.size() < 7 || !std::isspace(static_cast<unsigned char>(line[6])))
            continue;
        // assimp takes the rest of the line as one name, as here.
        const auto first = line.find_first_not_of(" \t", 7), last = line.find_last_not_of(" \t\r");
        if (first == std::string::npos) continue;
        const std::string name = line.substr(first, last - first + 1);
        std::error_code ec;
        if (!std::filesystem::is_regular_file(obj.parent_path() / name, ec))
            warnings.push_back(obj.string() + ": material library '" + name +
                               "' not found beside it; its materials are drawn in assimp's default grey");
    }
    return warnings;
}

/// assimp's functions, loaded once (in this process, before the import child is forked, so
/// that every child has them). Throws SceneError when the module cannot be loaded.
const assimp_import::Functions& assimp() {
    static const assimp_import::Functions& functions = load_module_table<assimp_import::Functions, SceneError>(
        GLINT_ASSIMP_MODULE, assimp_import::kEntryPoint, "assimp");
    return functions;
}

/// The bytes of a MeshFile `outcome` holds; its error thrown as the import's own would be.
std::string bytes_of(assimp_import::Outcome outcome) {
    if (outcome.error.empty()) return std::move(outcome.bytes);
    if (outcome.error_names_file) throw SceneError(outcome.error);
    throw std::runtime_error(outcome.error);
}

}  // namespace

MeshFile read_mesh_file(const std::filesystem::path& path, ReadMode mode) {
    if (!std::filesystem::exists(path)) throw SceneError(path.string() + ": no such mesh file");
    check_ply_header(path);
    if (std::optional<MeshFile> plain = read_plain_ply(path, mode)) return std::move(*plain);
    return read_mesh_file_with_assimp(path, mode);
}

MeshFile read_mesh_file_with_assimp(const std::filesystem::path& path, ReadMode mode) {
    const std::string context = path.string() + ": cannot read mesh file";
    const assimp_import::Functions& functions = assimp();
    const std::vector<char> bytes = run_isolated(
        [&] {
            assimp_import::Outcome outcome;
            functions.read_file(path.string(), mode, context, outcome);
            return bytes_of(std::move(outcome));
        },
        context);
    MeshFile file = mesh_file_from_bytes(std::string_view(bytes.data(), bytes.size()), path.string());
    if (mode == ReadMode::Lenient && lower_case_extension(path) == ".obj") {
        const std::vector<std::string> missing = missing_material_libraries(path);
        file.warnings.insert(file.warnings.end(), missing.begin(), missing.end());
    }
    return file;
}

MeshFile read_gltf_geometry(const gltf::Document& doc) {
    std::vector<std::string> warnings;
    const std::string glb = gltf::geometry_glb(doc, warnings);
    const std::string context = doc.path.string() + ": cannot read the geometry";
    const assimp_import::Functions& functions = assimp();
    const std::vector<char> bytes = run_isolated(
        [&] {
            assimp_import::Outcome outcome;
            functions.read_glb(glb, doc.path.string(), context, outcome);
            return bytes_of(std::move(outcome));
        },
        context);
    MeshFile file = mesh_file_from_bytes(std::string_view(bytes.data(), bytes.size()), doc.path.string());
    file.warnings.insert(file.warnings.begin(), warnings.begin(), warnings.end());
    // assimp numbers meshes primitive by primitive; the materials come from the JSON.
    std::vector<uint32_t> materials = gltf::primitive_materials(doc);
    if (materials.size() != file.mesh_materials.size())
        throw SceneError(doc.path.string() + ": assimp returned " + std::to_string(file.mesh_materials.size()) +
                         " meshes for " + std::to_string(materials.size()) + " primitives (expected one each)");
    file.mesh_materials = std::move(materials);
    file.gpu_instances = gltf::expand_gpu_instancing(doc, file);
    return file;
}

}  // namespace glint
