// The tables of every type a scene file can name. Adding a type: write its factory beside
// the type (a static `from_params` reading its keys from the ParamTable), add one line
// here, and document its keys in docs/scene-format.md.
#include "glint/scene_format/registry.h"

#include "glint/geometry/box.h"
#include "glint/geometry/disk.h"
#include "glint/geometry/heightfield.h"
#include "glint/geometry/quad.h"
#include "glint/geometry/sphere.h"
#include "glint/geometry/triangle_mesh.h"
#include "glint/lights/area_light.h"
#include "glint/lights/light.h"
#include "glint/materials/texture.h"
#include "glint/scene/scene.h"
#include "glint/scene_format/build_context.h"

#include <array>

namespace glint {

namespace {

/// Point-like lights are built without the scene; this adds what their factory made.
template <std::unique_ptr<Light> (*create)(const ParamTable&)>
void add_light(const ParamTable& params, BuildContext& context) {
    context.scene().add_light(create(params));
}

// The order of each table is the order of the names in messages ("expected one of ...").

constexpr std::array kShapeTypes{
    ShapeType{"sphere", Sphere::from_params},
    ShapeType{"triangle", TriangleMesh::triangle_from_params},
    ShapeType{"mesh", TriangleMesh::from_params},
    ShapeType{"quad", Quad::from_params},
    ShapeType{"plane", Quad::plane_from_params},
    ShapeType{"box", Box::from_params},
    ShapeType{"heightfield", Heightfield::from_params},
    ShapeType{"disk", Disk::from_params},
};

constexpr std::array kLightTypes{
    LightType{"point", add_light<PointLight::from_params>},
    LightType{"directional", add_light<DirectionalLight::from_params>},
    LightType{"spot", add_light<SpotLight::from_params>},
    LightType{"sphere", AreaLight::add_sphere_from_params},
    LightType{"quad", AreaLight::add_quad_from_params},
    LightType{"disk", AreaLight::add_disk_from_params},
};

constexpr std::array kTextureTypes{
    TextureType{"image", ImageTexture::from_params},
    TextureType{"checker", CheckerTexture::from_params},
};

constexpr std::array kMaterialTypes{
    MaterialType{"standard", Material::standard_from_params},
};

}  // namespace

std::span<const ShapeType> shape_types() { return kShapeTypes; }
std::span<const LightType> light_types() { return kLightTypes; }
std::span<const TextureType> texture_types() { return kTextureTypes; }
std::span<const MaterialType> material_types() { return kMaterialTypes; }

}  // namespace glint
