#pragma once
/// \file The film of the AOVs (image/aov.h): per pixel, sums of what the camera rays hit
/// first and of the radiance and its square, beside the image's own Film.

#include "glint/image/aov.h"
#include "glint/image/film.h"
#include "glint/image/image.h"
#include "glint/math/color.h"
#include "glint/math/vec3.h"

#include <cstdint>
#include <span>
#include <vector>

namespace glint {

/// What a camera ray hit first, filled by the integrator (TraceContext::first_hit).
struct FirstHit {
    bool hit = false;
    /// Diffuse reflectance kd·texture·(1 − transparency).
    Color albedo;
    /// Unit shading normal, on the camera's side.
    Vec3 normal;
    Vec3 position;
    /// Along the camera ray, whose direction has unit length.
    float distance = 0.0f;
};

/// What the AOV film keeps per pixel. Radiance sums are in double: the variance is a
/// difference of two of them.
struct AovPixel {
    Color albedo;
    Vec3 normal;
    Vec3 position;
    float distance = 0.0f;
    uint32_t hits = 0;
    uint32_t samples = 0;
    double radiance[3] = {0.0, 0.0, 0.0};
    double radiance_squared[3] = {0.0, 0.0, 0.0};
};

class AovFilm {
public:
    AovFilm(uint32_t width, uint32_t height, std::vector<Aov> aovs)
        : width_(width), height_(height), aovs_(std::move(aovs)), pixels_(std::size_t(width) * height) {}

    [[nodiscard]] const std::vector<Aov>& aovs() const { return aovs_; }

    /// Add one sample of pixel (x, y); as Film::add_sample, one thread per pixel at a time.
    void add_sample(uint32_t x, uint32_t y, const FirstHit& first, const Color& radiance);

    /// `image` (from Film::to_image, whose channels are named) with the AOVs' named channels
    /// after its own. Throws std::invalid_argument for an image without channel names.
    [[nodiscard]] Image append_to(const Image& image) const;

    /// The accumulators, row by row from the top (checkpoints save and restore them).
    [[nodiscard]] std::span<const AovPixel> pixels() const { return pixels_; }
    [[nodiscard]] std::span<AovPixel> pixels() { return pixels_; }

private:
    uint32_t width_, height_;
    std::vector<Aov> aovs_;
    std::vector<AovPixel> pixels_;
};

}  // namespace glint
