#include "display_options.h"

#include <fmt/core.h>

#include <string>

namespace glint::app {

void add_display_options(CLI::App* command, std::optional<glint::Exposure>& exposure,
                         std::optional<glint::ToneCurve>& tone_curve) {
    command->add_option_function<std::string>(
        "--exposure",
        [&exposure](const std::string& text) {
            exposure = glint::parse_exposure(text);
            if (!exposure)
                throw CLI::ValidationError("--exposure",
                                           fmt::format("expected a number of stops or 'auto'; got '{}'", text));
        },
        "Exposure in stops for PNG/JPEG/TIFF output, or 'auto' (the log-average luminance becomes middle grey); "
        "default: the scene's (0)");
    command->add_option_function<std::string>(
        "--tonemap",
        [&tone_curve](const std::string& text) {
            tone_curve = glint::parse_tone_curve(text);
            if (!tone_curve)
                throw CLI::ValidationError("--tonemap", fmt::format("expected {}; got '{}'",
                                                                    glint::tone_curve_names(), text));
        },
        fmt::format("Tone curve for PNG/JPEG/TIFF output: {} (EXR/HDR/PFM stay linear); default: the scene's "
                    "(none, pbr-neutral for glTF)",
                    glint::tone_curve_names()));
}

glint::DisplayTransform with_display_options(glint::DisplayTransform from_file,
                                             const std::optional<glint::Exposure>& exposure,
                                             const std::optional<glint::ToneCurve>& tone_curve) {
    if (exposure) from_file.exposure = *exposure;
    if (tone_curve) from_file.tone_curve = *tone_curve;
    return from_file;
}

}  // namespace glint::app
