#pragma once
// glint.Image: a rendered image (or one made from a NumPy array) whose pixels NumPy views
// without a copy, saved through the command line's writer.

#include "glint/image/display_transform.h"
#include "glint/image/image.h"

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace glint::python {

namespace py = pybind11;

/// Channels named (Film::to_image, AovFilm::append_to), and the display transform its scene
/// asks for (save() uses it for PNG and JPEG, as `glint render` does).
struct PythonImage {
    Image image;
    DisplayTransform display;
};

/// A copy of `pixels`, shaped (height, width) or (height, width, channels). `channels` names
/// them; by default Y, R G B, or R G B A for 1, 3 or 4 channels.
[[nodiscard]] PythonImage image_from_array(const py::array_t<float, py::array::c_style | py::array::forcecast>& pixels,
                                           std::optional<std::vector<std::string>> channels);

/// The pixels, shape (height, width, channels), for the buffer protocol.
[[nodiscard]] py::buffer_info image_buffer(PythonImage& image);

/// Channel `name` of the PythonImage `self` as a (height, width) array over its pixels;
/// KeyError listing the channels when it has no such channel.
[[nodiscard]] py::array image_channel(const py::object& self, const std::string& name);

/// Written as `glint render -o PATH` writes: under a temporary name, then renamed.
void save_image(const PythonImage& image, const std::filesystem::path& path);

}  // namespace glint::python
