// The scene builds the fractal it describes (fractal/ knows nothing of scene files): its
// [fractal] and [slice], with octonions folded into the quaternions where the SIMD engine
// renders them (fractal.h, QuaternionPaths).
#pragma once

#include <string>
#include <vector>

#include "quaternia/algebra/hypercomplex.h"
#include "quaternia/algebra/polynomial.h"
#include "quaternia/fractal/fractal.h"
#include "quaternia/fractal/hypercomplex_julia.h"
#include "quaternia/scene/scene.h"
#include "quaternia/util/memory_budget.h"

namespace quaternia {

// Throws UserError naming the bad key.
Fractal fractalFromScene(const Scene& scene);
// The scene's set in its own algebra through its multiplication table (HypercomplexJuliaSet, the
// quaternions too), never folded, with its slice: what the commands that work in the algebra
// itself take (orbits, planes of the other algebras).
Fractal hypercomplexFractalFromScene(const Scene& scene);

// Refuses, with a MemoryLimitError naming fractal.formula, a scene whose set's tables
// (JuliaSet::tableBytes: the bicomplex functions' escape maps, built by the first render) need
// more than `budget`; checked, like the environment map, on its own beside the image's buffers.
// The fractal already built from the scene (fractalFromScene), or built here.
void requireFractalMemory(const Scene& scene, const Fractal& fractal, const MemoryBudget& budget);
void requireFractalMemory(const Scene& scene, const MemoryBudget& budget);

// fractal.c with all of the algebra's components (those past its dimension 0), and the same as
// the list of its 4 or 8 components (how the commands' JSON writes it).
Hypercomplex cOfScene(const Scene& scene);
std::vector<double> cComponents(const Scene& scene);

// For what works in the quaternions' complex planes only (`quaternia cycles`; orbit and plane
// take every algebra): a scene in another algebra (fractal.algebra, issue 16) is refused with a
// UserError naming fractal.algebra rather than silently read as quaternions. `command` is the
// command named in the message.
void requireQuaternionAlgebra(const Scene& scene, const std::string& command);

// The map `formula` with c substituted, for the orbit analyses, which need an escape radius.
// Throws UserError naming `name` (the key, or the flag that set it) when it does not parse, or
// when it has no escape radius (degree below 2, or possibly unbounded).
Polynomial compileMap(const std::string& formula, const Quaternion& c,
                      const std::string& name = "fractal.formula");

}  // namespace quaternia
