#include "glint/scene_format/motion_params.h"

#include "glint/scene_format/transform_params.h"

#include <fmt/format.h>

namespace glint {

namespace {

std::vector<MotionKey> timed_keys(const ParamValue& value, std::string_view what) {
    const std::string name(what);
    const ParamValue::Array& entries = value.as_array(name);
    if (entries.size() < 2)
        value.fail(name, "at least two keys { time = ..., transform = {...} } (one key does not move)");
    std::vector<MotionKey> keys;
    for (std::size_t i = 0; i < entries.size(); ++i) {
        const ParamTable& key = entries[i].as_table(fmt::format("{}[{}]", name, i));
        MotionKey k;
        k.time = key.require_number("time");
        if (!keys.empty() && !(k.time > keys.back().time))
            key.fail("time",
                     fmt::format("a time after the previous key's ({}): keys in increasing time", keys.back().time));
        k.transform =
            read_transform(key.require("transform", "the object's transform at this time"), key.name_of("transform"));
        key.reject_unknown_keys();
        keys.push_back(k);
    }
    return keys;
}

}  // namespace

std::optional<std::vector<MotionKey>> read_motion_keys(const ParamTable& t) {
    const ParamValue* motion = t.find("motion");
    const ParamValue* end = t.find("transform_end");
    if (motion) {
        if (end) t.fail("transform_end", "either transform_end or motion keys, not both");
        if (t.find("transform")) t.fail("transform", "no transform beside motion: its keys place the object");
        return timed_keys(*motion, t.name_of("motion"));
    }
    if (!end) return std::nullopt;
    // pbrt's convention: the transforms hold at times 0 and 1; the shutter picks the times seen.
    Transform start;
    if (const ParamValue* v = t.find("transform")) start = read_transform(*v, ValueName(t, "transform"));
    return std::vector<MotionKey>{{0.0f, start}, {1.0f, read_transform(*end, ValueName(t, "transform_end"))}};
}

}  // namespace glint
