#include "glint/image/tone_curve.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace glint {

namespace {

/// A 3×3 matrix acting on a column (r, g, b): rows as written.
using Matrix3 = std::array<std::array<float, 3>, 3>;

Color multiply(const Matrix3& m, const Color& c) {
    return {m[0][0] * c.r + m[0][1] * c.g + m[0][2] * c.b, m[1][0] * c.r + m[1][1] * c.g + m[1][2] * c.b,
            m[2][0] * c.r + m[2][1] * c.g + m[2][2] * c.b};
}

Color clamp01(const Color& c) {
    return {std::clamp(c.r, 0.0f, 1.0f), std::clamp(c.g, 0.0f, 1.0f), std::clamp(c.b, 0.0f, 1.0f)};
}

float max_channel(const Color& c) { return std::max({c.r, c.g, c.b}); }

Color clamp_keeping_hue(const Color& c) {
    const Color positive{std::max(c.r, 0.0f), std::max(c.g, 0.0f), std::max(c.b, 0.0f)};
    const float peak = max_channel(positive);
    return peak > 1.0f ? positive / peak : positive;
}

// Stephen Hill's fit (BakingLab ACES.hlsl): sRGB → AP1 with the RRT's saturation, the
// RRT + ODT tone scale as a rational function, and back to sRGB with the ODT's saturation.
constexpr Matrix3 kAcesInput = {{{0.59719f, 0.35458f, 0.04823f},
                                 {0.07600f, 0.90834f, 0.01566f},
                                 {0.02840f, 0.13383f, 0.83777f}}};
constexpr Matrix3 kAcesOutput = {{{1.60475f, -0.53108f, -0.07367f},
                                  {-0.10208f, 1.10813f, -0.00605f},
                                  {-0.00327f, -0.07276f, 1.07602f}}};
/// three.js and the glTF Sample Viewer divide by 0.6 first: the fit alone maps 0.18 to 0.11.
constexpr float kAcesExposureBoost = 1.0f / 0.6f;

float aces_tone_scale(float v) {
    return (v * (v + 0.0245786f) - 0.000090537f) / (v * (0.983729f * v + 0.4329510f) + 0.238081f);
}

Color aces(const Color& linear) {
    const Color ap1 = multiply(kAcesInput, linear * kAcesExposureBoost);
    const Color toned{aces_tone_scale(ap1.r), aces_tone_scale(ap1.g), aces_tone_scale(ap1.b)};
    return clamp01(multiply(kAcesOutput, toned));
}

// AgX from Troy Sobotka's OCIO configuration, as Benjamin Wrensch's "minimal AgX
// implementation" (iolite-engine.com, 2023) condenses it.
constexpr Matrix3 kAgxInset = {{{0.842479062253094f, 0.0784335999999992f, 0.0792237451477643f},
                                {0.0423282422610123f, 0.878468636469772f, 0.0791661274605434f},
                                {0.0423756549057051f, 0.0784336f, 0.879142973793104f}}};
constexpr Matrix3 kAgxOutset = {{{1.19687900512017f, -0.0980208811401368f, -0.0990297440797205f},
                                 {-0.0528968517574562f, 1.15190312990417f, -0.0989611768448433f},
                                 {-0.0529716355144438f, -0.0980434501171241f, 1.15107367264116f}}};
/// The log2 window: 10 stops below and 6.5 above middle grey (log2 0.18 = -2.47393).
constexpr float kAgxMinEv = -12.47393f;
constexpr float kAgxMaxEv = 4.026069f;
/// AgX's display encoding is a pure 2.2 power; Glint's writer adds the sRGB encoding.
constexpr float kAgxDisplayGamma = 2.2f;

/// The default-contrast sigmoid over the normalised log value x in [0, 1] (Wrensch's fit).
float agx_contrast(float x) {
    const float x2 = x * x;
    const float x4 = x2 * x2;
    return 15.5f * x4 * x2 - 40.14f * x4 * x + 31.96f * x4 - 6.868f * x2 * x + 0.4298f * x2 + 0.1191f * x -
           0.00232f;
}

float agx_channel(float v) {
    const float ev = std::clamp(std::log2(std::max(v, 1e-10f)), kAgxMinEv, kAgxMaxEv);
    return agx_contrast((ev - kAgxMinEv) / (kAgxMaxEv - kAgxMinEv));
}

Color agx(const Color& linear) {
    const Color inset = multiply(kAgxInset, linear);
    const Color encoded = clamp01(multiply(kAgxOutset, {agx_channel(inset.r), agx_channel(inset.g), agx_channel(inset.b)}));
    return {std::pow(encoded.r, kAgxDisplayGamma), std::pow(encoded.g, kAgxDisplayGamma),
            std::pow(encoded.b, kAgxDisplayGamma)};
}

// Khronos PBR Neutral (KhronosGroup/ToneMapping, PBR_Neutral/README.md).
/// Values whose largest channel stays under this come out unchanged but for the toe.
constexpr float kNeutralStartCompression = 0.8f - 0.04f;
constexpr float kNeutralDesaturation = 0.15f;

Color pbr_neutral(const Color& linear) {
    Color c{std::max(linear.r, 0.0f), std::max(linear.g, 0.0f), std::max(linear.b, 0.0f)};
    // The toe: a small offset, quadratic near black, that keeps dark colours saturated.
    const float x = std::min({c.r, c.g, c.b});
    const float offset = x < 0.08f ? x - 6.25f * x * x : 0.04f;
    c = c - Color(offset);
    const float peak = max_channel(c);
    if (peak < kNeutralStartCompression) return c;
    const float d = 1.0f - kNeutralStartCompression;
    const float new_peak = 1.0f - d * d / (peak + d - kNeutralStartCompression);
    c *= new_peak / peak;
    // Highlights desaturate towards white as they are compressed.
    const float g = 1.0f - 1.0f / (kNeutralDesaturation * (peak - new_peak) + 1.0f);
    return clamp01(c * (1.0f - g) + Color(new_peak) * g);
}

}  // namespace

std::optional<ToneCurve> parse_tone_curve(std::string_view name) {
    if (name == "none") return ToneCurve::None;
    if (name == "clamp") return ToneCurve::Clamp;
    if (name == "aces") return ToneCurve::Aces;
    if (name == "agx") return ToneCurve::Agx;
    if (name == "pbr-neutral") return ToneCurve::PbrNeutral;
    return std::nullopt;
}

std::string_view tone_curve_name(ToneCurve curve) {
    switch (curve) {
        case ToneCurve::None: return "none";
        case ToneCurve::Clamp: return "clamp";
        case ToneCurve::Aces: return "aces";
        case ToneCurve::Agx: return "agx";
        case ToneCurve::PbrNeutral: return "pbr-neutral";
    }
    return "none";
}

std::string_view tone_curve_names() { return "none, clamp, aces, agx or pbr-neutral"; }

Color apply_tone_curve(ToneCurve curve, const Color& linear) {
    switch (curve) {
        case ToneCurve::None: return linear;
        case ToneCurve::Clamp: return clamp_keeping_hue(linear);
        case ToneCurve::Aces: return aces(linear);
        case ToneCurve::Agx: return agx(linear);
        case ToneCurve::PbrNeutral: return pbr_neutral(linear);
    }
    return linear;
}

}  // namespace glint
