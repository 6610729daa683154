// Internal to the parameter table's machinery (parameter_text.cpp, parameter_help.cpp,
// parameter_checks.cpp): the pieces of text that both the checks' messages and the help are
// made of, so that a range reads the same in an error and in --help.
#pragma once

#include <cstddef>
#include <string>

#include "quaternia/scene/parameters.h"

namespace quaternia::parameter_text {

// A string in TOML syntax: quoted, with escapes.
std::string quoted(const std::string& text);

// "[minimum, maximum]" of a parameter.
std::string interval(const Parameter& p);

// The number of components of a vector type: 2, 3, 4 or 6; 0 for the other types.
inline std::size_t vectorLength(ParameterType type) {
    switch (type) {
        case ParameterType::Vector2:
            return 2;
        case ParameterType::Vector3:
            return 3;
        case ParameterType::Vector4:
            return 4;
        case ParameterType::Vector6:
            return 6;
        default:
            return 0;
    }
}

}  // namespace quaternia::parameter_text
