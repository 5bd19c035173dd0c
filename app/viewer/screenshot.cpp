#include "screenshot.h"

#include "glint/image/image_io.h"

#include <SDL_opengl.h>
#include <fmt/core.h>

#include <cmath>
#include <cstdio>
#include <vector>

namespace glint::app {

void write_screenshot(SDL_Window* window, const std::string& path) {
    int w = 0, h = 0;
    SDL_GL_GetDrawableSize(window, &w, &h);
    std::vector<uint8_t> rgb(std::size_t(w) * std::size_t(h) * 3);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, w, h, GL_RGB, GL_UNSIGNED_BYTE, rgb.data());
    // The writer takes linear values and encodes them to sRGB: decode what the window shows.
    Image image(w, h, 3);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (int c = 0; c < 3; ++c) {
                const float v = float(rgb[(std::size_t(h - 1 - y) * w + x) * 3 + c]) / 255.0f;
                image.at(x, y, c) = v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f);
            }
    try {
        write_image(path, image, WriteOptions{});
        fmt::print("screenshot {}\n", path);
    } catch (const std::exception& e) {
        fmt::print("{}\n", e.what());
    }
    std::fflush(stdout);
}

}  // namespace glint::app
