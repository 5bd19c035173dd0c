#pragma once
/// \file The `transform` key of scene objects.

#include "glint/scene_format/param_table.h"
#include "glint/math/transform.h"

namespace glint {

/// world_from_object from a `transform` value, either one table applied as scale, then
/// rotate, then translate:
///   transform = { scale = 2, rotate = { axis = [0, 1, 0], degrees = 30 }, translate = [1, 0, 0] }
/// or an array of one-key tables applied in the order written:
///   transform = [ { rotate = [0, 45, 0] }, { translate = [0, 1, 0] }, { scale = [1, 2, 1] } ]
/// `rotate` is an axis and an angle, or Euler angles [x, y, z] in degrees applied about x,
/// then y, then z. `matrix` gives a row-major 4×4 (16 numbers or 4 rows of 4). Throws
/// SceneError at the offending value (zero scale, zero axis, singular matrix...).
[[nodiscard]] Transform read_transform(const ParamValue& value, const ValueName& what);

}  // namespace glint
