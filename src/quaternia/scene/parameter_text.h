// Internal to the parameter table's machinery (parameter_text.cpp, parameter_help.cpp,
// parameter_checks.cpp): the pieces of text that both the checks' messages and the help are
// made of, so that a range reads the same in an error and in --help. The Markdown helpers also
// write cmd/reference_command.cpp's tables of options, so that docs/cli.md escapes as
// docs/parameters.md does.
#pragma once

#include <cstddef>
#include <string>

#include "quaternia/scene/parameters.h"

namespace quaternia::parameter_text {

// A string in TOML syntax: quoted, with escapes.
std::string quoted(const std::string& text);

// "[minimum, maximum]" of a parameter.
std::string interval(const Parameter& p);

// `text` made safe for a cell of a Markdown table, as GitHub renders it: '|' escaped everywhere
// (it would end the cell, even inside a code span), and outside `code spans` '*', '\\' and '<'
// too, so that "i*z*j*z" stays as written instead of turning italic. Backticks are kept: help
// strings quote commands as `quaternia plane`.
std::string markdownCell(const std::string& text);

// `text` as a code span in a Markdown table cell.
std::string markdownCode(const std::string& text);

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
