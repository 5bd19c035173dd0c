#include "glint/lights/area_light.h"

#include "glint/geometry/disk.h"
#include "glint/geometry/quad.h"
#include "glint/geometry/sphere.h"
#include "glint/scene/scene.h"
#include "glint/scene_format/build_context.h"
#include "glint/scene_format/transform_params.h"

#include <cmath>
#include <stdexcept>

namespace glint {

namespace {

/// `radiance`, `transform` and `name` of an area light of `shape`; `two_sided` only for
/// shapes with two sides (a closed sphere emits outwards).
void add_shape_light(const ParamTable& t, BuildContext& context, std::shared_ptr<Shape> shape, bool has_two_sides) {
    const Color radiance = emitted_color(t, "radiance");
    const bool two_sided = has_two_sides && t.boolean("two_sided", false);
    std::optional<Transform> transform;
    if (const ParamValue* v = t.find("transform")) transform = read_transform(*v, t.name_of("transform"));
    const std::string name = t.string("name", "");
    t.reject_unknown_keys();
    context.scene().add_area_light(std::move(shape), Emitter{radiance, two_sided}, transform, name);
}

Vec3 column(const Matrix4& m, int c) { return {m.m[0][c], m.m[1][c], m.m[2][c]}; }

/// Does the linear part map every sphere to a sphere (orthogonal columns of equal length)?
bool is_similarity(const Matrix4& m) {
    const Vec3 c0 = column(m, 0), c1 = column(m, 1), c2 = column(m, 2);
    const float s = dot(c0, c0);
    constexpr float kTolerance = 1e-4f;
    auto near = [&](float a, float b) { return std::abs(a - b) <= kTolerance * s; };
    return near(dot(c1, c1), s) && near(dot(c2, c2), s) && near(dot(c0, c1), 0.0f) && near(dot(c1, c2), 0.0f) &&
           near(dot(c0, c2), 0.0f);
}

float linear_determinant(const Matrix4& m) { return dot(column(m, 0), cross(column(m, 1), column(m, 2))); }

/// Aᵀ·v for the linear part A.
Vec3 transpose_times(const Matrix4& m, const Vec3& v) {
    return {dot(column(m, 0), v), dot(column(m, 1), v), dot(column(m, 2), v)};
}

}  // namespace

AreaLight::AreaLight(std::shared_ptr<Shape> shape, const std::optional<Transform>& world_from_object,
                     const Color& radiance, const Texture* texture, bool two_sided)
    : Light(false), shape_(std::move(shape)), radiance_(radiance), texture_(texture), two_sided_(two_sided) {
    shape_->prepare_sampling();
    if (!(shape_->area() > 0.0f))
        throw std::invalid_argument(std::string(shape_->type_name()) + " has no area that can emit light");
    if (world_from_object && !world_from_object->is_identity()) {
        world_from_object_ = *world_from_object;
        object_from_world_ = world_from_object->inverse();
        similarity_ = is_similarity(world_from_object->matrix());
        det_ = std::abs(linear_determinant(world_from_object->matrix()));
    }
}

Color AreaLight::emitted(const Vec3& p, const Vec3& n, Vec2 uv, const Vec3& w) const {
    if (!two_sided_ && dot(n, w) <= 0.0f) return Color();
    return texture_ ? radiance_ * texture_->evaluate(uv, p) : radiance_;
}

float AreaLight::area_pdf(const Vec3& world_normal) const {
    // dA_world = |det A|·|A^{-T} n_obj| dA_obj = |det A| / |Aᵀ n_world| dA_obj.
    const float scale = det_ / length(transpose_times(world_from_object_->matrix(), world_normal));
    return 1.0f / (shape_->area() * scale);
}

LightSample AreaLight::sample(const Vec3& point, Vec2 u) const {
    LightSample ls;
    ls.is_delta = false;
    // Only a textured emitter reads the sample's texture coordinates; a sphere's cost an
    // atan2 and an acos, a fifth of the soft-shadow scene's time (docs/performance.md).
    const InteractionDetail detail = texture_ ? InteractionDetail::Full : InteractionDetail::WithoutTextureCoordinates;
    // Each branch reads its sample field by field where the call left it: one optional
    // assigned in all three was copied whole, a 32-byte load of the callee's narrower
    // stores that waited for them (store forwarding fails), a tenth of this function.
    Vec3 p, n;
    Vec2 uv;
    float pdf = 0.0f;
    if (!world_from_object_) {
        const std::optional<ShapeSample> s = shape_->sample_toward(point, u, detail);
        if (!s) return ls;
        p = s->p, n = s->n, uv = s->uv, pdf = s->pdf;
    } else if (similarity_) {
        const std::optional<ShapeSample> s = shape_->sample_toward(object_from_world_->point(point), u, detail);
        if (!s) return ls;
        p = world_from_object_->point(s->p);
        n = normalize(world_from_object_->normal(s->n));
        uv = s->uv, pdf = s->pdf;
    } else {
        const std::optional<ShapeSample> s = shape_->sample_area(u, detail);
        if (!s) return ls;
        p = world_from_object_->point(s->p);
        n = normalize(world_from_object_->normal(s->n));
        uv = s->uv;
        pdf = this->pdf(point, p, n);
    }
    const Vec3 d = p - point;
    const float dist = length(d);
    if (!(dist > 0.0f) || !(pdf > 0.0f) || !std::isfinite(pdf)) return ls;
    ls.direction = d / dist;
    ls.distance = dist;
    ls.point = p;
    ls.normal = dot(n, ls.direction) < 0.0f ? n : -n;
    ls.radiance = emitted(p, n, uv, -ls.direction);
    ls.pdf = pdf;
    return ls;
}

float AreaLight::pdf(const Vec3& ref, const Vec3& p, const Vec3& n) const {
    if (!world_from_object_) return shape_->pdf_toward(ref, p, n);
    if (similarity_)
        return shape_->pdf_toward(object_from_world_->point(ref), object_from_world_->point(p),
                                  normalize(object_from_world_->normal(n)));
    const Vec3 d = p - ref;
    const float dist2 = dot(d, d);
    const float cos_light = std::abs(dot(n, d)) / std::sqrt(dist2);
    if (cos_light == 0.0f) return 0.0f;
    return area_pdf(n) * dist2 / cos_light;
}

void AreaLight::add_sphere_from_params(const ParamTable& t, BuildContext& context) {
    add_shape_light(t, context, Sphere::from_params(t, context), false);
}

void AreaLight::add_quad_from_params(const ParamTable& t, BuildContext& context) {
    add_shape_light(t, context, Quad::from_params(t, context), true);
}

void AreaLight::add_disk_from_params(const ParamTable& t, BuildContext& context) {
    add_shape_light(t, context, Disk::from_params_facing(t, Vec3(0.0f, -1.0f, 0.0f)), true);
}

}  // namespace glint
