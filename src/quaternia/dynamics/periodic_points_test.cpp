#include "quaternia/dynamics/periodic_points.h"

#include <gtest/gtest.h>

#include "quaternia/algebra/formula.h"
#include "quaternia/algebra/test_helpers.h"

namespace quaternia {
namespace {

ComplexPolynomial quadratic(Complex c) {
    return ComplexPolynomial({c, 0, 1});
}

void expectNear(Complex actual, Complex expected, double tolerance) {
    EXPECT_NEAR(std::abs(actual - expected), 0, tolerance) << actual << " vs " << expected;
}

TEST(PeriodicPoints, CountsPointsOfExactPeriod) {
    EXPECT_EQ(periodicPointCount(2, 1), 2);
    EXPECT_EQ(periodicPointCount(2, 2), 2);
    EXPECT_EQ(periodicPointCount(2, 3), 6);
    EXPECT_EQ(periodicPointCount(2, 4), 12);
    EXPECT_EQ(periodicPointCount(2, 6), 54);  // 64 - 8 - 4 + 2
    EXPECT_EQ(periodicPointCount(3, 2), 6);
}

TEST(PeriodicPoints, FixedPointsAndTwoCycleOfMinusOne) {
    // docs/facts.md, Cycles and multipliers of z^2 + c: fixed points 1.61803 (multiplier 3.23607)
    // and -0.61803 (-1.23607), both repelling; the superattracting 2-cycle {0, -1}.
    PeriodicPoints fixed = periodicPoints(quadratic(-1), 1);
    ASSERT_EQ(fixed.cycles.size(), 2u);
    const double phi = (1 + std::sqrt(5.0)) / 2;
    expectNear(fixed.cycles[0].points[0], phi, 1e-14);
    expectNear(fixed.cycles[1].points[0], 1 - phi, 1e-14);
    expectNear(fixed.cycles[0].multiplier, 2 * phi, 1e-13);
    expectNear(fixed.cycles[1].multiplier, 2 - 2 * phi, 1e-13);
    for (const PeriodicCycle& cycle : fixed.cycles) {
        EXPECT_EQ(cycle.classification.stability, Stability::Repelling);
        EXPECT_EQ(cycle.period, 1);
        EXPECT_LT(cycle.residual, 1e-14);
    }
    PeriodicPoints two = periodicPoints(quadratic(-1), 2);
    ASSERT_EQ(two.cycles.size(), 1u);
    const PeriodicCycle& cycle = two.cycles[0];
    ASSERT_EQ(cycle.points.size(), 2u);
    expectNear(cycle.points[0], 0, 1e-14);
    expectNear(cycle.points[1], -1, 1e-14);
    EXPECT_LT(std::abs(cycle.multiplier), 1e-13);
    EXPECT_EQ(cycle.classification.stability, Stability::Superattracting);
    EXPECT_FALSE(cycle.degenerate);
    EXPECT_TRUE(cycle.complete);
}

TEST(PeriodicPoints, RepellingTwoCycleOfI) {
    // {-1+i, -i} with multiplier 4(c + 1) = 4 + 4i (docs/facts.md, Cycles and multipliers of
    // z^2 + c).
    PeriodicPoints two = periodicPoints(quadratic(Complex(0, 1)), 2);
    ASSERT_EQ(two.cycles.size(), 1u);
    const PeriodicCycle& cycle = two.cycles[0];
    expectNear(cycle.points[0], Complex(0, -1), 1e-14);
    expectNear(cycle.points[1], Complex(-1, 1), 1e-14);
    expectNear(cycle.multiplier, Complex(4, 4), 1e-12);
    EXPECT_EQ(cycle.classification.stability, Stability::Repelling);
}

TEST(PeriodicPoints, RabbitHasOneSuperattracting3Cycle) {
    const Complex c(-0.12256116687665, 0.74486176661974);
    PeriodicPoints three = periodicPoints(quadratic(c), 3);
    EXPECT_EQ(three.count, 6);
    ASSERT_EQ(three.cycles.size(), 2u);
    int superattracting = 0;
    for (const PeriodicCycle& cycle : three.cycles) {
        ASSERT_EQ(cycle.points.size(), 3u);
        if (cycle.classification.stability != Stability::Superattracting) {
            EXPECT_EQ(cycle.classification.stability, Stability::Repelling);
            continue;
        }
        ++superattracting;
        expectNear(cycle.points[0], 0, 1e-12);
        expectNear(cycle.points[1], c, 1e-12);
        expectNear(cycle.points[2], c * c + c, 1e-12);
    }
    EXPECT_EQ(superattracting, 1);
}

TEST(PeriodicPoints, ParabolicParametersGiveMultipleAndCollapsedCycles) {
    // c = 1/4: the double fixed point 1/2 with multiplier 1.
    PeriodicPoints quarter = periodicPoints(quadratic(0.25), 1);
    ASSERT_EQ(quarter.cycles.size(), 1u);
    EXPECT_EQ(quarter.cycles[0].multiplicity, 2);
    // The centroid of the cluster of two roots is more accurate than either root (1e-7).
    expectNear(quarter.cycles[0].points[0], 0.5, 1e-8);
    expectNear(quarter.cycles[0].multiplier, 1, 1e-8);
    EXPECT_EQ(quarter.cycles[0].classification.stability, Stability::Neutral);
    // c = -3/4: fixed points 3/2 and -1/2 (multiplier -1, neutral); the period-2 points
    // coincide with -1/2.
    PeriodicPoints fixed = periodicPoints(quadratic(-0.75), 1);
    ASSERT_EQ(fixed.cycles.size(), 2u);
    expectNear(fixed.cycles[1].points[0], -0.5, 1e-15);
    EXPECT_EQ(fixed.cycles[1].multiplier, Complex(-1));
    EXPECT_EQ(fixed.cycles[1].classification.stability, Stability::Neutral);
    PeriodicPoints two = periodicPoints(quadratic(-0.75), 2);
    ASSERT_EQ(two.cycles.size(), 1u);
    EXPECT_TRUE(two.cycles[0].degenerate);
    EXPECT_EQ(two.cycles[0].period, 1);
    // Collapsed: the centroid of the cluster, polished by Newton on f(z) = z.
    expectNear(two.cycles[0].points[0], -0.5, 1e-15);
    expectNear(two.cycles[0].multiplier, 1, 1e-14);  // (-1)^2
    EXPECT_EQ(two.cycles[0].classification.stability, Stability::Neutral);
}

TEST(PeriodicPoints, EveryPointOfPeriod8IsFoundOnce) {
    // 240 points of exact period 8 of z^2 - 1 in 30 cycles, all repelling except none:
    // the only attracting cycle of c = -1 has period 2.
    ComplexPolynomial f = quadratic(-1);
    PeriodicPoints eight = periodicPoints(f, 8);
    EXPECT_EQ(eight.count, 240);
    ASSERT_EQ(eight.cycles.size(), 30u);
    for (const PeriodicCycle& cycle : eight.cycles) {
        EXPECT_TRUE(cycle.complete);
        EXPECT_EQ(cycle.period, 8);
        EXPECT_LT(cycle.residual, 1e-9);
        EXPECT_EQ(cycle.classification.stability, Stability::Repelling);
        // Exact period 8: f^4(z) != z.
        Complex z = cycle.points[0];
        for (int k = 0; k < 4; ++k)
            z = f.evaluate(z);
        EXPECT_GT(std::abs(z - cycle.points[0]), 1e-6);
    }
}

TEST(PeriodicPoints, CubicMapTwoCycles) {
    // z^3 + c has 9 - 3 = 6 points of period 2, in 3 cycles; multiplier = 9 z1^2 z2^2.
    ComplexPolynomial f({Complex(0.1, 0.2), 0, 0, 1});
    PeriodicPoints two = periodicPoints(f, 2);
    ASSERT_EQ(two.cycles.size(), 3u);
    for (const PeriodicCycle& cycle : two.cycles) {
        Complex a = cycle.points[0], b = cycle.points[1];
        expectNear(f.evaluate(a), b, 1e-13);
        expectNear(f.evaluate(b), a, 1e-13);
        expectNear(cycle.multiplier, 9.0 * a * a * b * b, 1e-12);
    }
}

TEST(PeriodicPoints, RefusesPeriodsOutOfRange) {
    EXPECT_EQ(testing::thrownError([] { periodicPoints(quadratic(-1), 0); }).key(), "period");
    EXPECT_EQ(testing::thrownError([] { periodicPoints(quadratic(-1), 11); }).key(), "period");
    EXPECT_EQ(testing::thrownError([] {
                  periodicPoints(ComplexPolynomial({1, 0, 0, 1}), 7);
              }).key(),
              "period");  // 3^7 > 1024
    EXPECT_EQ(testing::thrownError([] {
                  periodicPoints(ComplexPolynomial({1, 2}), 1);
              }).key(),
              "period");
}

}  // namespace
}  // namespace quaternia
