#include "glint/scene_format/param_table.h"

#include "glint/scene_format/did_you_mean.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace glint {

namespace {

std::string element_name(std::string_view what, std::size_t index) { return fmt::format("{}[{}]", what, index); }

std::string join(const std::vector<std::string>& words) {
    std::string out;
    for (const std::string& w : words) out += (out.empty() ? "" : ", ") + w;
    return out;
}

}  // namespace

bool ParamValue::is_number() const {
    return std::holds_alternative<int64_t>(data_) || std::holds_alternative<double>(data_);
}

std::string ParamValue::describe() const {
    struct Describe {
        std::string operator()(bool b) const { return b ? "true" : "false"; }
        std::string operator()(int64_t i) const { return std::to_string(i); }
        std::string operator()(double d) const { return fmt::format("{}", d); }
        std::string operator()(const std::string& s) const {
            return s.size() <= 40 ? fmt::format("the string \"{}\"", s)
                                  : fmt::format("a string of {} characters", s.size());
        }
        std::string operator()(const Array& a) const { return fmt::format("an array of {}", a.size()); }
        std::string operator()(const std::shared_ptr<const ParamTable>&) const { return "a table"; }
    };
    return std::visit(Describe{}, data_);
}

void ParamValue::fail(std::string_view what, std::string_view expected) const {
    throw_scene_error(where_, fmt::format("{} is {}; expected {}", what, describe(), expected));
}

float ParamValue::as_float(std::string_view what) const {
    double d = 0.0;
    if (const auto* i = std::get_if<int64_t>(&data_)) {
        d = double(*i);
    } else if (const auto* f = std::get_if<double>(&data_)) {
        d = *f;
    } else {
        fail(what, "a number");
    }
    // TOML allows nan and inf; no scene quantity can be either, and float must hold it.
    if (!std::isfinite(d) || std::abs(d) > 3.0e38) fail(what, "a finite number");
    return static_cast<float>(d);
}

int64_t ParamValue::as_integer(std::string_view what) const {
    if (const auto* i = std::get_if<int64_t>(&data_)) return *i;
    fail(what, "an integer");
}

bool ParamValue::as_bool(std::string_view what) const {
    if (const auto* b = std::get_if<bool>(&data_)) return *b;
    fail(what, "true or false");
}

const std::string& ParamValue::as_string(std::string_view what) const {
    if (const auto* s = std::get_if<std::string>(&data_)) return *s;
    fail(what, "a string");
}

const ParamValue::Array& ParamValue::as_array(std::string_view what) const {
    if (const auto* a = std::get_if<Array>(&data_)) return *a;
    fail(what, "an array");
}

const ParamTable& ParamValue::as_table(std::string_view what) const {
    if (const auto* t = std::get_if<std::shared_ptr<const ParamTable>>(&data_)) return **t;
    fail(what, "a table");
}

Vec3 ParamValue::as_vec3(std::string_view what) const {
    const auto* a = std::get_if<Array>(&data_);
    if (!a || a->size() != 3) fail(what, "[x, y, z], an array of 3 numbers");
    return {(*a)[0].as_float(element_name(what, 0)), (*a)[1].as_float(element_name(what, 1)),
            (*a)[2].as_float(element_name(what, 2))};
}

Vec2 ParamValue::as_vec2(std::string_view what) const {
    const auto* a = std::get_if<Array>(&data_);
    if (!a || a->size() != 2) fail(what, "[x, y], an array of 2 numbers");
    return {(*a)[0].as_float(element_name(what, 0)), (*a)[1].as_float(element_name(what, 1))};
}

Color ParamValue::as_color(std::string_view what) const {
    constexpr std::string_view expected = "a colour: [r, g, b] of non-negative numbers, or one number for a grey";
    Color c;
    if (is_number()) {
        c = Color(as_float(what));
    } else {
        const auto* a = std::get_if<Array>(&data_);
        if (!a || a->size() != 3) fail(what, expected);
        c = Color((*a)[0].as_float(element_name(what, 0)), (*a)[1].as_float(element_name(what, 1)),
                  (*a)[2].as_float(element_name(what, 2)));
    }
    if (c.r < 0.0f || c.g < 0.0f || c.b < 0.0f) fail(what, expected);
    return c;
}

void ParamTable::add(std::string key, SourceLocation key_where, ParamValue value) {
    entries_.push_back(Entry{std::move(key), std::move(key_where), std::move(value)});
}

std::string ParamTable::name_of(std::string_view key) const {
    return path_.empty() ? std::string(key) : path_ + "." + std::string(key);
}

const ParamTable::Entry* ParamTable::entry(std::string_view key) const {
    for (const Entry& e : entries_)
        if (e.key == key) return &e;
    return nullptr;
}

const ParamValue* ParamTable::find(std::string_view key) const {
    if (std::find(known_keys_.begin(), known_keys_.end(), key) == known_keys_.end()) known_keys_.emplace_back(key);
    const Entry* e = entry(key);
    if (!e) return nullptr;
    e->read = true;
    return &e->value;
}

const ParamValue& ParamTable::require(std::string_view key, std::string_view expected) const {
    if (const ParamValue* v = find(key)) return *v;
    // A misspelling of the missing key is the likeliest cause: point at the misspelling.
    std::vector<std::string> unread;
    for (const Entry& e : entries_)
        if (!e.read) unread.push_back(e.key);
    const std::string where = path_.empty() ? "at the top level" : "in " + path_;
    if (const auto typo = closest_match(key, unread))
        throw_scene_error(entry(*typo)->key_where, fmt::format("unknown key '{}' {} (did you mean '{}'?); '{}' is "
                                                               "required: expected {}",
                                                               *typo, where, key, key, expected));
    fail_here(fmt::format("missing key '{}' {}; expected {}", key, where, expected));
}

