#include "gltf_animation.h"

#include "glint/diagnostics.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace glint::gltf {

namespace {

constexpr int kFloat = 5126;

bool is_normalized_integer(int component_type) {
    return component_type == 5120 || component_type == 5121 || component_type == 5122 || component_type == 5123;
}

std::string indexed(const std::string& array, std::size_t i) { return array + "[" + std::to_string(i) + "]"; }

/// `object[key]`, or SceneError "file: where.key is missing".
const nlohmann::json& required(const Document& doc, const nlohmann::json& object, const char* key,
                               const std::string& where) {
    if (!object.is_object() || !object.contains(key)) fail(doc.path, where + "." + key + " is missing");
    return object.at(key);
}

/// Accessor `index`, named `where` (its JSON path) in errors, as floats: of `type` with
/// FLOAT components, or, where `normalized_ok`, normalized integers (glTF 2.0 §3.11: the
/// accessor types of animation samplers; rotations may be normalized integers).
std::vector<float> read_accessor(const Document& doc, const std::string& where, const nlohmann::json& index_json,
                                 const char* type, int components, bool normalized_ok) {
    const auto index = integer<std::size_t>(index_json);
    const std::string accessor_name = "accessor " + std::to_string(index);
    const std::size_t count = array_size(doc.json, "accessors");
    if (index >= count)
        fail(doc.path, where + ": " + accessor_name + " does not exist (the file has " + std::to_string(count) + ")");
    const auto& accessor = doc.json.at("accessors").at(index);
    const std::string actual = accessor.value("type", "");
    if (actual != type)
        fail(doc.path, where + ": " + accessor_name + " is " + (actual.empty() ? "untyped" : actual) + " (expected " +
                           type + ")");
    const int component_type =
        integer<int>(required(doc, accessor, "componentType", "accessors[" + std::to_string(index) + "]"));
    const bool normalized =
        normalized_ok && accessor.value("normalized", false) && is_normalized_integer(component_type);
    if (component_type != kFloat && !normalized)
        fail(doc.path, where + ": " + accessor_name + " has componentType " + std::to_string(component_type) +
                           " (expected 5126, FLOAT" + (normalized_ok ? ", or a normalized 8- or 16-bit integer" : "") +
                           ")");
    try {
        return read_floats(doc, index, components);
    } catch (const SceneError& e) {
        // "file: accessor 3 lies outside its buffer view", said of the JSON path that uses it.
        const std::string prefix = doc.path.string() + ": ";
        std::string what = e.what();
        if (what.starts_with(prefix)) what.erase(0, prefix.size());
        fail(doc.path, where + ": " + what);
    }
}

/// The rotation (x, y, z, w), as glTF stores it, made unit length; the identity for a
/// zero quaternion (a node's rest rotation is not checked).
Quaternion unit_quaternion(const double v[4]) {
    const double n = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2] + v[3] * v[3]);
    if (!(n > 0.0) || !std::isfinite(n)) return {};
    return {v[3] / n, v[0] / n, v[1] / n, v[2] / n};
}

}  // namespace

NodeAnimation::NodeAnimation(const Document& doc, ImportNotes& notes) {
    const auto& json = doc.json;
    const std::size_t node_count = array_size(json, "nodes");
    animations_ = array_size(json, "animations");
    if (animations_ == 0) return;  // nothing read: such a file loads as without a shutter
    rest_.resize(node_count);
    animated_.assign(node_count, false);
    for (std::size_t n = 0; n < node_count; ++n) rest_[n].matrix = node_matrix(json.at("nodes").at(n));
    for (std::size_t a = 0; a < animations_; ++a) {
        const std::string at = indexed("animations", a);
        const auto& animation = json.at("animations").at(a);
        const auto& channels = required(doc, animation, "channels", at);
        const auto& samplers = required(doc, animation, "samplers", at);
        for (std::size_t c = 0; c < channels.size(); ++c) {
            const std::string where = at + "." + indexed("channels", c);
            const auto& channel = channels.at(c);
            const auto sampler = integer<std::size_t>(required(doc, channel, "sampler", where));
            if (sampler >= samplers.size())
                fail(doc.path, where + ".sampler: sampler " + std::to_string(sampler) + " does not exist (" + at +
                                   " has " + std::to_string(samplers.size()) + ")");
            const auto& target = required(doc, channel, "target", where);
            const std::string path = required(doc, target, "path", where + ".target").get<std::string>();
            if (!target.contains("node")) {  // §3.11: extensions may target something else
                notes.ignored("animation channel without a target node", "");
                continue;
            }
            const auto node = integer<std::size_t>(target.at("node"));
            if (node >= node_count)
                fail(doc.path, where + ".target.node: node " + std::to_string(node) + " does not exist (the file has " +
                                   std::to_string(node_count) + " nodes)");
            Channel kept;
            kept.node = node;
            if (path == "translation") {
                kept.path = Path::Translation;
            } else if (path == "rotation") {
                kept.path = Path::Rotation;
            } else if (path == "scale") {
                kept.path = Path::Scale;
            } else {
                notes.ignored(path == "weights" ? "animation of morph target weights (base shapes drawn)"
                                                : "animation channel path '" + path + "'",
                              "");
                continue;
            }
            const auto& node_json = json.at("nodes").at(node);
            if (node_json.contains("matrix"))
                fail(doc.path, where + ".target.node: node " + std::to_string(node) +
                                   " has a matrix (expected translation, rotation and scale: glTF 2.0 §3.5.3 animates "
                                   "only those)");
            kept.curve = read_curve(doc, samplers.at(sampler), at + "." + indexed("samplers", sampler), kept.path);
            channels_.push_back(std::move(kept));
            if (!animated_[node]) {
                animated_[node] = true;
                Rest& rest = rest_[node];
                if (node_json.contains("translation"))
                    for (int i = 0; i < 3; ++i)
                        rest.translation[i] = node_json.at("translation").at(std::size_t(i)).get<float>();
                if (node_json.contains("scale"))
                    for (int i = 0; i < 3; ++i) rest.scale[i] = node_json.at("scale").at(std::size_t(i)).get<float>();
                if (node_json.contains("rotation"))
                    for (int i = 0; i < 4; ++i)
                        rest.rotation[i] = node_json.at("rotation").at(std::size_t(i)).get<float>();
            }
        }
    }
}

