#pragma once
/// \file The motion keys of scene objects (motion blur; docs/scene-format.md, "Motion").

#include "glint/math/animated_transform.h"
#include "glint/scene_format/param_table.h"

#include <optional>
#include <vector>

namespace glint {

/// An object's placement over time, if it moves: `transform` at time 0 and `transform_end`
/// at time 1, or time-stamped keys
///   motion = [ { time = 0, transform = {...} }, { time = 0.5, transform = {...} }, ... ]
/// in increasing time (at least two). None when the object has neither. Throws SceneError
/// at the offending value: a key out of order, `motion` beside `transform`.
[[nodiscard]] std::optional<std::vector<MotionKey>> read_motion_keys(const ParamTable& t);

}  // namespace glint
