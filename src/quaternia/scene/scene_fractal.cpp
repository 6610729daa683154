#include "quaternia/scene/scene_fractal.h"

#include <algorithm>

#include "quaternia/algebra/formula.h"
#include "quaternia/util/error.h"

namespace quaternia {

Fractal fractalFromScene(const Scene& scene) {
    // The scalar engine is the reference: it draws every algebra in itself.
    const QuaternionPaths paths = scene.render.engine == RenderEngine::Simd
                                      ? QuaternionPaths::kWherePossible
                                      : QuaternionPaths::kNever;
    return Fractal::fromSettings(scene.fractal, scene.slice, paths);
}

void requireFractalMemory(const Scene& scene, const Fractal& fractal, const MemoryBudget& budget) {
    const uint64_t bytes = fractal.set().tableBytes();
    if (bytes == 0) return;
    requireMemory(bytes, budget, "fractal.formula",
                  "fractal.formula = \"" + scene.fractal.formula +
                      "\": building the certified escape maps of its two duplex components",
                  "the maps' size does not depend on the image; raise the memory budget");
}

void requireFractalMemory(const Scene& scene, const MemoryBudget& budget) {
    requireFractalMemory(scene, fractalFromScene(scene), budget);
}

Fractal hypercomplexFractalFromScene(const Scene& scene) {
    auto set = hypercomplexJuliaSetOf(scene.fractal);  // the formula and bailout first
    return Fractal(std::move(set), Slice(scene.slice, scene.fractal.algebra));
}

Hypercomplex cOfScene(const Scene& scene) {
    const Quaternion& c = scene.fractal.c;
    const std::array<double, 4>& upper = scene.fractal.cUpper;
    Hypercomplex value{c.w, c.x, c.y, c.z, 0, 0, 0, 0};
    if (algebraDimension(scene.fractal.algebra) == 8)
        std::copy(upper.begin(), upper.end(), value.begin() + 4);
    return value;
}

std::vector<double> cComponents(const Scene& scene) {
    const Hypercomplex c = cOfScene(scene);
    return {c.begin(), c.begin() + algebraDimension(scene.fractal.algebra)};
}

void requireQuaternionAlgebra(const Scene& scene, const std::string& command) {
    if (scene.fractal.algebra == Algebra::kQuaternion) return;
    throw UserError("fractal.algebra",
                    "fractal.algebra = \"" + std::string(algebraName(scene.fractal.algebra)) +
                        "\": `quaternia " + command +
                        "` works in the quaternions only so far; render, mesh, orbit and "
                        "plane (plane.kind = \"slice\") take every algebra");
}

Polynomial compileMap(const std::string& formula, const Quaternion& c, const std::string& name) {
    Polynomial p = compileFormula(formula, c, name);
    try {
        p.escapeRadius();
    } catch (const UserError& e) {
        // Polynomial::escapeRadius names the scene key; the formula may have come from a flag.
        std::string message = e.what();
        const std::string key = "fractal.formula";
        if (message.starts_with(key)) message = name + message.substr(key.size());
        throw UserError(name, message);
    }
    return p;
}

}  // namespace quaternia
