#include "quaternia/dynamics/cycle.h"

#include <gtest/gtest.h>

#include "quaternia/algebra/formula.h"

namespace quaternia {
namespace {

using Complex = std::complex<double>;

void expectNear(Complex actual, Complex expected, double tolerance) {
    EXPECT_NEAR(std::abs(actual - expected), 0, tolerance) << actual << " vs " << expected;
}

TEST(Cycle, ClassifiesMultipliersWithTolerance) {
    EXPECT_EQ(classifyMultiplier(0).stability, Stability::Superattracting);
    EXPECT_EQ(classifyMultiplier(1e-12).stability, Stability::Superattracting);
    EXPECT_EQ(classifyMultiplier(Complex(0.3, 0.4)).stability, Stability::Attracting);
    EXPECT_EQ(classifyMultiplier(-1).stability, Stability::Neutral);
    EXPECT_EQ(classifyMultiplier(std::polar(1.0 + 1e-12, 2.0)).stability, Stability::Neutral);
    EXPECT_EQ(classifyMultiplier(Complex(4, 4)).stability, Stability::Repelling);
    EXPECT_FALSE(classifyMultiplier(Complex(4, 4)).unsure);
    // Within the unsure band of 1 but outside the tolerance: classified, and flagged.
    Classification close = classifyMultiplier(1 - 1e-8);
    EXPECT_EQ(close.stability, Stability::Attracting);
    EXPECT_TRUE(close.unsure);
    EXPECT_TRUE(classifyMultiplier(1e-7).unsure);
}

TEST(Cycle, ClassifiesEigenvaluesInH) {
    EXPECT_EQ(classifyEigenvalues({0, 0, 0, 0}).stability, Stability::Superattracting);
    EXPECT_EQ(classifyEigenvalues({0.5, 0.5, 0.5, 0.5}).stability, Stability::Attracting);
    EXPECT_EQ(classifyEigenvalues({2, 2, 1.5, 1.5}).stability, Stability::Repelling);
    EXPECT_EQ(
        classifyEigenvalues({Complex(-0.6, 1.25), Complex(-0.6, -1.25), -0.6, -0.6}).stability,
        Stability::Saddle);
    EXPECT_EQ(classifyEigenvalues({-1, -1, 0.5, 0.5}).stability, Stability::Neutral);
    Classification weak = classifyEigenvalues({3, 3, 1, 1});
    EXPECT_EQ(weak.stability, Stability::Repelling);
    EXPECT_TRUE(weak.unsure);
}

TEST(Cycle, EigenvaluesOfCompanionMatrix) {
    // Companion matrix of z^4 + z^3 - z^2 + z - 2 = (z - 1)(z + 2)(z - i)(z + i).
    Matrix4 companion{{{-1, 1, -1, 2}, {1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}}};
    auto e = eigenvalues(companion);
    expectNear(e[0], -2, 1e-13);
    // |1| = |i| = |-i|: ordered by real part, then imaginary part.
    expectNear(e[1], 1, 1e-13);
    expectNear(e[2], Complex(0, 1), 1e-13);
    expectNear(e[3], Complex(0, -1), 1e-13);
}

TEST(Cycle, EigenvaluesAndSolveOf8x8BlockMatrix) {
    // The companion matrix above, similarity-mixed with a second block diag(3, -0.5, 0.25 +-
    // 0.5 i) (a rotation-scaling block): eigenvalues of both blocks, sorted as for 4x4.
    Matrix8 m{};
    const Matrix4 companion{{{-1, 1, -1, 2}, {1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}}};
    for (size_t i = 0; i < 4; ++i)
        for (size_t j = 0; j < 4; ++j)
            m[i][j] = companion[i][j];
    m[4][4] = 3, m[5][5] = -0.5, m[6][6] = 0.25, m[6][7] = -0.5, m[7][6] = 0.5, m[7][7] = 0.25;
    // A shear between the blocks keeps the eigenvalues (block triangular).
    m[0][5] = 0.7, m[2][6] = -1.1;
    auto e = eigenvalues(m);
    const std::array<Complex, 8> expected = {
        3, -2, 1, Complex(0, 1), Complex(0, -1), Complex(0.25, 0.5), Complex(0.25, -0.5), -0.5};
    for (size_t k = 0; k < 8; ++k)
        expectNear(e[k], expected[k], 1e-12);
    std::array<double, 8> x{}, b{};
    for (size_t i = 0; i < 8; ++i)
        for (size_t j = 0; j < 8; ++j)
            b[i] += m[i][j];  // m (1, ..., 1)
    ASSERT_TRUE(solve(m, b, x));
    for (double v : x)
        EXPECT_NEAR(v, 1, 1e-13);
}

TEST(Cycle, SolvesLinearSystemAndRefusesSingular) {
    Matrix4 m{{{2, 1, 0, 0}, {1, 3, 1, 0}, {0, 1, 4, 1}, {0, 0, 1, 5}}};
    std::array<double, 4> x{};
    ASSERT_TRUE(solve(m, {3, 5, 6, 6}, x));  // x = (1, 1, 1, 1)
    for (double v : x)
        EXPECT_NEAR(v, 1, 1e-14);
    Matrix4 singular{{{1, 2, 0, 0}, {2, 4, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}}};
    EXPECT_FALSE(solve(singular, {1, 1, 1, 1}, x));
}

TEST(Cycle, QuaternionFixedPointOfCEqualsIIsSaddle) {
    // docs/facts.md, Cycles of z^2 + c in H: the fixed point (1 - sqrt(1 - 4i)) / 2 =
    // -0.30024 + 0.62481i has eigenvalues {lambda, conj lambda, mu, mu} with lambda = 2z
    // (|lambda| = 1.386) and mu = 2 Re z = -0.60049.
    Complex z = (1.0 - std::sqrt(Complex(1, -4))) / 2.0;
    EXPECT_NEAR(z.real(), -0.30024, 1e-5);
    EXPECT_NEAR(z.imag(), 0.62481, 1e-5);
    Polynomial p = compileFormula("z^2 + c", kUnitI);
    Matrix4 j = cycleJacobian(p, {Quaternion(z.real(), z.imag(), 0, 0)});
    auto e = eigenvalues(j);
    expectNear(e[0], Complex(2 * z.real(), 2 * z.imag()), 1e-13);
    expectNear(e[1], Complex(2 * z.real(), -2 * z.imag()), 1e-13);
    expectNear(e[2], 2 * z.real(), 1e-13);
    expectNear(e[3], 2 * z.real(), 1e-13);
    EXPECT_NEAR(std::abs(e[0]), 1.386, 5e-4);
    EXPECT_NEAR(e[2].real(), -0.60049, 1e-5);
    EXPECT_EQ(classifyEigenvalues({e.begin(), e.end()}).stability, Stability::Saddle);
}

TEST(Cycle, JacobianAtQuarterIsHalfIdentity) {
    // c = 0.1875: the fixed point 0.25 has Jacobian 2 * 0.25 I (docs/facts.md, Cycles of
    // z^2 + c in H).
    Polynomial p = compileFormula("z^2 + c", Quaternion(0.1875));
    Matrix4 j = jacobian(p, Quaternion(0.25));
    for (int r = 0; r < 4; ++r) {
        for (int c = 0; c < 4; ++c)
            EXPECT_EQ(j[r][c], r == c ? 0.5 : 0.0);
    }
    for (Complex e : eigenvalues(j))
        EXPECT_EQ(e, Complex(0.5));
}

TEST(Cycle, CycleJacobianChainsInOrder) {
    // The 2-cycle {0, -1} of c = -1: J(-1) J(0) = 0, superattracting in every direction.
    Polynomial p = compileFormula("z^2 + c", Quaternion(-1));
    Matrix4 j = cycleJacobian(p, {Quaternion(0), Quaternion(-1)});
    for (const auto& row : j) {
        for (double v : row)
            EXPECT_EQ(v, 0.0);
    }
    // A non-commuting map: the chain J(z1) J(z0) equals the derivative of p(p(z)) computed by
    // finite differences.
    Polynomial q = compileFormula("(1+2j) z (0.5-k) z + c", Quaternion(0.1, 0.2, -0.1, 0.3));
    Quaternion z0(0.2, -0.1, 0.3, 0.1), z1 = q.evaluate(z0);
    Matrix4 chain = cycleJacobian(q, {z0, z1});
    const double h = 1e-6;
    for (int a = 0; a < 4; ++a) {
        Quaternion e;
        e[a] = h;
        Quaternion difference = (q.evaluate(q.evaluate(z0 + e)) - q.evaluate(q.evaluate(z0 - e)));
        for (int r = 0; r < 4; ++r)
            EXPECT_NEAR(chain[r][a], difference[r] / (2 * h), 1e-8);
    }
}

}  // namespace
}  // namespace quaternia
