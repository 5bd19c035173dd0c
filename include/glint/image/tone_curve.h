#pragma once
/// \file Tone curves: how scene-referred radiance (linear Rec.709, unbounded) becomes
/// display-referred linear values in [0, 1] before sRGB encoding. Applied only when writing
/// display formats (PNG, JPEG, 8-bit TIFF); EXR, HDR and PFM keep the radiance as it is.

#include "glint/math/color.h"

#include <optional>
#include <string_view>

namespace glint {

enum class ToneCurve {
    /// No curve: values pass through and the 8-bit encoder clips each channel at 1 (a
    /// bright red light turns yellow, then white). Glint's classic look for scenes built in
    /// display terms, as the assignments' are.
    None,
    /// Clip without a hue shift: a colour whose brightest channel exceeds 1 is scaled down
    /// until it is 1, so an over-exposed red light stays red.
    Clamp,
    /// ACES filmic: Stephen Hill's fit of the ACES RRT + sRGB ODT (BakingLab ACES.hlsl), with
    /// the 1/0.6 exposure boost three.js and the Khronos glTF Sample Viewer use, so that
    /// middle grey stays near middle grey.
    Aces,
    /// AgX (Troy Sobotka; Blender 4's default view), in Benjamin Wrensch's "minimal AgX"
    /// form: inset matrix, log2 encoding over [-12.47, 4.03] EV around 0.18, the
    /// default-contrast sigmoid as a 6th-order polynomial, outset matrix, 2.2 display gamma.
    Agx,
    /// Khronos PBR Neutral (KhronosGroup/ToneMapping, 2024): the glTF ecosystem's reference
    /// for viewers. Base colours under 0.76 come out unchanged (but for a small toe offset);
    /// brighter values compress towards 1 and desaturate.
    PbrNeutral,
};

/// "none", "clamp", "aces", "agx" or "pbr-neutral"; nullopt otherwise.
[[nodiscard]] std::optional<ToneCurve> parse_tone_curve(std::string_view name);
/// The name parse_tone_curve reads.
[[nodiscard]] std::string_view tone_curve_name(ToneCurve curve);
/// The names parse_tone_curve accepts, for messages: "none, clamp, aces, agx or pbr-neutral".
[[nodiscard]] std::string_view tone_curve_names();

/// Map exposed scene-linear Rec.709 to display-linear Rec.709. Every curve but None returns
/// values in [0, 1]; None returns `linear` unchanged.
[[nodiscard]] Color apply_tone_curve(ToneCurve curve, const Color& linear);

}  // namespace glint
