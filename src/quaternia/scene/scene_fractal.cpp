#include "quaternia/scene/scene_fractal.h"

namespace quaternia {

Fractal fractalFromScene(const Scene& scene) {
    // The scalar engine is the reference: it draws octonions as octonions.
    const OctonionFolding folding = scene.render.engine == RenderEngine::Simd
                                        ? OctonionFolding::kWherePossible
                                        : OctonionFolding::kNever;
    return Fractal::fromSettings(scene.fractal, scene.slice, folding);
}

Fractal hypercomplexFractalFromScene(const Scene& scene) {
    auto set = hypercomplexJuliaSetOf(scene.fractal);  // the formula and bailout first
    return Fractal(std::move(set), Slice(scene.slice, scene.fractal.algebra));
}

}  // namespace quaternia
