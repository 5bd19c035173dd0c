/// libglint_assimp.so: assimp's import and its conversion to Glint's meshes, materials and
/// textures, loaded by libglint the first time a mesh file or glTF is read (assimp_module.h
/// says why a module) and run only in the import child (isolated_import.h). Nothing here
/// throws across the boundary.

#include "assimp_module.h"
#include "mesh_file_bytes.h"

#include "glint/diagnostics.h"
#include "glint/image/image_io.h"
#include "glint/math/color.h"
#include "glint/util/file_extension.h"

#include <assimp/ObjMaterial.h>
#include <assimp/material.h>
#include <assimp/metadata.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <assimp/Importer.hpp>

#include <algorithm>
#include <cmath>
#include <exception>
#include <functional>
#include <initializer_list>
#include <optional>
#include <set>

namespace glint {

namespace {

// Triangulate: Glint stores triangles only. FlipUVs: assimp hands out OpenGL-style
// v (0 at the bottom), Glint's textures put v = 0 at the top row. ValidateDataStructure
// turns out-of-range indices into an error message instead of undefined reads. No
// JoinIdenticalVertices: it triples the time of a large PLY (0.2 s -> 0.7 s for the dragon)
// and renumbers vertices, and the formats that matter here are indexed already.
constexpr unsigned kImportFlags = aiProcess_Triangulate | aiProcess_FlipUVs | aiProcess_ValidateDataStructure;
// The strict reader skips the validation: its own checks (convert_mesh) refuse the same
// files and name the mesh, face and vertex, where assimp's would say it in its own words.
constexpr unsigned kStrictFlags = kImportFlags & ~unsigned(aiProcess_ValidateDataStructure);

/// How convert_scene() reads an assimp scene, and what it worked around.
struct Conversion {
    ReadMode mode = ReadMode::Lenient;
    /// Convert assimp's materials (glTF converts its own from the JSON).
    bool materials = true;
    /// A mesh without normals gets smooth ones (what users expect of a scanned PLY or an
    /// OBJ without `vn`); glTF asks for flat normals instead (spec §3.7.2.1).
    bool smooth_missing_normals = true;
    std::size_t dropped = 0, non_triangles = 0;
};

Matrix4 to_matrix(const aiMatrix4x4& a) {
    Matrix4 m;
    const float rows[4][4] = {
        {a.a1, a.a2, a.a3, a.a4}, {a.b1, a.b2, a.b3, a.b4}, {a.c1, a.c2, a.c3, a.c4}, {a.d1, a.d2, a.d3, a.d4}};
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) m.m[r][c] = rows[r][c];
    return m;
}

std::string mesh_name(const aiMesh* mesh, unsigned index) {
    return mesh->mName.length > 0 ? std::string(mesh->mName.C_Str()) : "mesh" + std::to_string(index);
}

/// The tangent frames a file stores (glTF's TANGENT, FBX's tangents and binormals), in
/// Glint's convention (geometry/tangent_space.h): the tangent made perpendicular to the
/// normal, and the sign that turns normal × tangent into the stored bitangent, the
/// direction "up" in the image (assimp's glTF reader stores normal × tangent · w, so the
/// sign is glTF's w). Empty, so that the mesh computes its own, when one is unusable:
/// non-finite, or parallel to its normal.
std::vector<Tangent> file_tangents(const aiMesh* mesh) {
    std::vector<Tangent> tangents(mesh->mNumVertices);
    for (unsigned v = 0; v < mesh->mNumVertices; ++v) {
        const Vec3 stored_normal(mesh->mNormals[v].x, mesh->mNormals[v].y, mesh->mNormals[v].z);
        const Vec3 t(mesh->mTangents[v].x, mesh->mTangents[v].y, mesh->mTangents[v].z);
        const float normal_length = std::sqrt(dot(stored_normal, stored_normal));
        if (!is_finite(stored_normal) || !is_finite(t) || !(normal_length > 0.0f)) return {};
        const Vec3 n = stored_normal / normal_length;
        const Vec3 along = t - n * dot(n, t);
        const float length = std::sqrt(dot(along, along));
        if (!(length > 1e-6f)) return {};
        float sign = 1.0f;
        if (mesh->mBitangents) {
            const Vec3 b(mesh->mBitangents[v].x, mesh->mBitangents[v].y, mesh->mBitangents[v].z);
            if (dot(cross(n, t), b) < 0.0f) sign = -1.0f;
        }
        tangents[v] = {along / length, sign};
    }
    return tangents;
}

/// MeshData of assimp mesh `index` of `path`. A triangle that indexes past the vertices or
/// touches a non-finite vertex is dropped and counted (Lenient) or refuses the file (Strict).
MeshData convert_mesh(const aiMesh* mesh, unsigned index, const std::filesystem::path& path, Conversion& conversion) {
    const bool strict = conversion.mode == ReadMode::Strict;
    auto refuse = [&](const std::string& what) {
        throw SceneError(path.string() + ": mesh " + std::to_string(index) + ": " + what);
    };
    MeshData data;
    const unsigned n = mesh->mNumVertices;
    data.positions.resize(n);
    for (unsigned v = 0; v < n; ++v) {
        data.positions[v] = {mesh->mVertices[v].x, mesh->mVertices[v].y, mesh->mVertices[v].z};
        if (strict && !is_finite(data.positions[v]))
            refuse("vertex " + std::to_string(v) + " has a non-finite position (expected finite coordinates)");
    }
    if (mesh->mNormals) {
        data.normals.resize(n);
        for (unsigned v = 0; v < n; ++v) {
            const Vec3 nv(mesh->mNormals[v].x, mesh->mNormals[v].y, mesh->mNormals[v].z);
            data.normals[v] = is_finite(nv) ? nv : Vec3(0.0f);
        }
    }
    if (mesh->mTangents && mesh->mNormals && mesh->mTextureCoords[0]) data.tangents = file_tangents(mesh);
    if (mesh->mTextureCoords[0]) {
        data.uvs.resize(n);
        for (unsigned v = 0; v < n; ++v) {
            const Vec2 uv(mesh->mTextureCoords[0][v].x, mesh->mTextureCoords[0][v].y);
            data.uvs[v] = std::isfinite(uv.x) && std::isfinite(uv.y) ? uv : Vec2(0.0f, 0.0f);
        }
    }
    if (mesh->mColors[0]) {
        // glTF's COLOR_0 is linear (glTF 2.0 §3.7.2.1); PLY's 8-bit colours (and OBJ's, written
        // from them) are display values, sRGB, as Blender and MeshLab read them.
        const std::string ext = lower_case_extension(path);
        const bool encoded = ext != ".gltf" && ext != ".glb";
        data.colors.resize(n);
        for (unsigned v = 0; v < n; ++v) {
            const aiColor4D& c = mesh->mColors[0][v];
            auto linear = [encoded](float x) {
                if (!std::isfinite(x)) return 1.0f;
                x = std::clamp(x, 0.0f, 1.0f);
                return encoded ? srgb_to_linear(x) : x;
            };
            data.colors[v] = {linear(c.r), linear(c.g), linear(c.b)};
        }
    }
    data.indices.reserve(std::size_t(mesh->mNumFaces) * 3);
    for (unsigned f = 0; f < mesh->mNumFaces; ++f) {
        const aiFace& face = mesh->mFaces[f];
        if (face.mNumIndices != 3) {
            ++conversion.non_triangles;
            continue;
        }
        bool ok = true;
        for (int k = 0; k < 3; ++k) {
            if (strict && face.mIndices[k] >= n)
                refuse("face " + std::to_string(f) + " uses vertex " + std::to_string(face.mIndices[k]) +
                       " (expected an index below " + std::to_string(n) + ")");
            ok = ok && face.mIndices[k] < n && is_finite(data.positions[face.mIndices[k]]);
        }
        if (!ok) {
            ++conversion.dropped;
            continue;
        }
        data.indices.insert(data.indices.end(), face.mIndices, face.mIndices + 3);
    }
    // Vertices no triangle uses may still be non-finite; move them onto a used vertex so the
    // mesh validates and its bounds stay finite.
    if (!data.indices.empty())
        for (Vec3& p : data.positions)
            if (!is_finite(p)) p = data.positions[data.indices[0]];
    if (!mesh->mNormals && conversion.smooth_missing_normals) compute_smooth_normals(data);
    return data;
}

/// The first texture of the first of `types` that `mat` has, decoded (embedded or beside
/// the file); null when it has none or it cannot be read (a warning says which and why).
std::shared_ptr<const Image> material_image(const aiScene* ai, const aiMaterial* mat,
                                            std::initializer_list<aiTextureType> types, ColorEncoding encoding,
                                            const std::filesystem::path& path, std::vector<std::string>& warnings) {
    aiString texture_path;
    const auto found = std::find_if(types.begin(), types.end(), [&](aiTextureType type) {
        return mat->GetTexture(type, 0, &texture_path) == AI_SUCCESS;
    });
    if (found == types.end()) return nullptr;
    const std::string name = texture_path.C_Str();
    try {
        if (const aiTexture* embedded = ai->GetEmbeddedTexture(name.c_str())) {
            if (embedded->mHeight == 0) {
                const auto* bytes = reinterpret_cast<const unsigned char*>(embedded->pcData);
                return std::make_shared<const Image>(decode_image(
                    {bytes, bytes + embedded->mWidth}, "embedded." + std::string(embedded->achFormatHint), encoding));
            }
            const bool srgb = encoding == ColorEncoding::Color;
            auto value = [srgb](unsigned char byte) { return srgb ? srgb_to_linear(byte / 255.0f) : byte / 255.0f; };
            Image img(int(embedded->mWidth), int(embedded->mHeight), 4);
            for (std::size_t i = 0; i < std::size_t(embedded->mWidth) * embedded->mHeight; ++i) {
                const aiTexel& t = embedded->pcData[i];
                const float rgba[4] = {value(t.r), value(t.g), value(t.b), t.a / 255.0f};
                std::copy(rgba, rgba + 4, img.pixels.begin() + std::ptrdiff_t(i * 4));
            }
            return std::make_shared<const Image>(std::move(img));
        }
        return std::make_shared<const Image>(read_image(path.parent_path() / name, encoding));
    } catch (const std::exception& e) {
        warnings.push_back(path.string() + ": material '" + mat->GetName().C_Str() + "': texture ignored: " + e.what());
        return nullptr;
    }
}

/// The material's tangent-space normal map. OBJ's `map_Bump`/`bump` (assimp's HEIGHT) is read
/// as a normal map, as Blender's OBJ importer and exporter do; a one- or two-channel image
/// there is a height map, which Glint does not bump with: ignored, with a warning.
std::shared_ptr<const Image> material_normal_image(const aiScene* ai, const aiMaterial* mat,
                                                   const std::filesystem::path& path,
                                                   std::vector<std::string>& warnings) {
    std::shared_ptr<const Image> image =
        material_image(ai, mat, {aiTextureType_NORMALS, aiTextureType_HEIGHT}, ColorEncoding::Data, path, warnings);
    if (image && image->channels < 3) {
        warnings.push_back(path.string() + ": material '" + mat->GetName().C_Str() + "': normal map ignored: it has " +
                           std::to_string(image->channels) +
                           " channel(s), a height map (expected RGB, a tangent-space normal map)");
        return nullptr;
    }
    return image;
}

/// OBJ/MTL, FBX, PLY... material as assimp describes it, in the Whitted model's terms.
Material convert_assimp_material(const aiMaterial* mat, unsigned index) {
    Material m;
    m.name = mat->GetName().length > 0 ? mat->GetName().C_Str() : "material" + std::to_string(index);
    aiColor3D c;
    if (mat->Get(AI_MATKEY_COLOR_DIFFUSE, c) == AI_SUCCESS) m.diffuse = {c.r, c.g, c.b};
    m.ambient = m.diffuse;  // the scene's ambient light lights the diffuse colour
    if (mat->Get(AI_MATKEY_COLOR_SPECULAR, c) == AI_SUCCESS) m.specular = {c.r, c.g, c.b};
    float shininess = 0.0f;
    if (mat->Get(AI_MATKEY_SHININESS, shininess) == AI_SUCCESS && shininess > 0.0f) m.shininess = shininess;
    if (mat->Get(AI_MATKEY_COLOR_EMISSIVE, c) == AI_SUCCESS) m.emission = {c.r, c.g, c.b};
    float reflectivity = 0.0f;
    if (mat->Get(AI_MATKEY_REFLECTIVITY, reflectivity) == AI_SUCCESS && reflectivity > 0.0f)
        m.reflectivity = Color(std::min(reflectivity, 1.0f));
    // OBJ's `-bm` on `norm` or `map_Bump`: the normal map's strength (Blender's Normal Map
    // node), which Glint applies as glTF's normalTexture.scale.
    float bump_multiplier = 1.0f;
    if ((mat->Get(AI_MATKEY_OBJ_BUMPMULT_NORMALS(0), bump_multiplier) == AI_SUCCESS ||
         mat->Get(AI_MATKEY_OBJ_BUMPMULT_HEIGHT(0), bump_multiplier) == AI_SUCCESS) &&
        std::isfinite(bump_multiplier))
        m.normal_scale = bump_multiplier;
    float opacity = 1.0f;
    if (mat->Get(AI_MATKEY_OPACITY, opacity) == AI_SUCCESS && opacity < 1.0f) {
        m.transparency = std::clamp(1.0f - opacity, 0.0f, 1.0f);
        float ior = 1.5f;
        if (mat->Get(AI_MATKEY_REFRACTI, ior) == AI_SUCCESS && ior >= 1.0f) m.ior = ior;
    }
    return m;
}

/// The up axis an FBX file's GlobalSettings declare (assimp's "UpAxis" 0/1/2 for x/y/z with
/// "UpAxisSign" ±1), which Blender's FBX importer honours. None for a downward axis, which
/// the framing camera does not take, and for formats that declare none (glTF is +y by
/// definition; assimp turns a COLLADA file's up axis into +y itself).
std::optional<UpAxis> declared_up_axis(const aiScene* ai) {
    int32_t axis = -1, sign = 1;
    if (!ai->mMetaData || !ai->mMetaData->Get("UpAxis", axis)) return std::nullopt;
    ai->mMetaData->Get("UpAxisSign", sign);
    if (sign < 0 || axis < 0 || axis > 2) return std::nullopt;
    return axis == 0 ? UpAxis::X : axis == 1 ? UpAxis::Y : UpAxis::Z;
}

/// Glint meshes, placements and (optionally) materials of an assimp scene read from `path`.
MeshFile convert_scene(const aiScene* ai, const std::filesystem::path& path, Conversion conversion) {
    MeshFile file;
    std::size_t empty = 0;
    for (unsigned i = 0; i < ai->mNumMeshes; ++i) {
        const aiMesh* mesh = ai->mMeshes[i];
        file.mesh_materials.push_back(mesh->mMaterialIndex);
        MeshData data = convert_mesh(mesh, i, path, conversion);
        if (mesh->HasBones()) file.skinned_meshes.push_back(mesh_name(mesh, i));
        if (mesh->mNumAnimMeshes > 0) file.morphed_meshes.push_back(mesh_name(mesh, i));
        if (data.indices.empty()) {
            ++empty;
            file.meshes.push_back(nullptr);
            continue;
        }
        file.meshes.push_back(std::make_shared<TriangleMesh>(std::move(data), mesh_name(mesh, i)));
    }
    if (conversion.dropped > 0)
        file.warnings.push_back(path.string() + ": dropped " + std::to_string(conversion.dropped) +
                                " triangle(s) with out-of-range indices or non-finite vertex positions");
    if (conversion.non_triangles > 0)
        file.warnings.push_back(path.string() + ": ignored " + std::to_string(conversion.non_triangles) +
                                " point/line primitive(s) (Glint renders triangles only)");
    if (empty > 0 && empty < ai->mNumMeshes)
        file.warnings.push_back(path.string() + ": " + std::to_string(empty) + " mesh(es) without triangles skipped");
    file.animations = ai->mNumAnimations;
    file.declared_up = declared_up_axis(ai);

    std::set<std::vector<unsigned>> groups;
    std::function<void(const aiNode*, const Matrix4&)> visit = [&](const aiNode* node, const Matrix4& parent) {
        const Matrix4 world = parent * to_matrix(node->mTransformation);
        std::vector<unsigned> group(node->mMeshes, node->mMeshes + node->mNumMeshes);
        for (unsigned m : group)
            if (m < file.meshes.size() && file.meshes[m]) file.placements.push_back({m, world, node->mName.C_Str()});
        if (!group.empty()) groups.insert(group);
        for (unsigned c = 0; c < node->mNumChildren; ++c) visit(node->mChildren[c], world);
    };
    visit(ai->mRootNode, Matrix4::identity());
    file.distinct_meshes = groups.size();
    // A strict read is merged mesh by mesh, placed or not; load_mesh_data checks for triangles.
    if (conversion.mode == ReadMode::Lenient && file.placements.empty())
        throw SceneError(path.string() + ": the file has no triangles to render (expected at least one triangle mesh)");

    if (conversion.materials) {
        for (unsigned i = 0; i < ai->mNumMaterials; ++i) {
            file.materials.push_back(convert_assimp_material(ai->mMaterials[i], i));
            file.material_images.push_back(material_image(ai, ai->mMaterials[i],
                                                          {aiTextureType_DIFFUSE, aiTextureType_BASE_COLOR},
                                                          ColorEncoding::Color, path, file.warnings));
            file.material_normal_images.push_back(material_normal_image(ai, ai->mMaterials[i], path, file.warnings));
        }
    }
    return file;
}

/// `read()`'s MeshFile as bytes in `out`, or what it threw as `out`'s error.
void convert_guarded(const std::function<MeshFile()>& read, assimp_import::Outcome& out) {
    try {
        out.bytes = to_bytes(read());
    } catch (const SceneError& e) {
        out.error = e.what();
        out.error_names_file = true;
    } catch (const std::exception& e) {
        out.error = e.what();
    }
}

void read_file(const std::string& path, ReadMode mode, const std::string& context, assimp_import::Outcome& out) {
    convert_guarded(
        [&] {
            const bool lenient = mode == ReadMode::Lenient;
            Assimp::Importer importer;
            const aiScene* ai = importer.ReadFile(path, mode == ReadMode::Strict ? kStrictFlags : kImportFlags);
            if (!ai || (ai->mFlags & AI_SCENE_FLAGS_INCOMPLETE) || !ai->mRootNode)
                throw SceneError(context + ": " + importer.GetErrorString());
            return convert_scene(ai, path, {.mode = mode, .materials = lenient, .smooth_missing_normals = lenient});
        },
        out);
}

void read_glb(const std::string& glb, const std::string& gltf_path, const std::string& context,
              assimp_import::Outcome& out) {
    convert_guarded(
        [&] {
            Assimp::Importer importer;
            const aiScene* ai = importer.ReadFileFromMemory(glb.data(), glb.size(), kImportFlags, "glb");
            if (!ai || (ai->mFlags & AI_SCENE_FLAGS_INCOMPLETE) || !ai->mRootNode)
                throw SceneError(context + ": " + importer.GetErrorString());
            return convert_scene(ai, gltf_path, {.materials = false, .smooth_missing_normals = false});
        },
        out);
}

constexpr assimp_import::Functions kFunctions{read_file, read_glb};

}  // namespace

}  // namespace glint

extern "C" __attribute__((visibility("default"))) const glint::assimp_import::Functions* glint_assimp_import() {
    return &glint::kFunctions;
}
