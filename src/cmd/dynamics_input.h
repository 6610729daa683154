// Shared by `quaternia orbit` and `quaternia cycles`: the short flags --formula and --c that set
// [fractal]'s map; reading --c and --z0 and writing numbers is algebra/constant_text.h's. What
// the commands compute from the scene is the library's (dynamics/orbit_report.h,
// dynamics/cycles_report.h, and scene/scene_fractal.h for the scene's map and c).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "quaternia/algebra/constant_text.h"
#include "quaternia/algebra/quaternion.h"
#include "quaternia/scene/scene.h"

namespace quaternia {

// --formula sets fractal.formula, --c sets fractal.c (in parseConstant's syntax); unset, the
// scene's values stand.
struct MapFlags {
    std::optional<std::string> formula, c;
};

void addMapFlags(CLI::App& command, MapFlags& flags, const std::string& formulaHelp,
                 const std::string& cHelp);
// Applies the flags given (after --set). Throws UserError naming the flag.
void applyMapFlags(Scene& scene, const MapFlags& flags);
// What a message about the formula names: "--formula" where it came from the flag, otherwise
// "fractal.formula".
std::string formulaName(const MapFlags& flags);

// q as the table's (1, i, j, k) vector, for setParameter.
std::vector<double> quaternionValue(const Quaternion& q);

}  // namespace quaternia
