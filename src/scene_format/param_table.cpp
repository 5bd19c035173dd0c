#include "glint/scene_format/param_table.h"

#include "glint/scene_format/did_you_mean.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace glint {

namespace {

std::string join(const std::vector<std::string>& words) {
    std::string out;
    for (const std::string& w : words) out += (out.empty() ? "" : ", ") + w;
    return out;
}

}  // namespace

std::string ValueName::str() const {
    if (array_) return fmt::format("{}[{}]", array_->str(), index_);
    return table_ ? table_->name_of(text_) : std::string(text_);
}

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

void ParamValue::fail(const ValueName& what, std::string_view expected) const {
    throw_scene_error(where_, fmt::format("{} is {}; expected {}", what.str(), describe(), expected));
}

float ParamValue::as_float(const ValueName& what) const {
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

int64_t ParamValue::as_integer(const ValueName& what) const {
    if (const auto* i = std::get_if<int64_t>(&data_)) return *i;
    fail(what, "an integer");
}

bool ParamValue::as_bool(const ValueName& what) const {
    if (const auto* b = std::get_if<bool>(&data_)) return *b;
    fail(what, "true or false");
}

const std::string& ParamValue::as_string(const ValueName& what) const {
    if (const auto* s = std::get_if<std::string>(&data_)) return *s;
    fail(what, "a string");
}

const ParamValue::Array& ParamValue::as_array(const ValueName& what) const {
    if (const auto* a = std::get_if<Array>(&data_)) return *a;
    fail(what, "an array");
}

const ParamTable& ParamValue::as_table(const ValueName& what) const {
    if (const auto* t = std::get_if<std::shared_ptr<const ParamTable>>(&data_)) return **t;
    fail(what, "a table");
}

Vec3 ParamValue::as_vec3(const ValueName& what) const {
    const auto* a = std::get_if<Array>(&data_);
    if (!a || a->size() != 3) fail(what, "[x, y, z], an array of 3 numbers");
    return {(*a)[0].as_float(ValueName(what, 0)), (*a)[1].as_float(ValueName(what, 1)),
            (*a)[2].as_float(ValueName(what, 2))};
}

Vec2 ParamValue::as_vec2(const ValueName& what) const {
    const auto* a = std::get_if<Array>(&data_);
    if (!a || a->size() != 2) fail(what, "[x, y], an array of 2 numbers");
    return {(*a)[0].as_float(ValueName(what, 0)), (*a)[1].as_float(ValueName(what, 1))};
}

Color ParamValue::as_color(const ValueName& what) const {
    constexpr std::string_view expected = "a colour: [r, g, b] of non-negative numbers, or one number for a grey";
    Color c;
    if (is_number()) {
        c = Color(as_float(what));
    } else {
        const auto* a = std::get_if<Array>(&data_);
        if (!a || a->size() != 3) fail(what, expected);
        c = Color((*a)[0].as_float(ValueName(what, 0)), (*a)[1].as_float(ValueName(what, 1)),
                  (*a)[2].as_float(ValueName(what, 2)));
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
    return v ? v->as_float(ValueName(*this, key)) : fallback;
}

float ParamTable::require_number(std::string_view key) const {
    return require(key, "a number").as_float(ValueName(*this, key));
}

int64_t ParamTable::integer(std::string_view key, int64_t fallback) const {
    const ParamValue* v = find(key);
    return v ? v->as_integer(ValueName(*this, key)) : fallback;
}

bool ParamTable::boolean(std::string_view key, bool fallback) const {
    const ParamValue* v = find(key);
    return v ? v->as_bool(ValueName(*this, key)) : fallback;
}

std::string ParamTable::string(std::string_view key, std::string_view fallback) const {
    const ParamValue* v = find(key);
    return v ? v->as_string(ValueName(*this, key)) : std::string(fallback);
}

const std::string& ParamTable::require_string(std::string_view key) const {
    return require(key, "a string").as_string(ValueName(*this, key));
}

Vec3 ParamTable::vec3(std::string_view key, const Vec3& fallback) const {
    const ParamValue* v = find(key);
    return v ? v->as_vec3(ValueName(*this, key)) : fallback;
}

Vec3 ParamTable::require_vec3(std::string_view key) const {
    return require(key, "[x, y, z]").as_vec3(ValueName(*this, key));
}

Vec2 ParamTable::vec2(std::string_view key, const Vec2& fallback) const {
    const ParamValue* v = find(key);
    return v ? v->as_vec2(ValueName(*this, key)) : fallback;
}

Color ParamTable::color(std::string_view key, const Color& fallback) const {
    const ParamValue* v = find(key);
    return v ? v->as_color(ValueName(*this, key)) : fallback;
}

std::vector<Vec3> ParamTable::vec3_list(std::string_view key, bool required) const {
    std::vector<Vec3> out;
    const ParamValue* v = required ? &require(key, "an array of [x, y, z]") : find(key);
    if (!v) return out;
    const ValueName name(*this, key);
    const auto& a = v->as_array(name);
    for (std::size_t i = 0; i < a.size(); ++i) out.push_back(a[i].as_vec3(ValueName(name, i)));
    return out;
}

std::vector<Vec2> ParamTable::vec2_list(std::string_view key) const {
    std::vector<Vec2> out;
    if (const ParamValue* v = find(key)) {
        const ValueName name(*this, key);
        const auto& a = v->as_array(name);
        for (std::size_t i = 0; i < a.size(); ++i) out.push_back(a[i].as_vec2(ValueName(name, i)));
    }
    return out;
}

std::string ParamTable::choice(std::string_view key, std::span<const std::string_view> choices,
                               std::string_view fallback) const {
    // The list of choices is spelt out only for a message: this runs once per object.
    const auto one_of = [&] {
        std::string list;
        for (const std::string_view c : choices) list += fmt::format("{}\"{}\"", list.empty() ? "" : ", ", c);
        return "one of " + list;
    };
    const ParamValue* v = find(key);
    if (!v) {
        if (fallback.empty()) static_cast<void>(require(key, one_of()));
        return std::string(fallback);
    }
    const std::string& s = v->as_string(ValueName(*this, key));
    if (std::find(choices.begin(), choices.end(), s) == choices.end())
        v->fail(name_of(key), one_of() + did_you_mean(s, std::vector<std::string>(choices.begin(), choices.end())));
    return s;
}

const ParamTable* ParamTable::table(std::string_view key) const {
    const ParamValue* v = find(key);
    return v ? &v->as_table(ValueName(*this, key)) : nullptr;
}

std::vector<const ParamTable*> ParamTable::tables(std::string_view key) const {
    std::vector<const ParamTable*> out;
    const ParamValue* v = find(key);
    if (!v) return out;
    const ValueName name(*this, key);
    if (!v->is_array()) v->fail(name, fmt::format("an array of tables, written [[{}]]", key));
    const auto& elements = v->as_array(name);
    for (std::size_t i = 0; i < elements.size(); ++i) out.push_back(&elements[i].as_table(ValueName(name, i)));
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
    // Every key was read: the names asked for, kept only to suggest one for a misspelt key,
    // are not needed again (a later call finds nothing unread). 100,000 objects would
    // otherwise keep tens of megabytes of them.
    std::vector<std::string>().swap(known_keys_);
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
