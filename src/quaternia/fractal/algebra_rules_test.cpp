// The table of per-algebra rules against the algebras themselves: each row's claims follow from
// its multiplication table (hypercomplex.h), so a new row cannot claim an estimate its algebra
// does not support.
#include "quaternia/fractal/algebra_rules.h"
#include "quaternia/fractal/distance.h"
#include "quaternia/fractal/fractal.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace quaternia {
namespace {

Hypercomplex randomElement(std::mt19937& random, int dimension) {
    std::uniform_real_distribution<double> uniform(-1, 1);
    Hypercomplex a{};
    for (int n = 0; n < dimension; ++n)
        a[size_t(n)] = uniform(random);
    return a;
}

TEST(AlgebraRules, EveryAlgebraHasItsOwnRow) {
    for (Algebra algebra : allAlgebras())
        EXPECT_EQ(algebraRules(algebra).algebra, algebra) << algebraName(algebra);
    EXPECT_TRUE(algebraRules(Algebra::kQuaternion).quaternionSet);
    for (Algebra algebra : allAlgebras()) {
        if (algebra != Algebra::kQuaternion) {
            EXPECT_FALSE(algebraRules(algebra).quaternionSet);
        }
    }
}

// An escape radius from the top-degree part needs |ab| = |a| |b|; the escape-time estimate
// needs an escape radius, so every row with an estimate has one of the two escape rules that
// provide it, and only rows of multiplicative norms claim the first.
TEST(AlgebraRules, MultiplicativeEscapeOnlyWhereTheNormIsMultiplicative) {
    std::mt19937 random(7);
    for (Algebra algebra : allAlgebras()) {
        const AlgebraRules& rules = algebraRules(algebra);
        const MultiplicationTable& table = MultiplicationTable::of(algebra);
        double worst = 0;
        for (int trial = 0; trial < 200; ++trial) {
            const Hypercomplex a = randomElement(random, table.dimension());
            const Hypercomplex b = randomElement(random, table.dimension());
            worst = std::max(worst, std::abs(euclideanNorm(table.multiply(a, b)) -
                                             euclideanNorm(a) * euclideanNorm(b)));
        }
        const bool multiplicative = worst < 1e-12;
        EXPECT_EQ(rules.escape == EscapeRule::kMultiplicativeNorm, multiplicative)
            << algebraName(algebra) << ": largest |ab| - |a||b| " << worst;
        // The arithmetic's own row (hypercomplex.h) says the same.
        EXPECT_EQ(algebraArithmetic(algebra).multiplicativeNorm, multiplicative)
            << algebraName(algebra);
        if (rules.distance == DistanceKind::kEstimate) {
            EXPECT_NE(rules.escape, EscapeRule::kNone) << algebraName(algebra);
        }
        if (rules.escape == EscapeRule::kMultiplicativeNorm) {
            EXPECT_EQ(rules.defaultBailout, 0) << "the certified radius is the bailout";
        }
    }
}

// No radius is certain where the algebra has null elements (a b = 0 with a, b != 0): an orbit
// may fall onto one and shrink from any size. Coquaternions: (1 + j)(1 - j) = 1 - j^2 = 0;
// biquaternions: (1 + i h)(1 - i h) = 1 - i^2 h^2 = 0.
TEST(AlgebraRules, NoEscapeRuleWhereNullElementsExist) {
    auto nullProduct = [](Algebra algebra, const Hypercomplex& a, const Hypercomplex& b) {
        return euclideanNorm(MultiplicationTable::of(algebra).multiply(a, b));
    };
    const Hypercomplex onePlusJ{1, 0, 1, 0, 0, 0, 0, 0}, oneMinusJ{1, 0, -1, 0, 0, 0, 0, 0};
    EXPECT_EQ(nullProduct(Algebra::kCoquaternion, onePlusJ, oneMinusJ), 0);
    EXPECT_EQ(algebraRules(Algebra::kCoquaternion).escape, EscapeRule::kNone);
    const Hypercomplex onePlusIh{1, 0, 0, 0, 0, 1, 0, 0}, oneMinusIh{1, 0, 0, 0, 0, -1, 0, 0};
    EXPECT_EQ(nullProduct(Algebra::kBiquaternion, onePlusIh, oneMinusIh), 0);
    EXPECT_EQ(algebraRules(Algebra::kBiquaternion).escape, EscapeRule::kNone);
    for (Algebra algebra : allAlgebras()) {
        if (algebraRules(algebra).escape == EscapeRule::kNone) {
            EXPECT_EQ(algebraRules(algebra).distance, DistanceKind::kLipschitz);
        }
    }
}

// The duplex form is an isomorphism onto C x C only for a commutative algebra; the fold onto
// the quaternions only for the octonions' real forms.
TEST(AlgebraRules, DuplexFormOnlyForTheCommutativeAlgebra) {
    std::mt19937 random(11);
    for (Algebra algebra : allAlgebras()) {
        const MultiplicationTable& table = MultiplicationTable::of(algebra);
        bool commutative = true;
        for (int trial = 0; trial < 50 && commutative; ++trial) {
            const Hypercomplex a = randomElement(random, table.dimension());
            const Hypercomplex b = randomElement(random, table.dimension());
            const Hypercomplex ab = table.multiply(a, b), ba = table.multiply(b, a);
            for (int n = 0; n < table.dimension(); ++n)
                commutative = commutative && std::abs(ab[size_t(n)] - ba[size_t(n)]) < 1e-12;
        }
        EXPECT_EQ(algebraRules(algebra).duplexForm, commutative) << algebraName(algebra);
        EXPECT_EQ(algebraRules(algebra).foldsOntoQuaternions, algebra == Algebra::kOctonion);
    }
}

}  // namespace
}  // namespace quaternia

