#include "glint/scene/environment.h"

#include "glint/image/image_io.h"
#include "glint/math/constants.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>

namespace glint {

std::optional<BackgroundKind> parse_environment_kind(std::string_view name) {
    if (name == "equirect" || name == "equirectangular" || name == "latlong") return BackgroundKind::Equirectangular;
    if (name == "spheremap" || name == "mirrorball" || name == "probe") return BackgroundKind::SphereMap;
    if (name == "angmap" || name == "angular") return BackgroundKind::AngularMap;
    return std::nullopt;
}

std::optional<std::string> environment_shape_problem(BackgroundKind kind, int width, int height) {
    const std::string found = std::to_string(width) + "x" + std::to_string(height);
    if (kind == BackgroundKind::Equirectangular && width != 2 * height)
        return "a 2:1 image for an equirectangular map (width = 2 × height), not " + found;
    if (kind == BackgroundKind::SphereMap && width != height)
        return "a square image for a sphere map, not " + found;
    if (kind == BackgroundKind::AngularMap && width != height)
        return "a square image for an angular map, not " + found;
    return std::nullopt;
}

Background load_environment(const std::filesystem::path& path, const EnvironmentOptions& options) {
    if (!(options.intensity >= 0.0f && std::isfinite(options.intensity)))
        throw std::invalid_argument(path.string() + ": environment intensity must be a finite number >= 0");
    if (!std::isfinite(options.rotation_degrees))
        throw std::invalid_argument(path.string() + ": environment rotation must be finite");
    auto image = std::make_shared<const Image>(read_image(path, ColorEncoding::Color));
    BackgroundKind kind = BackgroundKind::Equirectangular;
    if (options.kind) {
        kind = *options.kind;
    } else if (image->width == 2 * image->height) {
        kind = BackgroundKind::Equirectangular;
    } else if (image->width == image->height) {
        kind = BackgroundKind::SphereMap;
    } else {
        throw std::invalid_argument(path.string() + ": cannot tell the environment layout of a " +
                                    std::to_string(image->width) + "x" + std::to_string(image->height) +
                                    " image (expected 2:1 equirectangular or 1:1 sphere map; give the kind)");
    }
    if (kind == BackgroundKind::Constant) throw std::invalid_argument("an environment map needs an image layout");
    if (const std::optional<std::string> problem = environment_shape_problem(kind, image->width, image->height))
        throw std::invalid_argument(path.string() + ": expected " + *problem);
    return Background::environment(kind, std::move(image), options.rotation_degrees, options.intensity);
}

Color average_radiance(const Background& background) {
    // A Fibonacci sphere: equal-area, so the plain mean is the mean over solid angle.
    constexpr int kSamples = 1024;
    const float golden_angle = kPi * (3.0f - std::sqrt(5.0f));
    Color sum;
    for (int i = 0; i < kSamples; ++i) {
        const float y = 1.0f - 2.0f * (float(i) + 0.5f) / float(kSamples);
        const float r = std::sqrt(std::max(0.0f, 1.0f - y * y));
        const float phi = golden_angle * float(i);
        sum += background.evaluate(Vec3(r * std::cos(phi), y, r * std::sin(phi)));
    }
    return sum / float(kSamples);
}

}  // namespace glint
