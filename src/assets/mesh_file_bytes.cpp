#include "mesh_file_bytes.h"

#include "glint/diagnostics.h"
#include "glint/util/byte_stream.h"

#include <stdexcept>

namespace glint {

namespace {

// A field added to Material must be handed over too (or be a texture, which the parent
// makes from material_images): this fails to compile until write_material/read_material
// have been looked at.
static_assert(sizeof(Material) == 208, "Material changed: update write_material and read_material");

void write_material(ByteWriter& w, const Material& m) {
    w.text(m.name);
    w.value(m.ambient);
    w.value(m.diffuse);
    w.value(m.specular);
    w.value(m.shininess);
    w.value(m.reflectivity);
    w.value(uint8_t(m.fresnel_mirror));
    w.value(m.transparency);
    w.value(m.ior);
    w.value(m.emission);
    w.value(m.alpha_cutoff);
    w.value(m.normal_scale);
    w.value(m.roughness);
    w.value(m.base_color);
    w.value(m.metallic);
    w.value(m.absorption);
    w.value(m.dielectric_f0);
}

Material read_material(ByteReader& r) {
    Material m;
    m.name = r.text();
    m.ambient = r.value<Color>();
    m.diffuse = r.value<Color>();
    m.specular = r.value<Color>();
    m.shininess = r.value<float>();
    m.reflectivity = r.value<Color>();
    m.fresnel_mirror = r.value<uint8_t>() != 0;
    m.transparency = r.value<float>();
    m.ior = r.value<float>();
    m.emission = r.value<Color>();
    m.alpha_cutoff = r.value<float>();
    m.normal_scale = r.value<float>();
    m.roughness = r.value<float>();
    m.base_color = r.value<Color>();
    m.metallic = r.value<float>();
    m.absorption = r.value<Color>();
    m.dielectric_f0 = r.value<Color>();
    return m;
}

void write_names(ByteWriter& w, const std::vector<std::string>& names) {
    w.value(uint64_t(names.size()));
    for (const std::string& name : names) w.text(name);
}

std::vector<std::string> read_names(ByteReader& r) {
    // No reserve(): a damaged count ends with the data, not with a huge allocation.
    const auto n = r.value<uint64_t>();
    std::vector<std::string> names;
    for (uint64_t i = 0; i < n; ++i) names.push_back(r.text());
    return names;
}

void write_images(ByteWriter& w, const std::vector<std::shared_ptr<const Image>>& images) {
    w.value(uint64_t(images.size()));
    for (const std::shared_ptr<const Image>& image : images) {
        w.value(uint8_t(image != nullptr));
        if (!image) continue;
        w.value(image->width);
        w.value(image->height);
        w.value(image->channels);
        w.array(image->pixels);
    }
}

/// Throws ByteStreamError (or std::invalid_argument for an image whose size does not match
/// its pixels).
std::vector<std::shared_ptr<const Image>> read_images(ByteReader& r) {
    std::vector<std::shared_ptr<const Image>> images;
    for (uint64_t i = 0, n = r.value<uint64_t>(); i < n; ++i) {
        if (r.value<uint8_t>() == 0) {
            images.push_back(nullptr);
            continue;
        }
        auto image = std::make_shared<Image>();
        image->width = r.value<int>();
        image->height = r.value<int>();
        image->channels = r.value<int>();
        r.array(image->pixels);
        if (image->width <= 0 || image->height <= 0 || image->channels <= 0 ||
            image->pixels.size() !=
                std::size_t(image->width) * std::size_t(image->height) * std::size_t(image->channels))
            throw std::invalid_argument("an image's size does not match its pixels");
        images.push_back(std::move(image));
    }
    return images;
}

}  // namespace

std::string to_bytes(const MeshFile& file) {
    ByteWriter w;
    // Room for the meshes' arrays and the images' pixels, which are nearly all of it, plus
    // the rest: the dragon's 4.8 MB grew by doubling, copied 17 MB and faulted 4,000 pages.
    std::size_t size = std::size_t(1) << 16;
    for (const std::shared_ptr<TriangleMesh>& mesh : file.meshes)
        if (mesh) {
            const MeshData& data = mesh->data();
            size += 256 + mesh->name().size() + data.positions.size() * sizeof(Vec3) +
                    data.indices.size() * sizeof(uint32_t) + data.normals.size() * sizeof(Vec3) +
                    data.uvs.size() * sizeof(Vec2) + data.colors.size() * sizeof(Color) +
                    data.vertex_materials.size() * sizeof(data.vertex_materials[0]) +
                    data.tangents.size() * sizeof(Tangent);
        }
    for (const auto* images : {&file.material_images, &file.material_normal_images})
        for (const std::shared_ptr<const Image>& image : *images)
            if (image) size += 64 + image->pixels.size() * sizeof(float);
    w.reserve(size);
    w.value(uint64_t(file.meshes.size()));
    for (const std::shared_ptr<TriangleMesh>& mesh : file.meshes) {
        w.value(uint8_t(mesh != nullptr));
        if (!mesh) continue;
        w.text(mesh->name());
        const MeshData& data = mesh->data();
        w.array(data.positions);
        w.array(data.indices);
        w.array(data.normals);
        w.array(data.uvs);
        w.array(data.colors);
        w.array(data.vertex_materials);
        w.array(data.tangents);
    }
    w.array(file.mesh_materials);
    w.value(uint64_t(file.placements.size()));
    for (const MeshPlacement& p : file.placements) {
        w.value(p.mesh);
        w.value(p.file_from_mesh);
        w.text(p.node);
    }
    w.value(uint64_t(file.distinct_meshes));
    w.value(uint64_t(file.materials.size()));
    for (const Material& m : file.materials) write_material(w, m);
    write_images(w, file.material_images);
    write_images(w, file.material_normal_images);
    w.value(uint8_t(file.declared_up ? 1 + int(*file.declared_up) : 0));
    write_names(w, file.warnings);
    write_names(w, file.skinned_meshes);
    write_names(w, file.morphed_meshes);
    w.value(uint64_t(file.animations));
    w.value(uint64_t(file.gpu_instances));
    return w.take();
}

MeshFile mesh_file_from_bytes(std::string_view bytes, const std::string& context) {
    MeshFile file;
    ByteReader r(bytes);
    auto damaged = [&](const std::string& what) -> SceneError {
        return SceneError(context + ": the importer process handed back damaged data (" + what + ")");
    };
    try {
        for (uint64_t i = 0, n = r.value<uint64_t>(); i < n; ++i) {
            if (r.value<uint8_t>() == 0) {
                file.meshes.push_back(nullptr);
                continue;
            }
            std::string name = r.text();
            MeshData data;
            r.array(data.positions);
            r.array(data.indices);
            r.array(data.normals);
            r.array(data.uvs);
            r.array(data.colors);
            r.array(data.vertex_materials);
            r.array(data.tangents);
            file.meshes.push_back(std::make_shared<TriangleMesh>(std::move(data), std::move(name)));
        }
        r.array(file.mesh_materials);
        for (uint64_t i = 0, n = r.value<uint64_t>(); i < n; ++i) {
            MeshPlacement p;
            p.mesh = r.value<uint32_t>();
            p.file_from_mesh = r.value<Matrix4>();
            p.node = r.text();
            if (p.mesh >= file.meshes.size() || !file.meshes[p.mesh]) throw damaged("a node draws no mesh");
            file.placements.push_back(std::move(p));
        }
        file.distinct_meshes = std::size_t(r.value<uint64_t>());
        for (uint64_t i = 0, n = r.value<uint64_t>(); i < n; ++i) file.materials.push_back(read_material(r));
        file.material_images = read_images(r);
        file.material_normal_images = read_images(r);
        if (file.material_images.size() != file.materials.size() ||
            file.material_normal_images.size() != file.materials.size())
            throw damaged("a material's images are missing");
        const auto up = r.value<uint8_t>();
        if (up > 3) throw damaged("an unknown up axis");
        if (up > 0) file.declared_up = UpAxis(up - 1);
        file.warnings = read_names(r);
        file.skinned_meshes = read_names(r);
        file.morphed_meshes = read_names(r);
        file.animations = std::size_t(r.value<uint64_t>());
        file.gpu_instances = std::size_t(r.value<uint64_t>());
        if (!r.at_end()) throw damaged("data after the end");
    } catch (const ByteStreamError& e) {
        throw damaged(e.what());
    } catch (const std::invalid_argument& e) {
        throw damaged(e.what());  // a mesh that does not validate
    }
    return file;
}

}  // namespace glint
