#include "glint/scene_format/transform_params.h"

#include <fmt/format.h>

#include <stdexcept>

namespace glint {

namespace {

Transform scaling(const ParamValue& value, const ValueName& what) {
    const Vec3 s = value.is_number() ? Vec3(value.as_float(what)) : value.is_array() ? value.as_vec3(what) : Vec3(0.0f);
    if (!value.is_number() && !value.is_array()) value.fail(what, "a scale factor or [sx, sy, sz]");
    if (s.x == 0.0f || s.y == 0.0f || s.z == 0.0f) value.fail(what, "non-zero scale factors");
    return Transform::scale(s);
}

Transform rotation(const ParamValue& value, const ValueName& what) {
    constexpr std::string_view expected = "Euler angles [x, y, z] in degrees, or { axis = [x, y, z], degrees = a }";
    if (value.is_table()) {
        const ParamTable& t = value.as_table(what);
        const Vec3 axis = t.require_vec3("axis");
        const float degrees = t.require_number("degrees");
        t.reject_unknown_keys();
        if (!(length(axis) > 0.0f)) t.fail("axis", "a non-zero axis");
        return Transform::rotate(degrees, axis);
    }
    if (!value.is_array() || value.as_array(what).size() != 3) value.fail(what, expected);
    // Euler angles: about x first, then y, then z (world_from_object = Rz·Ry·Rx).
    const Vec3 e = value.as_vec3(what);
    return Transform::rotate(e.z, Vec3(0, 0, 1)) * Transform::rotate(e.y, Vec3(0, 1, 0)) *
           Transform::rotate(e.x, Vec3(1, 0, 0));
}

Transform matrix(const ParamValue& value, const ValueName& what) {
    constexpr std::string_view expected = "a row-major 4×4 matrix: 16 numbers or 4 rows of 4";
    if (!value.is_array()) value.fail(what, expected);
    std::vector<const ParamValue*> numbers;
    for (const ParamValue& element : value.as_array(what)) {
        if (element.is_array()) {
            if (element.as_array(what).size() != 4) element.fail(what.str() + " row", "4 numbers");
            for (const ParamValue& n : element.as_array(what)) numbers.push_back(&n);
        } else {
            numbers.push_back(&element);
        }
    }
    if (numbers.size() != 16) value.fail(what, expected);
    Matrix4 m;
    for (std::size_t i = 0; i < 16; ++i) m.m[i / 4][i % 4] = numbers[i]->as_float(ValueName(what, i));
    if (m.m[3][0] != 0.0f || m.m[3][1] != 0.0f || m.m[3][2] != 0.0f || m.m[3][3] != 1.0f)
        value.fail(what, "an affine matrix (last row 0, 0, 0, 1)");
    try {
        return Transform(m);
    } catch (const std::invalid_argument&) {
        value.fail(what, "an invertible matrix");
    }
}

/// One step of a transform list: a table with exactly one of the step keys.
Transform step(const ParamTable& t) {
    const ParamValue* scale = t.find("scale");
    const ParamValue* rotate = t.find("rotate");
    const ParamValue* translate = t.find("translate");
    const ParamValue* mat = t.find("matrix");
    t.reject_unknown_keys();
    const int count = int(scale != nullptr) + int(rotate != nullptr) + int(translate != nullptr) + int(mat != nullptr);
    if (count != 1)
        t.fail_here(
            fmt::format("{} has {} steps; expected exactly one of scale, rotate, translate, matrix per table "
                        "(the list gives the order)",
                        t.path(), count));
    if (scale) return scaling(*scale, ValueName(t, "scale"));
    if (rotate) return rotation(*rotate, ValueName(t, "rotate"));
    if (translate) return Transform::translate(translate->as_vec3(ValueName(t, "translate")));
    return matrix(*mat, ValueName(t, "matrix"));
}

}  // namespace

Transform read_transform(const ParamValue& value, const ValueName& name) {
    if (value.is_array()) {
        Transform world_from_object;
        const auto& steps = value.as_array(name);
        for (std::size_t i = 0; i < steps.size(); ++i)
            world_from_object = step(steps[i].as_table(ValueName(name, i))) * world_from_object;
        return world_from_object;
    }
    if (!value.is_table()) value.fail(name, "a table { scale, rotate, translate } or an array of such steps");
    const ParamTable& t = value.as_table(name);
    if (t.find("matrix")) {
        // A matrix is the whole transform; combining it with steps needs the list form's order.
        if (t.find("scale") || t.find("rotate") || t.find("translate"))
            t.fail_here(name.str() +
                        " has a matrix and other steps; expected either alone, or a list of steps to give "
                        "their order");
        const Transform m = matrix(*t.find("matrix"), ValueName(t, "matrix"));
        t.reject_unknown_keys();
        return m;
    }
    Transform world_from_object;
    if (const ParamValue* s = t.find("scale")) world_from_object = scaling(*s, ValueName(t, "scale"));
    if (const ParamValue* r = t.find("rotate"))
        world_from_object = rotation(*r, ValueName(t, "rotate")) * world_from_object;
    if (const ParamValue* tr = t.find("translate"))
        world_from_object = Transform::translate(tr->as_vec3(ValueName(t, "translate"))) * world_from_object;
    t.reject_unknown_keys();
    return world_from_object;
}

}  // namespace glint
