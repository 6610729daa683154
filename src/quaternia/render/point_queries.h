// Membership in K_N and the distance estimate at many points at once, decided as the renderer
// decides them: in the SIMD lanes where the renderer marches in them (LaneFractal::forScene: the
// quaternions, bicomplex polynomials; the scene's render.precision), else by the scalar
// reference (Fractal, JuliaSet), spread over every core by the one parallel-for. For front ends
// that ask about points of their own (the Python module's contains and distance).
#pragma once

#include <cstddef>
#include <cstdint>

#include "quaternia/scene/scene.h"
#include "quaternia/util/parallel.h"

namespace quaternia {

// `points` holds `count` points, row-major, `components` numbers each: 3 for points of the
// slice's 3D space (where the renderer's rays run; distances there are the renderer's, scaled
// by the slice), or the algebra's dimension (4, or 8 for the 8-component algebras) for points of
// the algebra itself (distances in the algebra). Writes, where not null, inside[i] (1 for a
// point of K_N, else 0) and distance[i] (0 inside; a lower bound of the distance to K_N where
// the algebra's distance is a proven Lipschitz bound). Validates the scene and throws UserError
// before any work: naming fractal.algebra for a number of components that the algebra does not
// have. Returns false if cancelled (the outputs are then partly written).
bool queryPoints(const Scene& scene, const double* points, std::size_t count, int components,
                 uint8_t* inside, double* distance, const WorkOptions& options = {});

}  // namespace quaternia
