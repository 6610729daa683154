#include "quaternia/fractal/slice.h"
#include "quaternia/algebra/test_helpers.h"

#include <gtest/gtest.h>

#include <random>

namespace quaternia {
namespace {

using namespace quaternia::testing;

SliceSettings defaultSlice() {
    return SliceSettings{Quaternion(0, 0, 0, 1), 0, Quaternion(1), Quaternion(1), {}, {}, {}};
}

TEST(Slice, DefaultSliceEmbedsXyzAsOneIJ) {
    Slice slice(defaultSlice());
    expectNear(slice.quaternionFromWorld({0.3, -0.7, 1.1}), Quaternion(0.3, -0.7, 1.1, 0));
    EXPECT_EQ(slice.stepScale(), 1);
}

// POV-Ray's slice: the normal is normalised, the distance is used as given, and the point lies
// on the hyperplane s^ . q = d.
TEST(Slice, TiltedSliceLiesOnThePovRayHyperplane) {
    SliceSettings settings = defaultSlice();
    settings.normal = Quaternion(0.2, -0.3, 0.4, 1);
    settings.distance = 0.15;
    Slice slice(settings);
    Quaternion unit = normalize(settings.normal);
    std::mt19937 rng(1);
    std::uniform_real_distribution<double> coordinate(-2, 2);
    for (int k = 0; k < 100; ++k) {
        Point3d p(coordinate(rng), coordinate(rng), coordinate(rng));
        Quaternion q = slice.quaternionFromWorld(p);
        EXPECT_NEAR(dot(q, unit), 0.15, 1e-12);
        EXPECT_EQ(q.w, p.x);
        EXPECT_EQ(q.x, p.y);
        EXPECT_EQ(q.y, p.z);
    }
    EXPECT_NEAR(slice.stepScale(), 1 / norm(settings.normal), 1e-15);
}

// The paper's view g(q k) (section 3.2.1) is left = 1, right = k^-1 = -k: the 3D point p shows
// the quaternion s(p) (-k), so that p = g(q k) for the q drawn there.
TEST(Slice, PaperViewRotatesHiddenDimensionIntoView) {
    SliceSettings settings = defaultSlice();
    settings.right = -kUnitK;
    Slice slice(settings);
    const double x = 0.3, y = -0.7, z = 1.1;
    Quaternion q = slice.quaternionFromWorld({x, y, z});
    expectNear(q, Quaternion(0, -z, y, -x));
    // and g(q k) recovers the point: q k = (x, y, z, 0).
    expectNear(q * kUnitK, Quaternion(x, y, z, 0));
}

// The tangents are the derivatives of the affine map p -> L s(p) R, tilt included.
TEST(Slice, TangentsAreDerivativesOfTheMap) {
    SliceSettings settings = defaultSlice();
    settings.normal = Quaternion(0.2, -0.3, 0.4, 1);
    settings.distance = 0.15;
    settings.left = Quaternion(0.9, 0.1, -0.3, 0.2);
    settings.right = Quaternion(0.5, 0.5, 0.1, -0.6);
    settings.anglesDegrees = {10, 20, 30, 40, 50, 60};
    Slice slice(settings);
    Point3d p(0.2, -0.4, 0.6);
    for (int axis = 0; axis < 3; ++axis) {
        Point3d shifted = p;
        shifted[axis] += 1;
        expectNear(slice.quaternionFromWorld(shifted) - slice.quaternionFromWorld(p),
                   slice.quaternionTangents()[axis], 1e-12);
        // A 3D step of length 1 moves the quaternion by at most 1 / stepScale.
        EXPECT_LE(norm(slice.quaternionTangents()[axis]), 1 / slice.stepScale() + 1e-12);
    }
}

TEST(Slice, PlaneAnglesTurnTheNamedPlaneOnly) {
    // (1, i) by 90 degrees: 1 -> i, j and k fixed.
    auto [l, r] = rotationFromPlaneAngles({90, 0, 0, 0, 0, 0});
    expectNear(l * Quaternion(1) * r, kUnitI);
    expectNear(l * kUnitJ * r, kUnitJ);
    expectNear(l * kUnitK * r, kUnitK);
    // (j, k) by 90 degrees: j -> k, 1 and i fixed.
    auto [l2, r2] = rotationFromPlaneAngles({0, 0, 0, 0, 0, 90});
    expectNear(l2 * kUnitJ * r2, kUnitK);
    expectNear(l2 * Quaternion(1) * r2, Quaternion(1));
    expectNear(l2 * kUnitI * r2, kUnitI);
    // (i, k) by 90 degrees: i -> k.
    auto [l3, r3] = rotationFromPlaneAngles({0, 0, 0, 0, 90, 0});
    expectNear(l3 * kUnitI * r3, kUnitK);
    expectNear(l3 * kUnitJ * r3, kUnitJ);
    // (1, k) by 90 degrees: 1 -> k.
    auto [l4, r4] = rotationFromPlaneAngles({0, 0, 90, 0, 0, 0});
    expectNear(l4 * Quaternion(1) * r4, kUnitK);
    expectNear(l4 * kUnitI * r4, kUnitI);
}

TEST(Slice, RotationIsAnIsometry) {
    SliceSettings settings = defaultSlice();
    settings.left = Quaternion(0.9, 0.1, -0.3, 0.2);
    settings.right = Quaternion(0.5, 0.5, 0.1, -0.6);
    settings.anglesDegrees = {15, -25, 35, 45, -55, 65};
    Slice slice(settings);
    std::mt19937 rng(2);
    std::uniform_real_distribution<double> coordinate(-2, 2);
    for (int k = 0; k < 100; ++k) {
        Point3d a(coordinate(rng), coordinate(rng), coordinate(rng));
        Point3d b(coordinate(rng), coordinate(rng), coordinate(rng));
        EXPECT_NEAR(norm(slice.quaternionFromWorld(a) - slice.quaternionFromWorld(b)),
                    length(a - b), 1e-12);
    }
}

}  // namespace
}  // namespace quaternia
