// TOML nodes as parameter values, for the readers of scene files (scene_file.cpp,
// animation_file.cpp). toml++ stays inside the scene layer: nothing above includes this header.
#pragma once

#include <optional>
#include <string>

#include <toml++/toml.h>

#include "quaternia/scene/scene.h"

namespace quaternia {

struct Parameter;

// Integers, floats, booleans, strings and arrays of numbers (integers and floats mixed, read
// as reals); nothing for tables, dates, times and other arrays. For a `parameter` with groups
// (slice.axes), an array of exactly that many arrays of numbers, all of one length, is read too,
// as the numbers one after the other.
std::optional<ParameterValue> toParameterValue(const toml::node& node,
                                               const Parameter* parameter = nullptr);

// What a value that toParameterValue could not read was, for messages.
std::string describeNode(const toml::node& node);

// "scene.toml:3:7: "
std::string location(const std::string& sourceName, const toml::source_position& where);

}  // namespace quaternia
