// Shared by `quaternia orbit` and `quaternia cycles`: the short flags --formula and --c that set
// [fractal]'s map; reading --c and --z0 and writing numbers is algebra/constant_text.h's.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "quaternia/algebra/constant_text.h"
#include "quaternia/algebra/polynomial.h"
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

// fractal.c with all of the algebra's components (those past its dimension 0), and the same as
// the list of its 4 or 8 components (how --json writes it).
Hypercomplex cOfScene(const Scene& scene);
std::vector<double> cComponents(const Scene& scene);

// `quaternia cycles` works in the quaternions' complex planes only (orbit and plane take every
// algebra): a scene in another algebra (fractal.algebra, issue 16) is refused with a UserError
// naming fractal.algebra rather than silently read as quaternions.
void requireQuaternionAlgebra(const Scene& scene, const std::string& command);

// The map `formula` with c substituted. Throws UserError naming `name` (formulaName) when it
// does not parse, or when it has no escape radius (degree below 2, or possibly unbounded).
Polynomial compileMap(const std::string& formula, const Quaternion& c, const std::string& name);

}  // namespace quaternia
