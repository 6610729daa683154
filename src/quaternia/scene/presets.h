// Named starting points: a few well-known Julia sets, each a handful of table keys. Declared once
// here and used by every command's --preset and by the explorer's preset buttons, so that
// `--preset rabbit` and the page's Rabbit are the same scene.
#pragma once

#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "quaternia/scene/parameters.h"
#include "quaternia/scene/scene.h"

namespace quaternia {

struct Preset {
    std::string name;         // what --preset takes: lower case, words joined by '-'
    std::string description;  // one line, for --help and the explorer's tooltips
    // The table keys it sets ("section.key", value), in order; every other key is left as is.
    std::vector<std::pair<std::string, ParameterValue>> values;
};

// Every preset, in display order.
const std::vector<Preset>& scenePresets();
// nullptr if there is no preset `name`.
const Preset* findPreset(std::string_view name);

// Sets each key of the preset `name` through the table (setParameter). Throws
// UserError("preset", "unknown preset 'rabit' (did you mean 'rabbit'?)") for an unknown name.
void applyPreset(Scene& scene, std::string_view name);

// The names in order, for an option's help: "rabbit, dendrite, ...".
std::string presetNames();

// One line per preset, "  name  description", under a heading: the presets part of --help.
std::string presetHelp();

// The presets as a Markdown section ("## Presets"): each name, its line and the keys it sets, for
// docs/parameters.md (`quaternia reference parameters`).
std::string presetReference();

}  // namespace quaternia