float ParamTable::number(std::string_view key, float fallback) const {
    const ParamValue* v = find(key);
    return v ? v->as_float(name_of(key)) : fallback;
}

float ParamTable::require_number(std::string_view key) const { return require(key, "a number").as_float(name_of(key)); }

int64_t ParamTable::integer(std::string_view key, int64_t fallback) const {
    const ParamValue* v = find(key);
    return v ? v->as_integer(name_of(key)) : fallback;
}

bool ParamTable::boolean(std::string_view key, bool fallback) const {
    const ParamValue* v = find(key);
    return v ? v->as_bool(name_of(key)) : fallback;
}

std::string ParamTable::string(std::string_view key, std::string_view fallback) const {
    const ParamValue* v = find(key);
    return v ? v->as_string(name_of(key)) : std::string(fallback);
}

const std::string& ParamTable::require_string(std::string_view key) const {
    return require(key, "a string").as_string(name_of(key));
}

Vec3 ParamTable::vec3(std::string_view key, const Vec3& fallback) const {
    const ParamValue* v = find(key);
    return v ? v->as_vec3(name_of(key)) : fallback;
}

Vec3 ParamTable::require_vec3(std::string_view key) const { return require(key, "[x, y, z]").as_vec3(name_of(key)); }

Vec2 ParamTable::vec2(std::string_view key, const Vec2& fallback) const {
    const ParamValue* v = find(key);
    return v ? v->as_vec2(name_of(key)) : fallback;
}

Color ParamTable::color(std::string_view key, const Color& fallback) const {
    const ParamValue* v = find(key);
    return v ? v->as_color(name_of(key)) : fallback;
}

std::vector<Vec3> ParamTable::vec3_list(std::string_view key, bool required) const {
    std::vector<Vec3> out;
    const ParamValue* v = required ? &require(key, "an array of [x, y, z]") : find(key);
    if (!v) return out;
    const auto& a = v->as_array(name_of(key));
    for (std::size_t i = 0; i < a.size(); ++i) out.push_back(a[i].as_vec3(element_name(name_of(key), i)));
    return out;
}

std::vector<Vec2> ParamTable::vec2_list(std::string_view key) const {
    std::vector<Vec2> out;
    if (const ParamValue* v = find(key)) {
        const auto& a = v->as_array(name_of(key));
        for (std::size_t i = 0; i < a.size(); ++i) out.push_back(a[i].as_vec2(element_name(name_of(key), i)));
    }
    return out;
}

std::string ParamTable::choice(std::string_view key, std::span<const std::string_view> choices,
                               std::string_view fallback) const {
    std::vector<std::string> names(choices.begin(), choices.end());
    std::string list;
    for (const std::string& n : names) list += (list.empty() ? "\"" : ", \"") + n + "\"";
    const ParamValue* v = fallback.empty() ? &require(key, "one of " + list) : find(key);
    if (!v) return std::string(fallback);
    const std::string& s = v->as_string(name_of(key));
    if (std::find(names.begin(), names.end(), s) == names.end())
        v->fail(name_of(key), "one of " + list + did_you_mean(s, names));
    return s;
}

const ParamTable* ParamTable::table(std::string_view key) const {
    const ParamValue* v = find(key);
    return v ? &v->as_table(name_of(key)) : nullptr;
}

std::vector<const ParamTable*> ParamTable::tables(std::string_view key) const {
    std::vector<const ParamTable*> out;
    const ParamValue* v = find(key);
    if (!v) return out;
    const std::string name = name_of(key);
    if (!v->is_array()) v->fail(name, fmt::format("an array of tables, written [[{}]]", key));
    const auto& elements = v->as_array(name);
    for (std::size_t i = 0; i < elements.size(); ++i) out.push_back(&elements[i].as_table(element_name(name, i)));
    return out;
}

void ParamTable::fail(std::string_view key, std::string_view expected) const {
    if (const Entry* e = entry(key)) e->value.fail(name_of(key), expected);
    fail_here(fmt::format("{} is missing; expected {}", name_of(key), expected));
}

void ParamTable::fail_here(const std::string& message) const { throw_scene_error(where_, message); }

void ParamTable::reject_unknown_keys() const {
    for (const Entry& e : entries_) {
        if (e.read) continue;
        std::vector<std::string> known = known_keys_;
        std::sort(known.begin(), known.end());
        const std::string where = path_.empty() ? "at the top level" : "in " + path_;
        const std::string expected = known.empty() ? "no keys here" : "one of: " + join(known);
        throw_scene_error(e.key_where, fmt::format("unknown key '{}' {}{}; expected {}", e.key, where,
                                                   did_you_mean(e.key, known), expected));
    }
}

void ParamTable::reject_unknown_keys_recursive() const {
    reject_unknown_keys();
    const auto visit = [](const auto& self, const ParamValue& value) -> void {
        if (value.is_table()) {
            value.as_table("").reject_unknown_keys_recursive();
        } else if (value.is_array()) {
            for (const ParamValue& element : value.as_array("")) self(self, element);
        }
    };
    for (const Entry& e : entries_) visit(visit, e.value);
}

}  // namespace glint