NodeAnimation::Curve NodeAnimation::read_curve(const Document& doc, const nlohmann::json& sampler,
                                               const std::string& where, Path path) {
    Curve curve;
    const std::string interpolation = sampler.is_object() ? sampler.value("interpolation", "LINEAR") : "LINEAR";
    if (interpolation == "STEP") {
        curve.interpolation = Interpolation::Step;
    } else if (interpolation == "CUBICSPLINE") {
        curve.interpolation = Interpolation::CubicSpline;
    } else if (interpolation != "LINEAR") {
        fail(doc.path, where + ".interpolation: '" + interpolation + "' (expected LINEAR, STEP or CUBICSPLINE)");
    }
    const bool cubic = curve.interpolation == Interpolation::CubicSpline;
    curve.times = read_accessor(doc, where + ".input", required(doc, sampler, "input", where), "SCALAR", 1, false);
    // animation.sampler.schema.json: key times strictly increasing.
    if (curve.times.size() < (cubic ? 2u : 1u))
        fail(doc.path, where + ".input: " + std::to_string(curve.times.size()) + " key time(s) (expected at least " +
                           (cubic ? "two for CUBICSPLINE" : "one") + ")");
    for (std::size_t i = 0; i < curve.times.size(); ++i) {
        if (!std::isfinite(curve.times[i]))
            fail(doc.path, where + ".input: key time " + std::to_string(i) + " is not finite");
        if (i > 0 && !(curve.times[i] > curve.times[i - 1]))
            fail(doc.path, where + ".input: key time " + std::to_string(i) + " (" + std::to_string(curve.times[i]) +
                               ") does not come after key time " + std::to_string(i - 1) + " (" +
                               std::to_string(curve.times[i - 1]) + "): expected strictly increasing times");
    }
    const bool rotation = path == Path::Rotation;
    curve.components = rotation ? 4 : 3;
    curve.values = read_accessor(doc, where + ".output", required(doc, sampler, "output", where),
                                 rotation ? "VEC4" : "VEC3", int(curve.components), rotation);
    const std::size_t elements = curve.values.size() / curve.components, per_key = cubic ? 3 : 1;
    if (elements != curve.times.size() * per_key)
        fail(doc.path, where + ".output: " + std::to_string(elements) + " elements for " +
                           std::to_string(curve.times.size()) + " key times (expected " +
                           std::to_string(curve.times.size() * per_key) +
                           (cubic ? ": in-tangent, value and out-tangent per key" : ": one value per key") + ")");
    for (std::size_t e = 0; e < elements; ++e) {
        double norm2 = 0.0;
        for (std::size_t c = 0; c < curve.components; ++c) {
            const float v = curve.values[e * curve.components + c];
            if (!std::isfinite(v))
                fail(doc.path, where + ".output: element " + std::to_string(e) +
                                   " is not finite (glTF 2.0 §3.6.2: no NaN or infinity)");
            norm2 += double(v) * double(v);
        }
        // A key value (not a tangent) of a rotation must be a rotation.
        if (rotation && (!cubic || e % 3 == 1) && !(norm2 > 1e-12))
            fail(doc.path,
                 where + ".output: element " + std::to_string(e) + " is a zero quaternion (expected a rotation)");
    }
    return curve;
}

