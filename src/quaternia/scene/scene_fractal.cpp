#include "quaternia/scene/scene_fractal.h"

namespace quaternia {

Fractal fractalFromScene(const Scene& scene) {
    // The scalar engine is the reference: it draws octonions as octonions.
    const OctonionFolding folding = scene.render.engine == RenderEngine::Simd
                                        ? OctonionFolding::kWherePossible
                                        : OctonionFolding::kNever;
    return Fractal::fromSettings(scene.fractal, scene.slice, folding);
}

std::shared_ptr<const HypercomplexFractal> hypercomplexFractalFromScene(const Scene& scene) {
    return hypercomplexFractalOf(scene.fractal, scene.slice);
}

}  // namespace quaternia
