#include "python_image.h"

#include "glint/image/image_io.h"

#include <algorithm>
#include <cstring>

namespace glint::python {

PythonImage image_from_array(const py::array_t<float, py::array::c_style | py::array::forcecast>& pixels,
                             std::optional<std::vector<std::string>> channels) {
    if (pixels.ndim() != 2 && pixels.ndim() != 3)
        throw py::value_error("expected an array of shape (height, width) or (height, width, channels); got " +
                              std::to_string(pixels.ndim()) + " dimensions");
    const auto count = pixels.ndim() == 3 ? pixels.shape(2) : 1;
    if (!channels) {
        switch (count) {
            case 1:
                channels = {{"Y"}};
                break;
            case 3:
                channels = {{"R", "G", "B"}};
                break;
            case 4:
                channels = {{"R", "G", "B", "A"}};
                break;
            default:
                throw py::value_error(std::to_string(count) +
                                      " channels: name them, channels=[...] (only 1, 3 and 4 have default names)");
        }
    }
    if (py::ssize_t(channels->size()) != count)
        throw py::value_error(std::to_string(channels->size()) + " channel names for " + std::to_string(count) +
                              " channels");
    if (pixels.shape(0) == 0 || pixels.shape(1) == 0) throw py::value_error("the image has no pixels");
    PythonImage out;
    out.image = Image(int(pixels.shape(1)), int(pixels.shape(0)), int(count));
    std::memcpy(out.image.pixels.data(), pixels.data(), out.image.pixels.size() * sizeof(float));
    out.image.channel_names = std::move(*channels);
    return out;
}

py::buffer_info image_buffer(PythonImage& image) {
    const auto c = py::ssize_t(image.image.channels), w = py::ssize_t(image.image.width);
    const auto f = py::ssize_t(sizeof(float));
    return {image.image.pixels.data(),
            f,
            py::format_descriptor<float>::format(),
            3,
            {py::ssize_t(image.image.height), w, c},
            {f * c * w, f * c, f}};
}

py::array image_channel(const py::object& self, const std::string& name) {
    const PythonImage& img = py::cast<const PythonImage&>(self);
    const std::vector<std::string>& names = img.image.channel_names;
    const auto it = std::find(names.begin(), names.end(), name);
    if (it == names.end()) {
        std::string list;
        for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
        throw py::key_error("no channel '" + name + "'; the image has " + list);
    }
    const auto f = py::ssize_t(sizeof(float)), c = py::ssize_t(img.image.channels);
    // `self` as the base keeps the image alive while the array lives.
    return {py::dtype::of<float>(),
            {py::ssize_t(img.image.height), py::ssize_t(img.image.width)},
            {f * c * img.image.width, f * c},
            img.image.pixels.data() + (it - names.begin()),
            self};
}

void save_image(const PythonImage& image, const std::filesystem::path& path) {
    WriteOptions options;
    options.tone_curve = image.display.tone_curve;
    options.exposure = exposure_stops(image.display.exposure, image.image);
    const py::gil_scoped_release release;
    write_image(path, image.image, options);
}

}  // namespace glint::python
