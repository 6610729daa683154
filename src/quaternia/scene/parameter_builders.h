// The typed builders of parameter table entries (parameter_table.cpp and its neighbours): each
// makes one entry bound to one field of a part of the Scene. A part is a member of Scene
// (&Scene::render) or a slot of an array of them (LightSlot{2}: scene.lights[2]).
#pragma once

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "quaternia/scene/parameters.h"

namespace quaternia::parameter_builders {

template <typename Section>
Section& partOf(Scene& scene, Section Scene::*part) {
    return scene.*part;
}
template <typename Section>
const Section& partOf(const Scene& scene, Section Scene::*part) {
    return scene.*part;
}
// scene.lights[index]: [light1] is index 0.
struct LightSlot {
    std::size_t index;
};
inline LightSettings& partOf(Scene& scene, LightSlot slot) {
    return scene.lights[slot.index];
}
inline const LightSettings& partOf(const Scene& scene, LightSlot slot) {
    return scene.lights[slot.index];
}

inline Parameter makeParameter(std::string section, std::string key, ParameterType type,
                               ParameterValue defaultValue, double minimum, double maximum,
                               std::string help) {
    Parameter p;
    p.section = std::move(section);
    p.key = std::move(key);
    p.type = type;
    p.defaultValue = std::move(defaultValue);
    p.minimum = minimum;
    p.maximum = maximum;
    p.help = std::move(help);
    return p;
}

template <typename Part, typename Section>
Parameter realParameter(std::string section, std::string key, Part part, double Section::*field,
                        double defaultValue, double minimum, double maximum, std::string help) {
    Parameter p = makeParameter(std::move(section), std::move(key), ParameterType::Real,
                                defaultValue, minimum, maximum, std::move(help));
    p.apply = [part, field](Scene& scene, const ParameterValue& value) {
        partOf(scene, part).*field = std::get<double>(value);
    };
    p.read = [part, field](const Scene& scene) -> ParameterValue {
        return partOf(scene, part).*field;
    };
    return p;
}

// `allowed`, if not empty, lists the only values allowed within [minimum, maximum].
template <typename Part, typename Section>
Parameter integerParameter(std::string section, std::string key, Part part, int Section::*field,
                           int64_t defaultValue, int64_t minimum, int64_t maximum, std::string help,
                           std::vector<int64_t> allowed = {}) {
    Parameter p = makeParameter(std::move(section), std::move(key), ParameterType::Integer,
                                defaultValue, double(minimum), double(maximum), std::move(help));
    p.allowedIntegers = std::move(allowed);
    p.apply = [part, field](Scene& scene, const ParameterValue& value) {
        partOf(scene, part).*field = int(std::get<int64_t>(value));  // the range makes it fit
    };
    p.read = [part, field](const Scene& scene) -> ParameterValue {
        return int64_t{partOf(scene, part).*field};
    };
    return p;
}

template <typename Part, typename Section>
Parameter booleanParameter(std::string section, std::string key, Part part, bool Section::*field,
                           bool defaultValue, std::string help) {
    Parameter p = makeParameter(std::move(section), std::move(key), ParameterType::Boolean,
                                defaultValue, 0, 0, std::move(help));
    p.apply = [part, field](Scene& scene, const ParameterValue& value) {
        partOf(scene, part).*field = std::get<bool>(value);
    };
    p.read = [part, field](const Scene& scene) -> ParameterValue {
        return partOf(scene, part).*field;
    };
    return p;
}

// Text whose length in bytes lies in [minimumLength, maximumLength].
template <typename Part, typename Section>
Parameter textParameter(std::string section, std::string key, Part part,
                        std::string Section::*field, std::string defaultValue, int minimumLength,
                        int maximumLength, std::string help) {
    Parameter p =
        makeParameter(std::move(section), std::move(key), ParameterType::Text,
                      std::move(defaultValue), minimumLength, maximumLength, std::move(help));
    p.apply = [part, field](Scene& scene, const ParameterValue& value) {
        partOf(scene, part).*field = std::get<std::string>(value);
    };
    p.read = [part, field](const Scene& scene) -> ParameterValue {
        return partOf(scene, part).*field;
    };
    return p;
}

// An enum chosen by name; `options` maps each word to its enum value, in display order.
template <typename Part, typename Section, typename Enum>
Parameter choiceParameter(std::string section, std::string key, Part part, Enum Section::*field,
                          std::string defaultValue,
                          std::vector<std::pair<std::string, Enum>> options, std::string help) {
    Parameter p = makeParameter(std::move(section), std::move(key), ParameterType::Choice,
                                std::move(defaultValue), 0, 0, std::move(help));
    for (const auto& option : options)
        p.choices.push_back(option.first);
    p.apply = [part, field, options](Scene& scene, const ParameterValue& value) {
        const auto& word = std::get<std::string>(value);
        for (const auto& [name, enumValue] : options)
            if (name == word) partOf(scene, part).*field = enumValue;
    };
    p.read = [part, field, options](const Scene& scene) -> ParameterValue {
        for (const auto& [name, enumValue] : options)
            if (enumValue == partOf(scene, part).*field) return name;
        return std::string("?");  // an enum value the table does not name; checkedValue rejects it
    };
    return p;
}

// A vector of N reals stored in any field with operator[] (Vector3d, Quaternion in (1, i, j, k)
// order, std::array); [minimum, maximum] bounds each component.
template <std::size_t N, typename Part, typename Section, typename Field>
Parameter vectorParameter(std::string section, std::string key, Part part, Field Section::*field,
                          const double (&defaultValue)[N], double minimum, double maximum,
                          std::string help) {
    static_assert(N == 2 || N == 3 || N == 4 || N == 6);
    ParameterType type = N == 2   ? ParameterType::Vector2
                         : N == 3 ? ParameterType::Vector3
                         : N == 4 ? ParameterType::Vector4
                                  : ParameterType::Vector6;
    Parameter p = makeParameter(std::move(section), std::move(key), type,
                                std::vector<double>(defaultValue, defaultValue + N), minimum,
                                maximum, std::move(help));
    p.apply = [part, field](Scene& scene, const ParameterValue& value) {
        const auto& v = std::get<std::vector<double>>(value);
        for (std::size_t i = 0; i < N; ++i)
            (partOf(scene, part).*field)[int(i)] = v[i];
    };
    p.read = [part, field](const Scene& scene) -> ParameterValue {
        std::vector<double> v(N);
        for (std::size_t i = 0; i < N; ++i)
            v[i] = (partOf(scene, part).*field)[int(i)];
        return v;
    };
    return p;
}

// A vector of reals whose allowed lengths are `lengths` (ParameterType::Components), stored as
// is in a std::vector<double> field; `groups` as Parameter::groups.
template <typename Part, typename Section>
Parameter componentsParameter(std::string section, std::string key, Part part,
                              std::vector<double> Section::*field, std::vector<double> defaultValue,
                              std::vector<std::size_t> lengths, double minimum, double maximum,
                              std::string help, std::size_t groups = 0) {
    Parameter p = makeParameter(std::move(section), std::move(key), ParameterType::Components,
                                std::move(defaultValue), minimum, maximum, std::move(help));
    p.lengths = std::move(lengths);
    p.groups = groups;
    p.apply = [part, field](Scene& scene, const ParameterValue& value) {
        partOf(scene, part).*field = std::get<std::vector<double>>(value);
    };
    p.read = [part, field](const Scene& scene) -> ParameterValue {
        return partOf(scene, part).*field;
    };
    return p;
}

// The entries of [light1] .. [light7], [material] and [ground] (parameter_table_scenery.cpp),
// which buildParameterTable puts after [shading].
std::vector<Parameter> sceneryParameters();

}  // namespace quaternia::parameter_builders
