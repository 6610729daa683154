// The report of `quaternia cycles`, for every front end (the CLI, the Python module): every
// periodic point of period cycles.period of the scene's map (fractal.formula with fractal.c, a
// complex polynomial on one plane C_u of the quaternions), grouped into cycles with multipliers
// and classes. Computed once (cyclesReport), then written as the CLI's table (toText) or its
// --json object (toJson); the library prints nothing.
#pragma once

#include <string>

#include "quaternia/algebra/complex_polynomial.h"
#include "quaternia/algebra/quaternion.h"
#include "quaternia/dynamics/periodic_points.h"
#include "quaternia/scene/json.h"
#include "quaternia/scene/scene.h"

namespace quaternia {

struct CyclesReport {
    std::string formula;     // fractal.formula
    Quaternion c;            // fractal.c
    ComplexRestriction map;  // the map on its plane C_u, in the coordinates x + y u
    PeriodicPoints points;   // of period cycles.period
};

// Throws UserError: naming fractal.algebra for an algebra other than the quaternions; naming
// `formulaName` for a formula that does not parse, has no escape radius or whose coefficients do
// not share one plane C_u; naming `periodName` for a period below 1 or with degree^period above
// kMaxPeriodicPoints. The CLI passes "--formula" and "--period" where those flags set the keys.
CyclesReport cyclesReport(const Scene& scene, const std::string& formulaName = "fractal.formula",
                          const std::string& periodName = "cycles.period");

// The `quaternia cycles --json` object: command, formula, c, plane_axis, period, points (their
// number) and cycles, each with period, points, multiplier, class, unsure, degenerate,
// multiplicity, complete and residual.
Json toJson(const CyclesReport& report);
// The table `quaternia cycles` prints: a headline, the plane's axis where it is not i, a header
// and one row per cycle, each line ending in a newline.
std::string toText(const CyclesReport& report);

}  // namespace quaternia
