#include "quaternia/dynamics/mandelbrot.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "quaternia/algebra/test_helpers.h"

namespace quaternia {
namespace {

using C = std::complex<double>;

TEST(Mandelbrot, BoundaryAndInteriorPointsAreMembers) {
    // -2: 0, -2, 2, 2, ...; 1/4: z_n rises slowly to the parabolic point 1/2; -3/4: converges
    // slowly to the parabolic point -1/2; i: 0, i, -1+i, -i, -1+i, ... is preperiodic.
    for (C c : {C(-2, 0), C(0.25, 0), C(-0.75, 0), C(0, 1), C(0, 0), C(-1, 0)})
        EXPECT_TRUE(inMandelbrotSet(c, 100000)) << c;
}

TEST(Mandelbrot, PointsOutsideEscape) {
    // 0.26 escapes after about pi / sqrt(0.01) = 31 steps through the parabolic gate.
    for (C c : {C(0.26, 0), C(-2.01, 0), C(1, 0), C(0, 1.01), C(-0.75, 0.1)})
        EXPECT_FALSE(inMandelbrotSet(c, 100000)) << c;
}

TEST(Mandelbrot, EscapeIterationAndEstimateAtKnownPoints) {
    MandelbrotEstimate e = estimateMandelbrot(C(1, 0), 100);
    EXPECT_FALSE(e.inside);
    EXPECT_EQ(e.escapeIteration, 3);  // 1, 2, 5: |5| > 2
    // M lies in |c| <= 2 and holds -2, so the distance from x < -2 to M is -2 - x. The estimate
    // is a lower bound near M, within the Koebe factor 4 of the distance.
    for (double x : {-2.05, -2.2, -2.5}) {
        double d = estimateMandelbrot(C(x, 0), 100000).distance;
        EXPECT_LE(d, -2 - x) << x;
        EXPECT_GE(d, (-2 - x) / 4) << x;
    }
    EXPECT_EQ(estimateMandelbrot(C(-1, 0), 1000).distance, 0);
}

TEST(Mandelbrot, SmoothCountIsContinuousWhereEscapeCountJumps) {
    double maxStep = 0;
    int jumps = 0;
    // Beyond the cusp 1/4 the orbit lingers near 1/2 for about pi / sqrt(c - 1/4) steps, so
    // the escape count falls from 14 to 1 along this segment.
    MandelbrotEstimate previous = estimateMandelbrot(C(0.3, 0), 1000);
    for (double x = 0.3; x <= 2.0; x += 1e-4) {
        MandelbrotEstimate e = estimateMandelbrot(C(x, 0), 1000);
        maxStep = std::max(maxStep, std::abs(e.smoothIteration - previous.smoothIteration));
        jumps += e.escapeIteration != previous.escapeIteration;
        previous = e;
    }
    EXPECT_GE(jumps, 10);
    EXPECT_LT(maxStep, 0.05);
}

TEST(Mandelbrot, MultibrotOfDegreeThree) {
    // M_3 meets the real axis in [-a, a], a = 2 / (3 sqrt 3) = 0.3849, where the fixed point
    // 1 / sqrt 3 turns parabolic: c = +-0.38 are members, c = 0.4 is not.
    EXPECT_TRUE(inMandelbrotSet(C(0.38, 0), 10000, 3));
    EXPECT_TRUE(inMandelbrotSet(C(-0.38, 0), 10000, 3));
    EXPECT_FALSE(inMandelbrotSet(C(0.4, 0), 10000, 3));
    EXPECT_TRUE(inMandelbrotSet(C(0, 1), 10000, 3));  // 0, i, 0, i, ...: i^3 + i = 0
}

TEST(Mandelbrot, QuaternionMembershipEqualsReducedComplexMembership) {
    std::mt19937 rng(7);
    int inside = 0, disagreements = 0;
    for (int n = 0; n < 3000; ++n) {
        Quaternion c = testing::randomQuaternion(rng, 1.2);
        c.w -= 0.5;
        bool quaternion = inQuaternionMandelbrotSet(c, 200);
        inside += quaternion;
        disagreements += quaternion != inMandelbrotSet(C(c.w, imaginaryNorm(c)), 200);
    }
    EXPECT_GT(inside, 50);
    EXPECT_EQ(disagreements, 0);
    EXPECT_TRUE(inQuaternionMandelbrotSet(Quaternion(-1, 0, 0, 0), 1000));
    EXPECT_TRUE(inQuaternionMandelbrotSet(testing::kJ, 1000));  // c = j behaves as c = i
    EXPECT_FALSE(inQuaternionMandelbrotSet(Quaternion(0, 0.8, 0.8, 0), 1000));
}

}  // namespace
}  // namespace quaternia
