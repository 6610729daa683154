// The scene builds the fractal it describes (fractal/ knows nothing of scene files): its
// [fractal] and [slice], with octonions folded into the quaternions where the SIMD engine
// renders them (fractal.h, OctonionFolding).
#pragma once

#include "quaternia/fractal/fractal.h"
#include "quaternia/fractal/hypercomplex_julia.h"
#include "quaternia/scene/scene.h"

namespace quaternia {

// Throws UserError naming the bad key.
Fractal fractalFromScene(const Scene& scene);
// The scene's set in its own algebra through its multiplication table (HypercomplexJuliaSet, the
// quaternions too), never folded, with its slice: what the commands that work in the algebra
// itself take (orbits, planes of the other algebras).
Fractal hypercomplexFractalFromScene(const Scene& scene);

}  // namespace quaternia