namespace quaternia {
namespace {

// An octonion scene in the quaternion subalgebra generated by i and e4 (fractal.cpp,
// octonionQuaternionSubalgebra) is drawn as a quaternion set whose estimates are the octonion
// set's at every point of the slice; a c with a part outside that subalgebra keeps the octonions.
TEST(QuaternionSubalgebra, OctonionSceneInTheSubalgebraOfIAndE4IsAQuaternionSet) {
    FractalSettings fractal;
    fractal.algebra = Algebra::kOctonion;
    fractal.formula = "(i z) (z i) + 0.1i z + c";
    fractal.c = Quaternion(-0.2, 0.6, 0, 0);
    fractal.cUpper = {0.2, 0.2, 0, 0};
    fractal.cComponents = 8;
    fractal.maxIterations = 12;
    SliceSettings slice;
    slice.origin.assign(8, 0.0);
    slice.axes.assign(24, 0.0);
    slice.axes[0] = slice.axes[8 + 1] = slice.axes[16 + 4] = 1;
    const Fractal fast = Fractal::fromSettings(fractal, slice, QuaternionPaths::kWherePossible);
    const Fractal reference = Fractal::fromSettings(fractal, slice, QuaternionPaths::kNever);
    ASSERT_NE(fast.setAs<QuaternionJuliaSet>(), nullptr);
    ASSERT_EQ(reference.setAs<QuaternionJuliaSet>(), nullptr);
    std::mt19937 random(7);
    std::uniform_real_distribution<double> coordinate(-1.5, 1.5);
    int inside = 0;
    for (int n = 0; n < 2000; ++n) {
        const Point3d p(coordinate(random), coordinate(random), coordinate(random));
        const DistanceEstimate a = fast.estimate(p), b = reference.estimate(p);
        ASSERT_EQ(a.inside, b.inside) << p[0] << " " << p[1] << " " << p[2];
        EXPECT_EQ(a.escapeIteration, b.escapeIteration);
        EXPECT_NEAR(a.distance, b.distance, 1e-9 * (1 + b.distance));
        inside += a.inside;
    }
    EXPECT_GT(inside, 20);
    fractal.cUpper[2] = 0.05;  // e6: outside span{1, i, e4, e5}
    EXPECT_EQ(Fractal::fromSettings(fractal, slice, QuaternionPaths::kWherePossible)
                  .setAs<QuaternionJuliaSet>(),
              nullptr);
}

}  // namespace
}  // namespace quaternia
