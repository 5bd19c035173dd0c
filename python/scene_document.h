#pragma once
// A scene described in Python (glint.Scene's set_* and add_* calls, glint.load_dict): the
// tree of tables a TOML file is parsed into, its values copied when given (a list changed
// afterwards changes nothing), each remembering the line of Python that gave it. The scene
// builder reads it as a ParamTable, as it reads a TOML file: a scene built in code has the
// same keys, the same defaults and the same messages, which name that line.

#include "glint/diagnostics.h"
#include "glint/scene_format/param_table.h"

#include <pybind11/pybind11.h>

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

namespace glint::python {

namespace py = pybind11;

struct DocumentValue;
using DocumentArray = std::vector<DocumentValue>;
/// Keys in the order given.
using DocumentTable = std::vector<std::pair<std::string, DocumentValue>>;

struct DocumentValue {
    std::variant<bool, int64_t, double, std::string, DocumentArray, DocumentTable> data;
    SourceLocation where;
};

/// The line of Python running now (the caller of the module's function), as "file:line".
[[nodiscard]] SourceLocation python_call_site();

/// A copy of `value`: bool, int, float, str, a path, a sequence (list, tuple), a dict with
/// string keys, or NumPy's arrays and scalars. `name` names it in the TypeError for
/// anything else ("objects[2].center").
[[nodiscard]] DocumentValue from_python(py::handle value, const std::string& name, const SourceLocation& where);

/// The keywords of one call (`center=(0, 1, 0), radius=2`) as a table named `name`.
[[nodiscard]] DocumentTable table_from_keywords(const py::kwargs& keywords, const std::string& name,
                                                const SourceLocation& where);

/// Section `section` of `root` ("camera") takes the keys of `keys`: a key given again
/// replaces its value, a new one is added.
void merge_into_section(DocumentTable& root, std::string_view section, DocumentTable keys, const SourceLocation& where);

/// One more table for the array of tables `section` of `root` ("objects").
void append_to_section(DocumentTable& root, std::string_view section, DocumentTable element,
                       const SourceLocation& where);

/// The number of tables in the array `section` of `root` (0 if it has none).
[[nodiscard]] std::size_t section_size(const DocumentTable& root, std::string_view section);

/// The document as the scene builder reads it: a fresh tree (its keys not yet read).
[[nodiscard]] std::shared_ptr<const ParamTable> to_param_table(const DocumentTable& root);

/// The document in plain Python (dicts, lists, numbers, strings), as tomllib reads a file.
[[nodiscard]] py::dict to_python(const DocumentTable& root);

}  // namespace glint::python
