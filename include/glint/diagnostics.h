#pragma once
/// \file What every loader reports a mistake with: a place in a file and SceneError.
/// A leaf header (no other Glint includes), so that any low-level reader can throw
/// without depending on the loaders above it (pbrt-v4's util/error.h `FileLoc`).

#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>

namespace glint {

/// A problem in an input file. what() reads `file:line:column: what is wrong and what was
/// expected` (line and column where the format knows them).
class SceneError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// Where something was written: file name, 1-based line and column (0 = unknown).
struct SourceLocation {
    std::shared_ptr<const std::string> file;
    uint32_t line = 0;
    uint32_t column = 0;

    /// "file:line:column", "file:line" when the column is unknown (a Python call site), or
    /// just "file" when the line is unknown too.
    [[nodiscard]] std::string to_string() const;
};

/// A SceneError that also keeps its location apart, so that the loader, which has the
/// text, can show the offending line.
class LocatedSceneError : public SceneError {
public:
    LocatedSceneError(SourceLocation where, const std::string& message)
        : SceneError(where.to_string() + ": " + message), where_(std::move(where)) {}
    [[nodiscard]] const SourceLocation& where() const { return where_; }

private:
    SourceLocation where_;
};

/// Throw LocatedSceneError: what() reads "file:line:column: message".
[[noreturn]] void throw_scene_error(const SourceLocation& where, const std::string& message);

}  // namespace glint
