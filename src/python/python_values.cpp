// The scene's values in and out of Python, and the module's exceptions.
#include <Python.h>

#include <cerrno>
#include <cstring>
#include <variant>

#include "python/python_module.h"
#include "quaternia/util/error.h"
#include "quaternia/util/memory_budget.h"

namespace quaternia::python {
namespace {

// quaternia.UnknownKeyError, made in bindErrors.
py::object& unknownKeyError() {
    static auto* type = new py::object();  // never freed: Python may outlive static destructors
    return *type;
}

void flatten(py::handle value, std::vector<double>& out, const Parameter& parameter) {
    if (py::isinstance<py::str>(value) || py::isinstance<py::bytes>(value))
        throw UserError(parameter.name(), parameter.name() + " must be " + describeType(parameter) +
                                              ", got a string");
    if (PySequence_Check(value.ptr()) || py::isinstance<py::array>(value)) {
        for (py::handle item : py::iter(value))
            flatten(item, out, parameter);
        return;
    }
    try {
        out.push_back(py::cast<double>(value));
    } catch (const py::cast_error&) {
        throw UserError(parameter.name(),
                        parameter.name() + " must be " + describeType(parameter) + ", got " +
                            std::string(py::str(value.get_type().attr("__name__"))));
    }
}

}  // namespace

ParameterValue parameterValueOf(const Parameter& parameter, py::handle value) {
    const py::module_ numpy = py::module_::import("numpy");
    if (py::isinstance<py::bool_>(value) || py::isinstance(value, numpy.attr("bool_")))
        return value.cast<bool>();
    if (py::isinstance<py::str>(value)) return value.cast<std::string>();
    // Integers (Python's and NumPy's) before floats: an exact integer stays one for an Integer.
    if (PyLong_Check(value.ptr()) || py::isinstance(value, numpy.attr("integer")))
        return value.cast<int64_t>();
    if (PyFloat_Check(value.ptr()) || py::isinstance(value, numpy.attr("floating")))
        return value.cast<double>();
    if (py::isinstance<py::array>(value) || PySequence_Check(value.ptr())) {
        std::vector<double> numbers;
        flatten(value, numbers, parameter);
        return numbers;
    }
    throw UserError(parameter.name(), parameter.name() + " must be " + describeType(parameter) +
                                          ", got " +
                                          std::string(py::str(value.get_type().attr("__name__"))));
}

py::object pythonValueOf(const Parameter& parameter, const ParameterValue& value) {
    if (const auto* numbers = std::get_if<std::vector<double>>(&value)) {
        py::list list;
        const std::size_t groups = parameter.groups;
        if (groups == 0 || numbers->size() % groups != 0) {
            for (double x : *numbers)
                list.append(x);
            return list;
        }
        const std::size_t group = numbers->size() / groups;
        for (std::size_t begin = 0; begin < numbers->size(); begin += group) {
            py::list row;
            for (std::size_t i = begin; i < begin + group && i < numbers->size(); ++i)
                row.append((*numbers)[i]);
            list.append(row);
        }
        return list;
    }
    return std::visit(
        [](const auto& v) -> py::object {
            using T = std::decay_t<decltype(v)>;
            if constexpr (std::is_same_v<T, std::vector<double>>) {
                return py::none();
            } else {
                return py::cast(v);
            }
        },
        value);
}

const Parameter& parameterNamed(const std::string& name) {
    if (const Parameter* parameter = findParameter(name)) return *parameter;
    if (std::optional<std::string> light = pastTheLights(name)) raiseUnknownKey(*light);
    raiseUnknownKey("unknown key '" + name + "' (did you mean '" + nearestParameterName(name) +
                    "'?)");
}

Scene withOverrides(const Scene& scene,
                    const std::vector<std::pair<const char*, std::optional<int64_t>>>& values) {
    Scene result = scene;
    for (const auto& [name, value] : values)
        if (value) setParameter(result, name, *value);
    return result;
}

void raiseUnknownKey(const std::string& message) {
    PyErr_SetString(unknownKeyError().ptr(), message.c_str());
    throw py::error_already_set();
}

void raiseMemoryError(const std::string& message) {
    PyErr_SetString(PyExc_MemoryError, message.c_str());
    throw py::error_already_set();
}

void raiseOSError(const std::string& message) {
    PyErr_SetString(PyExc_OSError, message.c_str());
    throw py::error_already_set();
}

int threadsOf(std::optional<int> threads) {
    if (threads && (*threads < 0 || *threads > 1024))
        throw UserError("threads", "threads must be in [0, 1024], got " + std::to_string(*threads));
    return threads.value_or(0);
}

MemoryBudget memoryBudgetOf(const std::optional<std::string>& budget, int threads) {
    return parseMemoryBudget(budget.value_or("auto"), "memory_budget", resolveThreadCount(threads));
}

void requireMemoryOrRaise(uint64_t bytes, const std::optional<std::string>& budget, int threads,
                          const std::string& key, const std::string& what,
                          const std::string& advice) {
    requireMemory(bytes, memoryBudgetOf(budget, threads), key, what,
                  advice);  // MemoryLimitError: MemoryError
}

void bindErrors(py::module_& module) {
    // Bad keys and values are ValueErrors; an unknown key read or set like a mapping's is also
    // a KeyError, whose message prints plainly (KeyError's own __str__ quotes it).
    py::object builtins = py::module_::import("builtins");
    py::tuple bases = py::make_tuple(builtins.attr("KeyError"), builtins.attr("ValueError"));
    unknownKeyError() = py::reinterpret_steal<py::object>(
        PyErr_NewExceptionWithDoc("quaternia.UnknownKeyError",
                                  "A scene key that the parameter table does not have; the "
                                  "message names the nearest one.",
                                  bases.ptr(), nullptr));
    unknownKeyError().attr("__str__") = builtins.attr("Exception").attr("__str__");
    module.attr("UnknownKeyError") = unknownKeyError();
    py::register_exception_translator([](std::exception_ptr error) {
        try {
            if (error) std::rethrow_exception(error);
        } catch (const MemoryLimitError& e) {
            PyErr_SetString(PyExc_MemoryError, e.what());
        } catch (const UserError& e) {
            PyErr_SetString(PyExc_ValueError, e.what());
        }
    });
}

}  // namespace quaternia::python
