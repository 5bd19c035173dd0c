#pragma once
/// \file The `[[shapes]]` and `[[objects]]` sections: geometry placed in the scene.

#include "glint/scene_format/build_context.h"
#include "glint/scene_format/scene_builder.h"

namespace glint {

/// Build the named shapes of `[[shapes]]`, then add every `[[objects]]` entry of `root`
/// and then of `more_objects` (if given) to the context's scene, whose materials must
/// already be there. Shapes come from the shape
/// table (scene_format/registry.h); a mesh file (`type = "mesh"` with `file`) is imported
/// through the context's mesh cache, and its warnings join the context's. Throws
/// SceneError at `file:line:column`.
void add_objects(const ParamTable& root, const MoreObjects& more_objects, BuildContext& context);

}  // namespace glint
