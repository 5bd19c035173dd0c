#include "scene_document.h"

#include <pybind11/numpy.h>

#include <algorithm>

namespace glint::python {

namespace {

std::string key_name(const std::string& table, const std::string& key) {
    return table.empty() ? key : table + "." + key;
}

std::string type_name(py::handle value) { return py::str(py::type::handle_of(value).attr("__name__")); }

std::vector<std::pair<std::string, DocumentValue>>::iterator find_key(DocumentTable& table, std::string_view key) {
    return std::find_if(table.begin(), table.end(), [&](const auto& entry) { return entry.first == key; });
}

ParamValue to_param_value(const DocumentValue& value, const std::string& name);

std::shared_ptr<const ParamTable> to_param_table(const DocumentTable& table, const std::string& name,
                                                 const SourceLocation& where) {
    auto out = std::make_shared<ParamTable>(name, where);
    out->reserve(table.size());
    for (const auto& [key, value] : table) out->add(key, value.where, to_param_value(value, key_name(name, key)));
    return out;
}

/// The TOML front end's naming (toml_scene_loader.cpp): tables and arrays inside an array
/// are named by their index; numbers and strings are named by the reader they are given to.
ParamValue to_param_value(const DocumentValue& value, const std::string& name) {
    struct Convert {
        const DocumentValue& value;
        const std::string& name;
        ParamValue::Storage operator()(bool b) const { return b; }
        ParamValue::Storage operator()(int64_t i) const { return i; }
        ParamValue::Storage operator()(double d) const { return d; }
        ParamValue::Storage operator()(const std::string& s) const { return s; }
        ParamValue::Storage operator()(const DocumentArray& array) const {
            ParamValue::Array elements;
            elements.reserve(array.size());
            for (std::size_t i = 0; i < array.size(); ++i) {
                const bool nested = !std::holds_alternative<bool>(array[i].data) &&
                                    !std::holds_alternative<int64_t>(array[i].data) &&
                                    !std::holds_alternative<double>(array[i].data) &&
                                    !std::holds_alternative<std::string>(array[i].data);
                elements.push_back(to_param_value(array[i], nested ? name + "[" + std::to_string(i) + "]" : name));
            }
            return elements;
        }
        ParamValue::Storage operator()(const DocumentTable& table) const {
            return to_param_table(table, name, value.where);
        }
    };
    return {std::visit(Convert{value, name}, value.data), value.where};
}

py::object to_python(const DocumentValue& value) {
    struct Convert {
        py::object operator()(bool b) const { return py::bool_(b); }
        py::object operator()(int64_t i) const { return py::int_(i); }
        py::object operator()(double d) const { return py::float_(d); }
        py::object operator()(const std::string& s) const { return py::str(s); }
        py::object operator()(const DocumentArray& array) const {
            py::list list;
            for (const DocumentValue& element : array) list.append(to_python(element));
            return list;
        }
        py::object operator()(const DocumentTable& table) const { return to_python(table); }
    };
    return std::visit(Convert{}, value.data);
}

}  // namespace

SourceLocation python_call_site() {
    // The innermost Python frame is the caller's: calls into this module push none.
    PyFrameObject* frame = PyEval_GetFrame();
    if (frame == nullptr) return {std::make_shared<const std::string>("<python>"), 0, 0};
    const auto code = py::reinterpret_steal<py::object>(reinterpret_cast<PyObject*>(PyFrame_GetCode(frame)));
    return {std::make_shared<const std::string>(py::str(code.attr("co_filename"))),
            uint32_t(std::max(PyFrame_GetLineNumber(frame), 0)), 0};
}

DocumentValue from_python(py::handle value, const std::string& name, const SourceLocation& where) {
    // NumPy's arrays and scalars become Python's lists and numbers (np.bool_ a bool).
    if (py::isinstance<py::array>(value) || py::isinstance(value, py::module_::import("numpy").attr("generic")))
        return from_python(value.attr("tolist")(), name, where);
    // bool before int: True is an int in Python.
    if (PyBool_Check(value.ptr())) return {value.cast<bool>(), where};
    if (PyLong_Check(value.ptr())) {
        try {
            return {value.cast<int64_t>(), where};
        } catch (const py::cast_error&) {
            throw py::value_error(name + " is " + std::string(py::repr(value)) + "; expected a 64-bit integer");
        }
    }
    if (PyFloat_Check(value.ptr())) return {value.cast<double>(), where};
    if (py::isinstance<py::str>(value)) return {value.cast<std::string>(), where};
    if (py::hasattr(value, "__fspath__"))
        return {py::cast<std::string>(py::module_::import("os").attr("fspath")(value)), where};
    if (py::isinstance<py::dict>(value)) {
        DocumentTable table;
        for (const auto& [key, element] : py::reinterpret_borrow<py::dict>(value)) {
            if (!py::isinstance<py::str>(key))
                throw py::type_error(name + " has the key " + std::string(py::repr(key)) + "; keys are strings");
            const auto k = key.cast<std::string>();
            table.emplace_back(k, from_python(element, key_name(name, k), where));
        }
        return {std::move(table), where};
    }
    if (py::isinstance<py::sequence>(value) && !py::isinstance<py::bytes>(value)) {
        DocumentArray array;
        std::size_t i = 0;
        for (const py::handle element : py::reinterpret_borrow<py::sequence>(value))
            array.push_back(from_python(element, name + "[" + std::to_string(i++) + "]", where));
        return {std::move(array), where};
    }
    // Other numbers (fractions.Fraction, decimal.Decimal) as floats.
    if (py::hasattr(value, "__float__"))
        return {py::cast<double>(py::float_(py::reinterpret_borrow<py::object>(value))), where};
    throw py::type_error(name + " is " + std::string(py::repr(value)) + " (" + type_name(value) +
                         "); expected a number, a string, a bool, a sequence or a dict");
}

DocumentTable table_from_keywords(const py::kwargs& keywords, const std::string& name, const SourceLocation& where) {
    DocumentTable table;
    for (const auto& [key, value] : keywords) {
        const auto k = key.cast<std::string>();
        table.emplace_back(k, from_python(value, key_name(name, k), where));
    }
    return table;
}

void merge_into_section(DocumentTable& root, std::string_view section, DocumentTable keys,
                        const SourceLocation& where) {
    auto it = find_key(root, section);
    if (it == root.end()) {
        root.emplace_back(std::string(section), DocumentValue{std::move(keys), where});
        return;
    }
    auto* table = std::get_if<DocumentTable>(&it->second.data);
    if (table == nullptr) throw py::type_error(std::string(section) + " is not a table in this scene's dict");
    for (auto& [key, value] : keys) {
        if (auto old = find_key(*table, key); old != table->end())
            old->second = std::move(value);
        else
            table->emplace_back(std::move(key), std::move(value));
    }
}

void append_to_section(DocumentTable& root, std::string_view section, DocumentTable element,
                       const SourceLocation& where) {
    auto it = find_key(root, section);
    if (it == root.end()) {
        root.emplace_back(std::string(section), DocumentValue{DocumentArray{}, where});
        it = std::prev(root.end());
    }
    auto* array = std::get_if<DocumentArray>(&it->second.data);
    if (array == nullptr)
        throw py::type_error(std::string(section) + " is not an array of tables in this scene's dict");
    array->push_back({std::move(element), where});
}

std::size_t section_size(const DocumentTable& root, std::string_view section) {
    const auto it = std::find_if(root.begin(), root.end(), [&](const auto& entry) { return entry.first == section; });
    if (it == root.end()) return 0;
    const auto* array = std::get_if<DocumentArray>(&it->second.data);
    return array ? array->size() : 0;
}

std::shared_ptr<const ParamTable> to_param_table(const DocumentTable& root) {
    return to_param_table(root, "", python_call_site());
}

py::dict to_python(const DocumentTable& root) {
    py::dict dict;
    for (const auto& [key, value] : root) dict[py::str(key)] = to_python(value);
    return dict;
}

}  // namespace glint::python
