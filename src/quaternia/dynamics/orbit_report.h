// The report of `quaternia orbit`, for every front end (the CLI, the Python module): the fate of
// the scene's orbit from orbit.z0 under fractal.formula with fractal.c in fractal.algebra, its
// cycle's multipliers and class, and whether K is connected. Computed once (orbitReport), then
// written as the CLI's text (toText) or its --json object (toJson); the library prints nothing.
#pragma once

#include <optional>
#include <string>

#include "quaternia/algebra/hypercomplex.h"
#include "quaternia/algebra/quaternion.h"
#include "quaternia/dynamics/connectedness.h"
#include "quaternia/dynamics/orbit.h"
#include "quaternia/scene/json.h"
#include "quaternia/scene/scene.h"

namespace quaternia {

struct OrbitReport {
    // What was analysed, as the scene gave it.
    Algebra algebra = Algebra::kQuaternion;
    std::string formula;
    Hypercomplex c{};  // fractal.c, the components past the algebra's dimension 0
    Quaternion z0;     // orbit.z0; in an 8-component algebra components 4 .. 7 are 0
    int maxIterations = 0;
    // The orbit: OrbitResult in the quaternions, HypercomplexOrbitResult<4 or 8> in the others.
    AnyOrbitResult orbit;
    // K's connectedness, where the map restricts to a complex polynomial on a copy of C (the
    // quaternions' complex restriction, or HypercomplexFormula::complexAxis); else none.
    std::optional<Connectedness> connectedness;
};

// Throws UserError on a map without an escape radius or a formula that does not parse. In the
// quaternions the message names `formulaName` (the CLI passes "--formula" where the formula came
// from that flag); in the other algebras it names fractal.formula.
OrbitReport orbitReport(const Scene& scene, const std::string& formulaName = "fractal.formula");

// The `quaternia orbit --json` object: command, algebra (other algebras only), formula, c, z0,
// max_iterations, the orbit's fields (fate, escape_iteration, preperiod, period, class, unsure,
// note), cycle, escape_radius, tolerance, iterations and connectedness (null where absent).
Json toJson(const OrbitReport& report);
// The text `quaternia orbit` prints: lines "orbit of z0 = ...", "fate: ...", and where they
// apply "cycle:", "multiplier:", "in H: ...", "unsure:" and "K:", each ending in a newline.
std::string toText(const OrbitReport& report);

}  // namespace quaternia
