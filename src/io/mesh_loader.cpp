#include "glint/io/mesh_loader.h"

#include "glint/io/scene_file.h"

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

namespace glint {

namespace {

const aiScene* read_file(Assimp::Importer& importer, const std::filesystem::path& path, unsigned flags) {
    if (!std::filesystem::exists(path)) throw SceneError(path.string() + ": no such mesh file");
    const aiScene* ai = importer.ReadFile(path.string(), flags);
    if (!ai || (ai->mFlags & AI_SCENE_FLAGS_INCOMPLETE) || !ai->mRootNode)
        throw SceneError(path.string() + ": cannot read mesh: " + importer.GetErrorString());
    return ai;
}

}  // namespace

MeshData load_mesh_data(const std::filesystem::path& path) {
    Assimp::Importer importer;
    const aiScene* ai = read_file(importer, path, aiProcess_Triangulate | aiProcess_JoinIdenticalVertices);
    MeshData data;
    for (unsigned m = 0; m < ai->mNumMeshes; ++m) {
        const aiMesh* mesh = ai->mMeshes[m];
        if (!(mesh->mPrimitiveTypes & aiPrimitiveType_TRIANGLE)) continue;
        const auto base = static_cast<uint32_t>(data.positions.size());
        for (unsigned v = 0; v < mesh->mNumVertices; ++v)
            data.positions.emplace_back(mesh->mVertices[v].x, mesh->mVertices[v].y, mesh->mVertices[v].z);
        for (unsigned f = 0; f < mesh->mNumFaces; ++f) {
            const aiFace& face = mesh->mFaces[f];
            if (face.mNumIndices != 3) continue;
            for (int k = 0; k < 3; ++k) data.indices.push_back(base + face.mIndices[k]);
        }
    }
    if (data.indices.empty()) throw SceneError(path.string() + ": the file has no triangles");
    return data;
}

MeshImportResult import_mesh_file(Scene&, const std::filesystem::path& path, const Transform&,
                                  std::optional<uint32_t>) {
    throw SceneError(path.string() + ": mesh import into scenes is not implemented yet");
}

}  // namespace glint
