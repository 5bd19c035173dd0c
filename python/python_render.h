#pragma once
// glint.render and glint.explain: the command line's render and explain, with its settings
// as keywords (light_samples for --light-samples).

#include "python_image.h"
#include "python_scene.h"

#include <pybind11/pybind11.h>

#include <cstdint>
#include <optional>
#include <utility>

namespace glint::python {

namespace py = pybind11;

/// Render `scene` with its settings overridden by `keywords`; `progress` as
/// run_interruptibly takes it. The GIL is released while the render runs.
[[nodiscard]] PythonImage render(PythonScene& scene, const py::object& progress, const py::kwargs& keywords);

/// Pixel `pixel` (column, row from the top left) explained as `glint explain --json` prints it,
/// as dicts and lists: its value, and each sample's rays (of sample `sample` only, if given).
[[nodiscard]] py::object explain(PythonScene& scene, std::pair<int64_t, int64_t> pixel, std::optional<int64_t> sample,
                                 const py::kwargs& keywords);

}  // namespace glint::python
