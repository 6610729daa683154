#include "quaternia/render/shade.h"

#include <gtest/gtest.h>

#include <utility>
#include <vector>

#include "quaternia/render/camera.h"
#include "quaternia/scene/parameters.h"
#include "quaternia/scene/scene_fractal.h"
#include "quaternia/scene/test_scenes.h"

namespace quaternia {
namespace {

struct UnitBall {
    Scene scene = testing::unitBallScene(16, 16);
    Fractal fractal = fractalFromScene(scene);
};

TEST(Shader, BackgroundIsVerticalGradient) {
    UnitBall ball;
    ball.scene.shading.backgroundTop = {0, 0, 1};
    ball.scene.shading.backgroundBottom = {1, 0, 0};
    Shader shader(ball.scene.shading, ball.fractal);
    EXPECT_EQ(shader.background(Ray{{}, {0, 1, 0}}), Color(0, 0, 1));
    EXPECT_EQ(shader.background(Ray{{}, {0, -1, 0}}), Color(1, 0, 0));
    EXPECT_EQ(shader.background(Ray{{}, {1, 0, 0}}), Color(0.5, 0, 0.5));
}

// The row form (SIMD, float) gives every pixel centre's background() of the camera's ray, for
// rows and spans that are not multiples of the vector length, with the alpha asked for.
TEST(Shader, BackgroundRowMatchesThePixelsRays) {
    UnitBall ball;
    ball.scene.shading.backgroundTop = {0.2, 0.5, 1};
    ball.scene.shading.backgroundBottom = {1, 0.1, 0};
    Shader shader(ball.scene.shading, ball.fractal);
    CameraSettings settings = ball.scene.camera;
    settings.position = {0.7, 1.9, -4};
    const Camera camera(settings, 101, 37);
    std::vector<Rgba> row(101);
    for (int py : {0, 18, 36}) {
        for (auto [x0, count] : {std::pair{0, 101}, std::pair{3, 23}, std::pair{97, 4}}) {
            const Camera::RowDirections directions = camera.rowDirections(py);
            shader.backgroundRow(directions.first, directions.step, x0, count, 0.25f, row.data());
            for (int i = 0; i < count; ++i) {
                const Color expected =
                    shader.background(camera.generateRay(x0 + i + 0.5, py + 0.5));
                EXPECT_NEAR(row[i].r, expected.x, 1e-5) << py << " " << x0 + i;
                EXPECT_NEAR(row[i].g, expected.y, 1e-5) << py << " " << x0 + i;
                EXPECT_NEAR(row[i].b, expected.z, 1e-5) << py << " " << x0 + i;
                EXPECT_EQ(row[i].a, 0.25f);
            }
        }
    }
}

TEST(Shader, DisplayAppliesExposureClampAndGamma) {
    UnitBall ball;
    ball.scene.shading.gamma = 2;
    ball.scene.shading.exposure = 4;
    Shader shader(ball.scene.shading, ball.fractal);
    Color display = shader.toDisplay({0.0625, 1, -1});
    EXPECT_DOUBLE_EQ(display.x, 0.5);  // (0.0625 * 4)^(1/2)
    EXPECT_DOUBLE_EQ(display.y, 1);
    EXPECT_DOUBLE_EQ(display.z, 0);
}

// The unit ball lit from above: a point under it is in its shadow, points beside or above it
// see the light.
TEST(Shader, ShadowOfTheUnitBall) {
    UnitBall ball;
    ball.scene.shading.lightDirection = {0, 1, 0};
    for (Shadows mode : {Shadows::Hard, Shadows::Soft}) {
        ball.scene.shading.shadows = mode;
        Shader shader(ball.scene.shading, ball.fractal);
        ShadingStats stats;
        EXPECT_EQ(shader.shadow({0, -1.05, 0}, shader.keyLight({0, -1.05, 0}), stats), 0);
        EXPECT_EQ(shader.shadow({0, 1.05, 0}, shader.keyLight({0, 1.05, 0}), stats), 1);
        EXPECT_GT(stats.estimates, 0);
    }
    // Grazing past the ball's edge: a penumbra between the two. With bailout 2 the bounding
    // sphere is larger than the ball (K_30 is the unit ball to within 1e-9), so the shadow ray
    // is marched.
    ball.scene.fractal.bailout = 2;
    ball.fractal = fractalFromScene(ball.scene);
    ball.scene.shading.shadows = Shadows::Soft;
    Shader soft(ball.scene.shading, ball.fractal);
    ShadingStats stats;
    double penumbra = soft.shadow({1.02, -1.0, 0}, soft.keyLight({1.02, -1.0, 0}), stats);
    EXPECT_GT(penumbra, 0);
    EXPECT_LT(penumbra, 1);
    ball.scene.shading.shadows = Shadows::None;
    const Shader unshadowed(ball.scene.shading, ball.fractal);
    EXPECT_EQ(unshadowed.shadow({0, -1.05, 0}, unshadowed.keyLight({0, -1.05, 0}), stats), 1);
}

// On the convex unit ball nothing occludes the open side.
TEST(Shader, ConvexSurfaceIsUnoccluded) {
    UnitBall ball;
    Shader shader(ball.scene.shading, ball.fractal);
    ShadingStats stats;
    EXPECT_GT(shader.ambientOcclusion({0, 0, -1.0001}, {0, 0, -1}, stats), 0.95);
}

TEST(Shader, AlbedoFollowsColoringMode) {
    UnitBall ball;
    ball.scene.shading.baseColor = {1, 0, 0};
    ball.scene.shading.accentColor = {0, 0, 1};
    DistanceEstimate nearZero, farOut;
    nearZero.trap = 0;
    farOut.trap = ball.fractal.set().escapeRadius();
    ball.scene.shading.coloring = Coloring::OrbitTrap;
    Shader trap(ball.scene.shading, ball.fractal);
    EXPECT_EQ(trap.albedo(nearZero), Color(0, 0, 1));
    EXPECT_EQ(trap.albedo(farOut), Color(1, 0, 0));
    ball.scene.shading.coloring = Coloring::Solid;
    EXPECT_EQ(Shader(ball.scene.shading, ball.fractal).albedo(nearZero), Color(1, 0, 0));
}

// Lambert: the side facing the key light is brighter than the side facing away.
TEST(Shader, LitSideIsBrighter) {
    UnitBall ball;
    ball.scene.shading.lightDirection = {0, 1, 0};
    Shader shader(ball.scene.shading, ball.fractal);
    ShadingStats stats;
    auto shadeAt = [&](const Point3d& p) {
        Hit hit{0, p, p, ball.fractal.estimate(p)};
        Ray ray{p * 3.0, -normalize(p)};
        Color c = shader.shade(hit, ray, 1e-3, stats);
        return c.x + c.y + c.z;
    };
    EXPECT_GT(shadeAt({0, 1.0001, 0}), 2 * shadeAt({0, -1.0001, 0}));
}

}  // namespace
}  // namespace quaternia
