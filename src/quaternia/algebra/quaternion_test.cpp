// Algebra identities of H (docs/facts.md, Algebra): Hamilton's table exactly, and the norm,
// conjugation and inverse laws on seeded random quaternions with explicit tolerances.
#include "quaternia/algebra/quaternion.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "quaternia/algebra/test_helpers.h"

namespace quaternia {
namespace {

using namespace quaternia::testing;

constexpr Quaternion kOne{1};

TEST(Quaternion, HamiltonProductTable) {
    // Exact: every product of basis elements is a signed basis element.
    EXPECT_EQ(kI * kI, -kOne);
    EXPECT_EQ(kJ * kJ, -kOne);
    EXPECT_EQ(kK * kK, -kOne);
    EXPECT_EQ(kI * kJ * kK, -kOne);
    EXPECT_EQ(kI * kJ, kK);
    EXPECT_EQ(kJ * kK, kI);
    EXPECT_EQ(kK * kI, kJ);
    EXPECT_EQ(kJ * kI, -kK);
    EXPECT_EQ(kK * kJ, -kI);
    EXPECT_EQ(kI * kK, -kJ);
}

TEST(Quaternion, RealNumbersAreCentral) {
    std::mt19937 rng(11);
    for (int n = 0; n < 100; ++n) {
        const Quaternion q = randomQuaternion(rng, 2.0);
        const Quaternion r{std::uniform_real_distribution<double>(-3, 3)(rng)};
        EXPECT_EQ(r * q, q * r);
        expectNear(r * q, q * r.w, 1e-15);
        EXPECT_EQ(kOne * q, q);
        EXPECT_EQ(q * kOne, q);
    }
}

TEST(Quaternion, ProductIsNotCommutative) {
    const Quaternion p{1, 2, 3, 4}, q{-0.5, 0.25, 1, -2};
    const Quaternion pq = p * q, qp = q * p;
    EXPECT_NE(pq, qp);
    // pq - qp = 2 (vp x vq): (2,3,4) x (0.25,1,-2) = (-10, 5, 1.25).
    expectNear(pq - qp, Quaternion{0, -20, 10, 2.5}, 1e-14);
}

TEST(Quaternion, NormIsMultiplicative) {
    std::mt19937 rng(1843);
    for (int n = 0; n < 1000; ++n) {
        const Quaternion p = randomQuaternion(rng, 2.0), q = randomQuaternion(rng, 2.0);
        const double expected = norm(p) * norm(q);
        EXPECT_NEAR(norm(p * q), expected, 1e-14 * (1 + expected));
    }
}

TEST(Quaternion, ConjugateReversesProducts) {
    std::mt19937 rng(7);
    for (int n = 0; n < 1000; ++n) {
        const Quaternion p = randomQuaternion(rng, 2.0), q = randomQuaternion(rng, 2.0);
        expectNear(conj(p * q), conj(q) * conj(p), 1e-14);
    }
}

TEST(Quaternion, InverseGivesOne) {
    std::mt19937 rng(42);
    for (int n = 0; n < 1000; ++n) {
        const Quaternion q = randomQuaternion(rng, 2.0);
        if (norm(q) < 1e-3) continue;
        expectNear(q * inverse(q), kOne, 1e-13);
        expectNear(inverse(q) * q, kOne, 1e-13);
    }
    EXPECT_EQ(inverse(kI), -kI);
}

TEST(Quaternion, SquareMatchesProduct) {
    std::mt19937 rng(3);
    for (int n = 0; n < 1000; ++n) {
        const Quaternion q = randomQuaternion(rng, 2.0);
        expectNear(square(q), q * q, 1e-14);
        // q^2 = (a^2 - |v|^2) + 2 a v (docs/facts.md, Algebra).
        const double v2 = q.x * q.x + q.y * q.y + q.z * q.z;
        EXPECT_NEAR(square(q).w, q.w * q.w - v2, 1e-14);
    }
}

TEST(Quaternion, TimesKMatchesPaperExample) {
    // q k = -z + y i - x j + w k for q = w + x i + y j + z k, so g(q k) = (-z, y, -x).
    const double w = 0.3, x = -1.25, y = 2.5, z = 0.75;
    const Quaternion qk = Quaternion{w, x, y, z} * kK;
    EXPECT_EQ(qk, (Quaternion{-z, y, -x, w}));
    EXPECT_EQ(qk.w, -z);
    EXPECT_EQ(qk.x, y);
    EXPECT_EQ(qk.y, -x);
}

TEST(Quaternion, ExpImaginaryIsUnitAndTurnsItsPlane) {
    const Quaternion u = normalize(Quaternion{0, 1, -2, 2});
    const double theta = 0.7;
    const Quaternion e = expImaginary(u, theta);
    EXPECT_NEAR(norm(e), 1, 1e-15);
    EXPECT_NEAR(e.w, std::cos(theta), 1e-15);
    expectNear(Quaternion{0, e.x, e.y, e.z}, u * std::sin(theta), 1e-15);
    // In C_u it multiplies like e^{i theta}: angles add, and exp(u pi/2) = u.
    expectNear(e * expImaginary(u, 0.4), expImaginary(u, 1.1), 1e-15);
    expectNear(expImaginary(u, std::numbers::pi / 2), u, 1e-15);
    // Left and right multiplication by e rotate span{1, u} by 2 theta: e 1 e = e^2.
    expectNear(e * kOne * e, expImaginary(u, 2 * theta), 1e-15);
}

TEST(Quaternion, HelpersAgreeWithDefinitions) {
    const Quaternion q{1, -2, 2, 4};
    EXPECT_EQ(normSquared(q), 25);
    EXPECT_EQ(norm(q), 5);
    EXPECT_EQ(realPart(q), 1);
    EXPECT_EQ(imaginaryNorm(Quaternion{7, 2, -3, 6}), 7);
    EXPECT_EQ(dot(q, Quaternion{1, 1, 1, 1}), 5);
    EXPECT_EQ(conj(q), (Quaternion{1, 2, -2, -4}));
    EXPECT_EQ(Quaternion(Quaternionf(q)), q);
    EXPECT_TRUE(isFinite(q));
    EXPECT_FALSE(isFinite(Quaternion{0, std::nan(""), 0, 0}));
}

}  // namespace
}  // namespace quaternia
