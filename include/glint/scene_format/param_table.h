#pragma once
/// \file A parsed scene description: a tree of tables whose every key and value remembers
/// where it was written, read through typed getters that track which keys were used.
///
/// The TOML front end (toml_scene_loader.cpp, the only file that sees toml++) turns the file
/// into this tree; the scene builders read it. A key that no builder asked for is a mistake
/// (a typo must never pass silently), reported by reject_unknown_keys() with the keys the
/// builder did ask for as suggestions (pbrt-v4's ReportUnused, mitsuba3's "unreferenced
/// property").

#include "glint/diagnostics.h"
#include "glint/math/color.h"
#include "glint/math/vec2.h"
#include "glint/math/vec3.h"

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace glint {

class ParamTable;

/// The name of a value in messages ("objects[3].radius", "camera.position[1]"), spelt out
/// only when a message needs it: a scene of 100,000 objects reads a million values, and
/// building each one's name as a string cost more than reading it. It refers to what it was
/// made from, so it lives no longer than the call it is passed to.
class ValueName {
public:
    // Implicit: any string names a value.
    ValueName(std::string_view name) : text_(name) {}    // NOLINT
    ValueName(const std::string& name) : text_(name) {}  // NOLINT
    ValueName(const char* name) : text_(name) {}         // NOLINT
    /// `key` of `table`: "objects[3]" + "radius".
    ValueName(const ParamTable& table, std::string_view key) : text_(key), table_(&table) {}
    /// Element `index` of the array named `array`: "camera.position" + "[1]".
    ValueName(const ValueName& array, std::size_t index) : array_(&array), index_(index) {}

    [[nodiscard]] std::string str() const;

private:
    std::string_view text_;
    const ParamTable* table_ = nullptr;
    const ValueName* array_ = nullptr;
    std::size_t index_ = 0;
};

/// One value: a boolean, an integer, a floating-point number, a string, an array or a table.
class ParamValue {
public:
    using Array = std::vector<ParamValue>;
    using Storage = std::variant<bool, int64_t, double, std::string, Array, std::shared_ptr<const ParamTable>>;

    ParamValue(Storage data, SourceLocation where) : data_(std::move(data)), where_(std::move(where)) {}

    [[nodiscard]] const SourceLocation& where() const { return where_; }
    [[nodiscard]] bool is_number() const;
    [[nodiscard]] bool is_string() const { return std::holds_alternative<std::string>(data_); }
    [[nodiscard]] bool is_array() const { return std::holds_alternative<Array>(data_); }
    [[nodiscard]] bool is_table() const { return std::holds_alternative<std::shared_ptr<const ParamTable>>(data_); }
    /// The type in words for messages: "a string", "an array of 3", ...
    [[nodiscard]] std::string describe() const;

    // Typed reads. `what` names the value in the error (e.g. "objects[2].radius"); each
    // throws SceneError at the value's location saying what it is and what was expected.

    /// A finite number; integers are accepted.
    [[nodiscard]] float as_float(const ValueName& what) const;
    [[nodiscard]] int64_t as_integer(const ValueName& what) const;
    [[nodiscard]] bool as_bool(const ValueName& what) const;
    [[nodiscard]] const std::string& as_string(const ValueName& what) const;
    [[nodiscard]] const Array& as_array(const ValueName& what) const;
    [[nodiscard]] const ParamTable& as_table(const ValueName& what) const;
    /// [x, y, z] of finite numbers.
    [[nodiscard]] Vec3 as_vec3(const ValueName& what) const;
    /// [x, y] of finite numbers.
    [[nodiscard]] Vec2 as_vec2(const ValueName& what) const;
    /// [r, g, b], or one number for a grey; components must be finite and non-negative.
    [[nodiscard]] Color as_color(const ValueName& what) const;

    /// Throw SceneError at this value: "<what> is <this value>; expected <expected>".
    [[noreturn]] void fail(const ValueName& what, std::string_view expected) const;

private:
    Storage data_;
    SourceLocation where_;
};

/// A table: keys in file order, each with its location and a "was read" flag.
class ParamTable {
public:
    /// `path` names the table in messages ("camera", "objects[3]", "objects[3].transform").
    ParamTable(std::string path, SourceLocation where) : path_(std::move(path)), where_(std::move(where)) {}

    void add(std::string key, SourceLocation key_where, ParamValue value);
    /// Room for `count` keys (a loader that knows how many it will add).
    void reserve(std::size_t count) { entries_.reserve(count); }

    [[nodiscard]] const std::string& path() const { return path_; }
    [[nodiscard]] const SourceLocation& where() const { return where_; }
    /// Full name of a key for messages: "objects[3].radius" ("radius" at the top level).
    [[nodiscard]] std::string name_of(std::string_view key) const;

    /// The value of `key` (null if absent). Marks it read and records `key` as one this
    /// table understands (the suggestions for misspelt keys).
    [[nodiscard]] const ParamValue* find(std::string_view key) const;
    /// find() that throws "missing required key" (naming `expected`) when absent.
    [[nodiscard]] const ParamValue& require(std::string_view key, std::string_view expected) const;

    [[nodiscard]] float number(std::string_view key, float fallback) const;
    [[nodiscard]] float require_number(std::string_view key) const;
    [[nodiscard]] int64_t integer(std::string_view key, int64_t fallback) const;
    [[nodiscard]] bool boolean(std::string_view key, bool fallback) const;
    [[nodiscard]] std::string string(std::string_view key, std::string_view fallback) const;
    [[nodiscard]] const std::string& require_string(std::string_view key) const;
    [[nodiscard]] Vec3 vec3(std::string_view key, const Vec3& fallback) const;
    [[nodiscard]] Vec3 require_vec3(std::string_view key) const;
    [[nodiscard]] Vec2 vec2(std::string_view key, const Vec2& fallback) const;
    [[nodiscard]] Color color(std::string_view key, const Color& fallback) const;
    /// An array of [x, y, z] (empty when absent and not `required`).
    [[nodiscard]] std::vector<Vec3> vec3_list(std::string_view key, bool required) const;
    /// An array of [x, y] (empty when absent).
    [[nodiscard]] std::vector<Vec2> vec2_list(std::string_view key) const;
    /// A string that must be one of `choices` (or `fallback` when absent; an empty fallback
    /// makes the key required).
    [[nodiscard]] std::string choice(std::string_view key, std::span<const std::string_view> choices,
                                     std::string_view fallback) const;
    /// A sub-table, or null if absent.
    [[nodiscard]] const ParamTable* table(std::string_view key) const;
    /// Every element of an array of tables (`[[objects]]`); empty if absent.
    [[nodiscard]] std::vector<const ParamTable*> tables(std::string_view key) const;

    /// Throw at the value of `key` (at the table if absent): "<key> is <value>; expected <expected>".
    [[noreturn]] void fail(std::string_view key, std::string_view expected) const;
    /// Throw at the table itself with a free-form message.
    [[noreturn]] void fail_here(const std::string& message) const;

    /// Throw for the first key (in file order) that no getter asked for, suggesting the
    /// closest key that was asked for.
    void reject_unknown_keys() const;
    /// reject_unknown_keys() on this table and every table below it, depth first.
    void reject_unknown_keys_recursive() const;

private:
    struct Entry {
        std::string key;
        SourceLocation key_where;
        ParamValue value;
        mutable bool read = false;
    };
    [[nodiscard]] const Entry* entry(std::string_view key) const;

    std::string path_;
    SourceLocation where_;
    std::vector<Entry> entries_;
    mutable std::vector<std::string> known_keys_;
};

}  // namespace glint
