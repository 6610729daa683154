#include "quaternia/scene/toml_values.h"

#include <utility>
#include <vector>

#include "quaternia/scene/parameters.h"

namespace quaternia {

namespace {

// The numbers of an array of numbers, appended to `numbers`; false if an element is not one.
bool appendNumbers(const toml::array& array, std::vector<double>& numbers) {
    for (const auto& element : array) {
        if (const auto* integer = element.as_integer())
            numbers.push_back(double(integer->get()));
        else if (const auto* real = element.as_floating_point())
            numbers.push_back(real->get());
        else
            return false;
    }
    return true;
}

}  // namespace

std::optional<ParameterValue> toParameterValue(const toml::node& node, const Parameter* parameter) {
    // Built in place: moving a variant temporary into the optional trips GCC 12's
    // -Wmaybe-uninitialized false positive in optimised sanitizer builds.
    auto value = [](auto&& x) {
        return std::optional<ParameterValue>(std::in_place, std::forward<decltype(x)>(x));
    };
    if (const auto* integer = node.as_integer()) return value(int64_t(integer->get()));
    if (const auto* real = node.as_floating_point()) return value(double(real->get()));
    if (const auto* boolean = node.as_boolean()) return value(bool(boolean->get()));
    if (const auto* text = node.as_string()) return value(std::string(text->get()));
    if (const auto* array = node.as_array()) {
        std::vector<double> numbers;
        if (appendNumbers(*array, numbers)) return value(std::move(numbers));
        // `groups` arrays of equal length ([[a0 .. a7], [b0 .. b7], [c0 .. c7]]), flattened.
        const std::size_t groups = parameter != nullptr ? parameter->groups : 0;
        if (groups == 0 || array->size() != groups) return std::nullopt;
        numbers.clear();
        const auto* first = array->get(0)->as_array();
        for (const auto& element : *array) {
            const auto* inner = element.as_array();
            if (inner == nullptr || first == nullptr || inner->size() != first->size() ||
                !appendNumbers(*inner, numbers))
                return std::nullopt;
        }
        return value(std::move(numbers));
    }
    return std::nullopt;
}

// What a value that toParameterValue could not read was, for messages.
std::string describeNode(const toml::node& node) {
    if (auto value = toParameterValue(node)) return formatValue(*value);
    if (const auto* array = node.as_array()) {
        std::string out = "[";
        for (std::size_t i = 0; i < array->size(); ++i)
            out += (i ? ", " : "") + describeNode(*array->get(i));
        return out + "]";
    }
    if (node.is_table()) return "a table";
    if (node.is_date()) return "a date";
    if (node.is_time()) return "a time";
    return "a date-time";
}

// "scene.toml:3:7: "
std::string location(const std::string& sourceName, const toml::source_position& where) {
    return sourceName + ":" + std::to_string(where.line) + ":" + std::to_string(where.column) +
           ": ";
}

}  // namespace quaternia
