#include "quaternia/render/camera.h"

#include <gtest/gtest.h>

#include <random>

#include "quaternia/render/render.h"
#include "quaternia/scene/test_scenes.h"

namespace quaternia {
namespace {

CameraSettings referenceCamera() {
    return CameraSettings{{1, 1.5, -4}, {0, 0, 0}, {0, 1, 0}, 45};
}

// The two directions printed in the reference set's README, checked there pixel for pixel
// against POV-Ray.
TEST(Camera, MatchesPovRayCornerDirections) {
    Camera camera(referenceCamera(), 640, 480);
    Ray first = camera.generateRay(0.5, 0.5);
    EXPECT_NEAR(first.direction.x, -0.581735413, 1e-9);
    EXPECT_NEAR(first.direction.y, -0.044905681, 1e-9);
    EXPECT_NEAR(first.direction.z, 0.812137543, 1e-9);
    Ray last = camera.generateRay(639.5, 479.5);
    EXPECT_NEAR(last.direction.x, 0.176785375, 1e-9);
    EXPECT_NEAR(last.direction.y, -0.562519375, 1e-9);
    EXPECT_NEAR(last.direction.z, 0.807662605, 1e-9);
    EXPECT_EQ(first.origin, Point3d(1, 1.5, -4));
}

TEST(Camera, CentreRayLooksAtTarget) {
    Camera camera(referenceCamera(), 320, 240);
    Ray centre = camera.generateRay(160, 120);
    Vector3d expected = normalize(Vector3d(-1, -1.5, 4));
    EXPECT_NEAR(dot(centre.direction, expected), 1.0, 1e-12);
}

// The horizontal field of view spans exactly fov degrees between the left and right edges.
TEST(Camera, HorizontalFieldOfViewIsExact) {
    CameraSettings settings{{0, 0, -5}, {0, 0, 0}, {0, 1, 0}, 60};
    Camera camera(settings, 400, 100);
    Ray left = camera.generateRay(0, 50);
    Ray right = camera.generateRay(400, 50);
    double angle = std::acos(dot(left.direction, right.direction)) * 180 / 3.14159265358979;
    EXPECT_NEAR(angle, 60.0, 1e-9);
    // Left-handed: +x is to the right of the screen when looking along +z.
    EXPECT_LT(left.direction.x, 0);
    EXPECT_GT(right.direction.x, 0);
    EXPECT_NEAR(camera.pixelFootprint(5.0), 5.0 * 2 * std::tan(3.14159265358979 / 6) / 400, 1e-12);
}

}  // namespace
}  // namespace quaternia

namespace quaternia {
namespace {

TEST(Camera, ProjectInvertsGenerateRay) {
    Camera camera(referenceCamera(), 320, 240);
    for (auto [x, y] : {std::pair{0.5, 0.5}, {160.0, 120.0}, {319.5, 10.25}, {37.0, 201.0}}) {
        Ray ray = camera.generateRay(x, y);
        auto projected = camera.project(ray.at(3.7));
        ASSERT_TRUE(projected.has_value());
        EXPECT_NEAR((*projected)[0], x, 1e-9);
        EXPECT_NEAR((*projected)[1], y, 1e-9);
    }
    EXPECT_FALSE(camera.project(Point3d(1, 1.5, -4) - Point3d(0, 0, 1)).has_value());
}

}  // namespace
}  // namespace quaternia

namespace quaternia {
namespace {

// The thin lens (camera.aperture): every lens ray of an image point passes through the point
// where the pinhole ray meets the plane in focus (focus_distance along the view axis), and
// leaves from within the lens's disc, which lies across the view axis.
TEST(ThinLens, LensRaysMeetOnThePlaneInFocus) {
    CameraSettings settings{{1, 2, -5}, {0, 0, 0}, {0, 1, 0}, 40, 0.5, 3.5};
    const Camera camera(settings, 64, 48);
    const Vector3d forward = normalize(settings.lookAt - settings.position);
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> unit(0, 1);
    for (int i = 0; i < 200; ++i) {
        const double x = 64 * unit(rng), y = 48 * unit(rng);
        const Ray pinhole = camera.generateRay(x, y);
        const Point3d focus = pinhole.at(3.5 / dot(pinhole.direction, forward));
        const Ray lens = camera.generateRay(x, y, {unit(rng), unit(rng)});
        const Vector3d offset = lens.origin - settings.position;
        EXPECT_LE(length(offset), 0.25 + 1e-12);
        EXPECT_NEAR(dot(offset, forward), 0, 1e-12);
        const Vector3d toFocus = focus - lens.origin;
        EXPECT_NEAR(length(toFocus - lens.direction * dot(toFocus, lens.direction)), 0, 1e-9);
    }
    settings.aperture = 0;
    const Camera pinholeCamera(settings, 64, 48);
    const Ray a = pinholeCamera.generateRay(10, 20, {0.9, 0.1});
    const Ray b = pinholeCamera.generateRay(10, 20);
    EXPECT_EQ(a.origin, b.origin);
    EXPECT_EQ(a.direction, b.direction);
}

// The concentric map keeps area: as many of a grid's points fall in the inner disc of radius
// 1/sqrt(2) as outside it, and none beyond the unit circle.
TEST(ThinLens, LensPointKeepsArea) {
    int inner = 0, all = 0;
    for (int i = 0; i < 100; ++i) {
        for (int j = 0; j < 100; ++j) {
            const auto [u, v] = lensPoint({(i + 0.5) / 100, (j + 0.5) / 100});
            const double r2 = u * u + v * v;
            EXPECT_LE(r2, 1 + 1e-12);
            inner += r2 < 0.5;
            ++all;
        }
    }
    EXPECT_NEAR(inner, all / 2, all / 100);
}

// Depth of field on the unit ball seen from 4 units away: focused on its outline (whose points
// lie sqrt(15) away) the outline stays sharp; focused at 2 units it blurs into the circle of
// confusion, aperture |d - T| / d on the plane in focus: 0.2 x 1.87 / 3.87 = 0.097, 4.7 pixels
// there. The pixels of partial coverage along the centre row measure the blur's width.
TEST(ThinLens, OutlineBlursByTheCircleOfConfusion) {
    for (RenderEngine engine : {RenderEngine::Simd, RenderEngine::Scalar}) {
        auto blurredPixels = [&](double focus) {
            Scene scene = testing::unitBallScene(81, 81);
            scene.camera.position = {0, 0, -4};
            scene.camera.aperture = 0.2;
            scene.camera.focusDistance = focus;
            scene.render.samples = 64;
            scene.render.engine = engine;
            scene.shading.shadows = Shadows::None;
            scene.shading.ambientOcclusion = 0;
            const RenderResult result = render(scene);
            int partial = 0;
            for (int px = 0; px < 81; ++px) {
                const float alpha = result.image.at(px, 40).a;
                partial += alpha > 0.05f && alpha < 0.95f;
            }
            return partial;
        };
        const int sharp = blurredPixels(std::sqrt(15.0));
        const int blurred = blurredPixels(2);
        EXPECT_LE(sharp, 4);  // both sides of the ball
        // 4.7 pixels a side less the 5% at either end of the ramp: 4 to 5 of them.
        EXPECT_GE(blurred, 2 * 3);
        EXPECT_LE(blurred, 2 * 6);
    }
}

}  // namespace
}  // namespace quaternia