std::array<double, 4> NodeAnimation::evaluate(const Curve& curve, bool rotation, float time) {
    const std::size_t n = curve.components, stride = curve.interpolation == Interpolation::CubicSpline ? 3 : 1,
                      value_at = stride == 3 ? 1 : 0;
    // Element `which` (0 in-tangent, 1 value, 2 out-tangent of a spline) of key k.
    auto element = [&](std::size_t k, std::size_t which) {
        std::array<double, 4> v{};
        for (std::size_t c = 0; c < n; ++c) v[c] = curve.values[(k * stride + which) * n + c];
        return v;
    };
    auto finish = [&](std::array<double, 4> v) {
        if (!rotation) return v;
        const Quaternion q = unit_quaternion(v.data());
        return std::array<double, 4>{q.x, q.y, q.z, q.w};
    };
    const std::vector<float>& t = curve.times;
    // Before the first key and after the last the end values hold (§3.11).
    if (time <= t.front()) return finish(element(0, value_at));
    if (time >= t.back()) return finish(element(t.size() - 1, value_at));
    const std::size_t k = std::size_t(std::upper_bound(t.begin(), t.end(), time) - t.begin()) - 1;
    const double td = double(t[k + 1]) - double(t[k]), s = (double(time) - double(t[k])) / td;
    switch (curve.interpolation) {
        case Interpolation::Step:
            return finish(element(k, 0));
        case Interpolation::Linear: {
            const auto a = element(k, 0), b = element(k + 1, 0);
            if (rotation) {  // Appendix C: slerp along the shorter arc
                const Quaternion q = slerp(unit_quaternion(a.data()), unit_quaternion(b.data()), s);
                return {q.x, q.y, q.z, q.w};
            }
            return {(1.0 - s) * a[0] + s * b[0], (1.0 - s) * a[1] + s * b[1], (1.0 - s) * a[2] + s * b[2], 0.0};
        }
        case Interpolation::CubicSpline: {
            // Appendix C: the cubic Hermite spline through v_k and v_k+1 with the out-tangent
            // b_k and in-tangent a_k+1, both scaled by the key interval t_d.
            const auto v0 = element(k, 1), b0 = element(k, 2), a1 = element(k + 1, 0), v1 = element(k + 1, 1);
            const double s2 = s * s, s3 = s2 * s;
            const double h00 = 2 * s3 - 3 * s2 + 1, h10 = td * (s3 - 2 * s2 + s), h01 = -2 * s3 + 3 * s2,
                         h11 = td * (s3 - s2);
            std::array<double, 4> p{};
            for (std::size_t c = 0; c < n; ++c) p[c] = h00 * v0[c] + h10 * b0[c] + h01 * v1[c] + h11 * a1[c];
            // A spline between rotations can pass through zero: then the key's value holds.
            if (rotation && !(p[0] * p[0] + p[1] * p[1] + p[2] * p[2] + p[3] * p[3] > 1e-12)) return finish(v0);
            return finish(p);
        }
    }
    return {};
}

std::vector<float> NodeAnimation::key_times(bool step_only) const {
    std::vector<float> times;
    for (const Channel& channel : channels_)
        if (!step_only || channel.curve.interpolation == Interpolation::Step)
            times.insert(times.end(), channel.curve.times.begin(), channel.curve.times.end());
    std::sort(times.begin(), times.end());
    times.erase(std::unique(times.begin(), times.end()), times.end());
    return times;
}

NodePose NodeAnimation::pose(float time) const {
    NodePose pose;
    const std::size_t node_count = rest_.size();
    pose.local.resize(node_count);
    pose.rotation.resize(node_count);
    std::vector<Rest> now = rest_;
    for (const Channel& channel : channels_) {
        const auto v = evaluate(channel.curve, channel.path == Path::Rotation, time);
        Rest& r = now[channel.node];
        switch (channel.path) {
            case Path::Translation:
                r.translation = {float(v[0]), float(v[1]), float(v[2])};
                break;
            case Path::Rotation:
                for (int i = 0; i < 4; ++i) r.rotation[i] = float(v[std::size_t(i)]);
                break;
            case Path::Scale:
                r.scale = {float(v[0]), float(v[1]), float(v[2])};
                break;
        }
    }
    for (std::size_t i = 0; i < node_count; ++i) {
        const Rest& r = now[i];
        pose.local[i] = animated_[i] ? trs_matrix(r.translation, r.rotation, r.scale) : r.matrix;
        const double q[4] = {r.rotation[0], r.rotation[1], r.rotation[2], r.rotation[3]};
        pose.rotation[i] = animated_[i] ? unit_quaternion(q) : Quaternion{};
    }
    return pose;
}

}  // namespace glint::gltf
