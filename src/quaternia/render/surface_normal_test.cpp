#include "quaternia/fractal/fractal.h"

#include <gtest/gtest.h>

#include <random>

#include "quaternia/render/camera.h"
#include "quaternia/render/march.h"
#include "quaternia/scene/parameters.h"
#include "quaternia/scene/scene_fractal.h"
#include "quaternia/scene/test_scenes.h"

namespace quaternia {
namespace {

// The analytic normal (one pass through the Jacobians, tilt and rotation included) agrees with
// central differences of the potential at surface points found by sphere tracing.
void expectNormalsAgree(const Scene& scene, double minimumCosine) {
    Fractal fractal = fractalFromScene(scene);
    Camera camera(scene.camera, 160, 120);
    MarchSettings settings;
    settings.pixelAngle = camera.pixelFootprint(1);
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> x(0, 160), y(0, 120);
    int compared = 0, agreeing = 0;
    while (compared < 200) {
        MarchResult result = march(fractal, camera.generateRay(x(rng), y(rng)), settings);
        if (!result.hit || result.hit->estimate.inside) continue;
        Point3d p = result.hit->outside;
        Vector3d analytic = fractal.normal(p);
        Vector3d numeric = fractal.normalByDifferences(p, 1e-6);
        ++compared;
        agreeing += dot(analytic, numeric) > minimumCosine;
    }
    EXPECT_EQ(agreeing, compared) << scene.fractal.formula;
}

TEST(Fractal, AnalyticNormalMatchesDifferences) {
    expectNormalsAgree(testing::referenceScene("case01_sqr_A"), 0.99);
}

TEST(Fractal, AnalyticNormalMatchesDifferencesOnRotatedTiltedSlice) {
    Scene scene = testing::referenceScene("case06_sqr_A_tilt");
    scene.slice.left = Quaternion(0.9, 0.1, -0.3, 0.2);
    scene.slice.right = Quaternion(0.5, 0.5, 0.1, -0.6);
    expectNormalsAgree(scene, 0.99);
}

TEST(Fractal, AnalyticNormalMatchesDifferencesForTwoSidedPolynomial) {
    Scene scene = testing::referenceScene("case01_sqr_A");
    scene.fractal.formula = "(1+0.5i) z (0.8-0.3k) z + c";
    scene.fractal.c = Quaternion(-0.3, 0.4, 0.1, 0);
    scene.fractal.bailout = 0;
    expectNormalsAgree(scene, 0.99);
}

}  // namespace
}  // namespace quaternia
