#include "quaternia/scene/scene_rules.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "quaternia/scene/parameters.h"
#include "quaternia/util/error.h"

namespace quaternia {
namespace {

// Scenes built in code (tests, the explorer, animation frames) need not pass through
// setParameter, so every value is checked against the table again; it comes first, so that the
// rules after it may take each value as in range.
void everyValueInRange(const Scene& scene) {
    for (const auto& p : parameterTable())
        checkedValue(p, p.read(scene));
}

// The view direction is camera.look_at - camera.position: where they coincide no ray can be
// aimed.
void cameraHasAViewDirection(const Scene& scene) {
    const CameraSettings& camera = scene.camera;
    Vector3d view = camera.lookAt - camera.position;
    if (dot(view, view) == 0)
        throw UserError("camera.look_at",
                        "camera.look_at equals camera.position; the camera needs a direction to "
                        "look in");
}

// The image's sideways axis is built from camera.up and the view direction, which a zero or
// parallel up vector cannot give.
void upIsNotAlongTheView(const Scene& scene) {
    const CameraSettings& camera = scene.camera;
    Vector3d view = camera.lookAt - camera.position;
    // sin(angle between up and view) below 1e-9: no sideways axis can be built from them.
    if (length(cross(camera.up, view)) <= 1e-9 * length(camera.up) * length(view))
        throw UserError("camera.up", "camera.up = " +
                                         formatValue(std::vector<double>{camera.up.x, camera.up.y,
                                                                         camera.up.z}) +
                                         " is zero or parallel to the view direction "
                                         "camera.look_at - camera.position");
}

// fractal.c takes 4 or 8 components whichever the algebra, since a scene may set fractal.c
// before fractal.algebra; here, with both known, a shorter c is the algebra's element with zeros
// in the components not given (so that switching the algebra alone works: the default c of 4
// components is an octonion's), and a longer one would lose components without a word.
void constantFitsTheAlgebra(const Scene& scene) {
    const FractalSettings& fractal = scene.fractal;
    const int dimension = algebraDimension(fractal.algebra);
    const std::string algebra(algebraName(fractal.algebra));
    if (fractal.cComponents > dimension)
        throw UserError("fractal.c", "fractal.c has " + std::to_string(fractal.cComponents) +
                                         " components; the " + algebra + " algebra has " +
                                         std::to_string(dimension));
}

bool hasEightComponents(const Scene& scene) {
    return algebraDimension(scene.fractal.algebra) == 8;
}

// The 8-component algebras are sliced by slice.origin and slice.axes alone: the quaternion
// slice's keys must keep their defaults, or a scene would say more than it draws.
void eightComponentSlicesKeepTheQuaternionSliceKeys(const Scene& scene) {
    if (!hasEightComponents(scene)) return;
    const std::string algebra(algebraName(scene.fractal.algebra));
    for (const char* name :
         {"slice.normal", "slice.distance", "slice.left", "slice.right", "slice.angles"}) {
        const Parameter& p = *findParameter(name);
        if (p.read(scene) != p.defaultValue)
            throw UserError(name, std::string(name) + " applies to the 4-component algebras; the " +
                                      algebra + " algebra takes slice.origin and slice.axes");
    }
}

// The axes are orthonormalised in order to span the slice, which takes three independent
// directions. Gram-Schmidt in order: each axis less its projections on the ones before must keep
// at least 1e-9 of its own length.
void sliceAxesAreIndependent(const Scene& scene) {
    if (!hasEightComponents(scene)) return;
    const std::vector<double>& axes = scene.slice.axes;
    if (axes.empty()) return;
    // 8 components per axis, or 4 (the rest 0).
    const std::size_t kDimension = axes.size() / 3;
    std::vector<std::vector<double>> units;
    for (std::size_t a = 0; a * kDimension < axes.size(); ++a) {
        std::vector<double> v(axes.begin() + std::ptrdiff_t(a * kDimension),
                              axes.begin() + std::ptrdiff_t((a + 1) * kDimension));
        auto length = [](const std::vector<double>& x) {
            double sum = 0;
            for (double component : x)
                sum += component * component;
            return std::sqrt(sum);
        };
        const double own = length(v);
        const std::string axis = "slice.axes: axis " + std::to_string(a + 1);
        if (own == 0)
            throw UserError("slice.axes",
                            axis + " is zero; three independent directions are needed");
        for (const auto& unit : units) {
            double along = 0;
            for (std::size_t k = 0; k < kDimension; ++k)
                along += v[k] * unit[k];
            for (std::size_t k = 0; k < kDimension; ++k)
                v[k] -= along * unit[k];
        }
        const double rest = length(v);
        if (rest < 1e-9 * own)
            throw UserError("slice.axes", axis +
                                              " lies in the span of the axes before it; three "
                                              "independent directions are needed");
        for (double& component : v)
            component /= rest;
        units.push_back(std::move(v));
    }
}

// The 4-component algebras are sliced by the hyperplane and its rotations; slice.origin and
// slice.axes would be ignored there, so a scene that gives them says more than it draws.
void onlyEightComponentSlicesTakeOriginAndAxes(const Scene& scene) {
    if (hasEightComponents(scene)) return;
    const SliceSettings& slice = scene.slice;
    const std::string algebra(algebraName(scene.fractal.algebra));
    for (const auto& [key, values] :
         {std::pair<const char*, const std::vector<double>*>{"slice.origin", &slice.origin},
          {"slice.axes", &slice.axes}})
        if (!values->empty())
            throw UserError(key, std::string(key) +
                                     " is for the 8-component algebras (biquaternion, "
                                     "octonion); " +
                                     algebra +
                                     " slices are set by slice.normal, slice.distance, "
                                     "slice.left, slice.right and slice.angles");
}

// The hyperplane slice.normal . q = slice.distance has no orientation without its normal.
void sliceNormalIsNotZero(const Scene& scene) {
    if (hasEightComponents(scene)) return;
    if (norm(scene.slice.normal) == 0)
        throw UserError("slice.normal", "slice.normal must not be zero");
}

// The 3D step of a marcher is the 4D distance times |s^_w| (docs/methods.md, Slices and the
// step factor), so a w component that is merely tiny would stall every ray; 1e-6 of the
// normal's length is the floor.
void sliceNormalHasAWComponent(const Scene& scene) {
    if (hasEightComponents(scene)) return;
    const SliceSettings& slice = scene.slice;
    if (std::abs(slice.normal[3]) < 1e-6 * norm(slice.normal))
        throw UserError("slice.normal",
                        "slice.normal needs a w component (the 4th): POV-Ray's slice computes "
                        "w = (distance - s.xyz) / s_w for each 3D point, so |s_w| must be at "
                        "least 1e-6 of the normal's length");
}

// slice.left and slice.right are divided by their length to make them unit quaternions; zero
// has no direction to keep.
void sliceLeftIsNotZero(const Scene& scene) {
    if (normSquared(scene.slice.left) == 0)
        throw UserError("slice.left", "slice.left must not be zero (it is made unit length)");
}

void sliceRightIsNotZero(const Scene& scene) {
    if (normSquared(scene.slice.right) == 0)
        throw UserError("slice.right", "slice.right must not be zero (it is made unit length)");
}

// Shading normalises the directions towards its lights: a zero vector points nowhere.
void keyLightHasADirection(const Scene& scene) {
    const ShadingSettings& shading = scene.shading;
    if (dot(shading.lightDirection, shading.lightDirection) == 0)
        throw UserError("shading.light_direction", "shading.light_direction must not be zero");
}

// A spot light shines along spot_target - light_position, which must be a direction.
void spotLightAimsAwayFromItself(const Scene& scene) {
    const ShadingSettings& shading = scene.shading;
    if (shading.lightKind == LightKind::Spot &&
        dot(shading.spotTarget - shading.lightPosition,
            shading.spotTarget - shading.lightPosition) == 0)
        throw UserError("shading.spot_target",
                        "shading.spot_target must differ from shading.light_position");
}

void fillLightHasADirection(const Scene& scene) {
    const ShadingSettings& shading = scene.shading;
    if (dot(shading.fillDirection, shading.fillDirection) == 0)
        throw UserError("shading.fill_direction", "shading.fill_direction must not be zero");
}

// Width, height and samples are each in range alone, but a render takes their product in
// samples: it is held to the largest image at 16 samples a pixel.
void samplesWithinTheLimit(const Scene& scene) {
    const RenderSettings& render = scene.render;
    constexpr int64_t kMaximumSamples = int64_t{16384} * 16384 * 16;
    int64_t total = int64_t{render.width} * render.height * render.samples;
    if (total > kMaximumSamples)
        throw UserError("render.samples",
                        "render.width * render.height * render.samples = " +
                            std::to_string(render.width) + " * " + std::to_string(render.height) +
                            " * " + std::to_string(render.samples) + " = " + std::to_string(total) +
                            " samples, more than the limit of " + std::to_string(kMaximumSamples) +
                            " (16384 * 16384 * 16); lower render.samples or the image size");
}

// The order is part of the behaviour: a scene that breaks several rules is told of the first, so
// moving a rule changes what such a scene is told.
constexpr std::array kSceneRules = {
    SceneRule{"every value is in its range", everyValueInRange},
    SceneRule{"the camera has a view direction", cameraHasAViewDirection},
    SceneRule{"camera.up is not along the view", upIsNotAlongTheView},
    SceneRule{"fractal.c has the algebra's number of components", constantFitsTheAlgebra},
    SceneRule{"8-component slices keep the quaternion slice keys at their defaults",
              eightComponentSlicesKeepTheQuaternionSliceKeys},
    SceneRule{"slice.axes are independent", sliceAxesAreIndependent},
    SceneRule{"only 8-component slices take slice.origin and slice.axes",
              onlyEightComponentSlicesTakeOriginAndAxes},
    SceneRule{"slice.normal is not zero", sliceNormalIsNotZero},
    SceneRule{"slice.normal has a w component", sliceNormalHasAWComponent},
    SceneRule{"slice.left is not zero", sliceLeftIsNotZero},
    SceneRule{"slice.right is not zero", sliceRightIsNotZero},
    SceneRule{"shading.light_direction is not zero", keyLightHasADirection},
    SceneRule{"a spot light aims away from itself", spotLightAimsAwayFromItself},
    SceneRule{"shading.fill_direction is not zero", fillLightHasADirection},
    SceneRule{"the total number of samples is within the limit", samplesWithinTheLimit},
};

}  // namespace

std::span<const SceneRule> sceneRules() {
    return kSceneRules;
}

void validateScene(const Scene& scene) {
    for (const SceneRule& rule : sceneRules())
        rule.check(scene);
}

}  // namespace quaternia
