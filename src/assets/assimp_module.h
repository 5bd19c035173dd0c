#pragma once
/// \file The boundary between libglint and assimp. Internal to src/assets.
///
/// assimp 5.2.5 (Debian 12) is one shared library with 44,000 relocations, plus Draco and
/// minizip: linked in, it cost every process 7-10 ms before main() (on a 2-core EPYC), most
/// of the start-up of `glint --help` and of a render that reads no mesh file
/// (docs/performance.md, "Start-up"). So assimp and the conversion of what it reads live in
/// a module of their own, `libglint_assimp.so` (assimp_import.cpp), loaded the first time a
/// mesh file or a glTF is read, and called only in the import child (isolated_import.h).
/// The module links its own copy of the libglint code the conversion uses, and hands back
/// the MeshFile as bytes (mesh_file_bytes.h), as the child does.

#include "mesh_file.h"

#include <string>

namespace glint::assimp_import {

/// A MeshFile as bytes, or what went wrong.
struct Outcome {
    std::string bytes;
    std::string error;
    /// The error names the file already (a SceneError's); otherwise it is a bare reason.
    bool error_names_file = false;
};

struct Functions {
    /// Read the mesh file at `path`. `context` ("PATH: cannot read mesh file") starts the
    /// error when assimp refuses the file.
    void (*read_file)(const std::string& path, ReadMode mode, const std::string& context, Outcome& out);
    /// Read the geometry-only GLB in memory that gltf::geometry_glb made of the glTF at
    /// `gltf_path` (leniently, without materials or generated normals).
    void (*read_glb)(const std::string& glb, const std::string& gltf_path, const std::string& context, Outcome& out);
};

/// The module's entry point, looked up by this name.
inline constexpr const char* kEntryPoint = "glint_assimp_import";

}  // namespace glint::assimp_import
