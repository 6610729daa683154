#include "quaternia/render/camera.h"

#include <gtest/gtest.h>

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
