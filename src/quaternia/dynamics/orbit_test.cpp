#include "quaternia/dynamics/orbit.h"

#include <gtest/gtest.h>

#include "quaternia/algebra/formula.h"
#include "quaternia/algebra/test_helpers.h"
#include "quaternia/dynamics/connectedness.h"
#include "quaternia/fractal/hypercomplex_julia.h"

namespace quaternia {
namespace {

using Complex = std::complex<double>;
using testing::expectNear;

// docs/facts.md, Cycles and multipliers of z^2 + c: the rabbit and the airplane.
const Quaternion kRabbit(-0.12256116687665, 0.74486176661974, 0, 0);
const Quaternion kAirplane(-1.75487766624669);

OrbitResult orbitOf(const Quaternion& c, const Quaternion& z0, int maxIterations = 1000) {
    OrbitOptions options;
    options.maxIterations = maxIterations;
    return analyzeOrbit(compileFormula("z^2 + c", c), z0, options);
}

TEST(Orbit, CriticalOrbitOfMinusOneIsSuperattracting2Cycle) {
    OrbitResult r = orbitOf(-1.0, 0.0);
    EXPECT_EQ(r.fate, OrbitFate::Periodic);
    ASSERT_TRUE(r.cycle);
    ASSERT_EQ(r.cycle->period(), 2);
    expectNear(r.cycle->points[0], 0.0, 0);
    expectNear(r.cycle->points[1], -1.0, 0);
    ASSERT_TRUE(r.cycle->multiplier);
    EXPECT_EQ(*r.cycle->multiplier, Complex(0));
    EXPECT_EQ(r.governingClass.stability, Stability::Superattracting);
    EXPECT_EQ(r.cycle->classInH.stability, Stability::Superattracting);
    EXPECT_FALSE(r.unsure);
}

TEST(Orbit, LandingOnAnAttractingCycleIsPreperiodicConvergingIsAttracted) {
    OrbitResult landing = orbitOf(-1.0, 1.0);  // 1 -> 0 -> -1 -> 0
    EXPECT_EQ(landing.fate, OrbitFate::Preperiodic);
    EXPECT_EQ(landing.preperiod, 1);
    EXPECT_EQ(landing.cycle->period(), 2);
    OrbitResult converging = orbitOf(-1.0, Quaternion(0.3, 0.2, 0, 0));
    EXPECT_EQ(converging.fate, OrbitFate::Attracted);
    EXPECT_EQ(converging.cycle->period(), 2);
    EXPECT_GT(converging.preperiod, 2);
    EXPECT_EQ(converging.governingClass.stability, Stability::Superattracting);
}

TEST(Orbit, RepellingFixedPointsOfMinusOne) {
    // Fixed points (1 +- sqrt 5) / 2 with multipliers 1 +- sqrt 5 (docs/facts.md, Cycles and
    // multipliers of z^2 + c).
    const double phi = (1 + std::sqrt(5.0)) / 2;
    for (double z : {phi, 1 - phi}) {
        OrbitResult r = orbitOf(-1.0, z);
        EXPECT_EQ(r.fate, OrbitFate::Periodic) << z;
        ASSERT_TRUE(r.cycle && r.cycle->multiplier);
        EXPECT_EQ(r.cycle->period(), 1);
        EXPECT_NEAR(r.cycle->multiplier->real(), 2 * z, 1e-14);
        EXPECT_EQ(r.governingClass.stability, Stability::Repelling);
    }
    EXPECT_NEAR(orbitOf(-1.0, phi).cycle->multiplier->real(), 3.23607, 1e-5);
    EXPECT_NEAR(orbitOf(-1.0, 1 - phi).cycle->multiplier->real(), -1.23607, 1e-5);
}

TEST(Orbit, ParabolicFixedPointIsNeutral) {
    OrbitResult r = orbitOf(-0.75, -0.5);
    EXPECT_EQ(r.fate, OrbitFate::Periodic);
    EXPECT_EQ(*r.cycle->multiplier, Complex(-1));
    EXPECT_EQ(r.governingClass.stability, Stability::Neutral);
    // The critical orbit converges like 1/sqrt(n): no decision within the limit.
    EXPECT_EQ(orbitOf(-0.75, 0.0, 200).fate, OrbitFate::Undecided);
}

TEST(Orbit, CriticalOrbitOfIIsStrictlyPreperiodic) {
    // 0 -> i -> -1+i -> -i -> -1+i: preperiod 2, period 2, multiplier 4 + 4i
    // (docs/facts.md, Cycles and multipliers of z^2 + c).
    OrbitResult r = orbitOf(kUnitI, 0.0);
    EXPECT_EQ(r.fate, OrbitFate::Preperiodic);
    EXPECT_EQ(r.preperiod, 2);
    ASSERT_EQ(r.cycle->period(), 2);
    expectNear(r.cycle->points[0], Quaternion(-1, 1, 0, 0), 1e-14);
    expectNear(r.cycle->points[1], Quaternion(0, -1, 0, 0), 1e-14);
    EXPECT_NEAR(std::abs(*r.cycle->multiplier - Complex(4, 4)), 0, 1e-13);
    EXPECT_NEAR(std::abs(*r.cycle->multiplier), 5.657, 5e-4);
    EXPECT_EQ(r.governingClass.stability, Stability::Repelling);
    EXPECT_FALSE(r.unsure);
}

TEST(Orbit, RabbitAndAirplaneAreSuperattracting3Cycles) {
    for (const Quaternion& c : {kRabbit, kAirplane}) {
        OrbitResult r = orbitOf(c, 0.0);
        EXPECT_EQ(r.fate, OrbitFate::Periodic) << c;
        ASSERT_TRUE(r.cycle);
        ASSERT_EQ(r.cycle->period(), 3);
        // 0 -> c -> c^2 + c -> 0, refined to the exact cycle of the 14-digit parameter.
        expectNear(r.cycle->points[1], c, 1e-12);
        expectNear(r.cycle->points[2], square(c) + c, 1e-12);
        EXPECT_LT(std::abs(*r.cycle->multiplier), 1e-11);
        EXPECT_EQ(r.governingClass.stability, Stability::Superattracting);
    }
}

TEST(Orbit, RabbitInteriorOrbitIn3DSliceSettlesOn3Cycle) {
    // z0 off the plane C_i: the orbit lives in span{1, i, j} and converges to the rabbit's
    // cycle, superattracting in H too (mu = 8 Re 0 Re c Re(c^2 + c) = 0).
    OrbitResult r = orbitOf(kRabbit, Quaternion(0.05, 0.02, 0.03, 0));
    EXPECT_EQ(r.fate, OrbitFate::Attracted);
    ASSERT_EQ(r.cycle->period(), 3);
    EXPECT_EQ(r.cycle->classInH.stability, Stability::Superattracting);
    EXPECT_EQ(r.governingClass.stability, Stability::Superattracting);
    for (const Quaternion& w : r.cycle->points)
        EXPECT_LT(std::abs(w.y) + std::abs(w.z), 1e-12) << w;
    // Same for c = -1 with a point in a general 3D slice.
    EXPECT_EQ(orbitOf(-1.0, Quaternion(0.1, 0.1, 0.05, -0.05)).cycle->period(), 2);
}

TEST(Orbit, QuaternionFixedPointOfIIsSaddleInH) {
    Complex z = (1.0 - std::sqrt(Complex(1, -4))) / 2.0;
    OrbitResult r = orbitOf(kUnitI, Quaternion(z.real(), z.imag(), 0, 0));
    EXPECT_EQ(r.fate, OrbitFate::Periodic);
    ASSERT_EQ(r.cycle->period(), 1);
    EXPECT_EQ(r.cycle->complexClass.stability, Stability::Repelling);
    EXPECT_EQ(r.cycle->classInH.stability, Stability::Saddle);
    EXPECT_NEAR(std::abs(r.cycle->eigenvalues[0]), 1.386, 5e-4);
    EXPECT_NEAR(r.cycle->eigenvalues[3].real(), -0.60049, 1e-5);
    // Started in the plane, the orbit is governed by the complex class.
    EXPECT_EQ(r.governingClass.stability, Stability::Repelling);
    // The same point in the plane C_j of c = j: the complex multiplier is taken in C_j.
    OrbitResult inJ = orbitOf(kUnitJ, Quaternion(z.real(), 0, z.imag(), 0));
    EXPECT_EQ(inJ.cycle->axis, kUnitJ);
    EXPECT_NEAR(std::abs(*inJ.cycle->multiplier - 2.0 * z), 0, 1e-14);
    EXPECT_EQ(inJ.cycle->classInH.stability, Stability::Saddle);
}

TEST(Orbit, FixedPointOfQuarterMapIsAttractingInEveryDirection) {
    // c = 0.1875: a point near 0.25 in H converges to it; the Jacobian there is 0.5 I.
    OrbitResult r = orbitOf(0.1875, Quaternion(0.2, 0.01, -0.02, 0.03));
    EXPECT_EQ(r.fate, OrbitFate::Attracted);
    ASSERT_EQ(r.cycle->period(), 1);
    expectNear(r.cycle->points[0], 0.25, 1e-15);
    for (std::complex<double> e : r.cycle->eigenvalues)
        EXPECT_NEAR(std::abs(e - 0.5), 0, 1e-14);
    EXPECT_EQ(r.cycle->classInH.stability, Stability::Attracting);
}

TEST(Orbit, EscapeIterationIsExact) {
    // c = 1: 0 -> 1 -> 2, and R_1 = (1 + sqrt 5) / 2 < 2.
    OrbitResult r = orbitOf(1.0, 0.0);
    EXPECT_EQ(r.fate, OrbitFate::Escapes);
    EXPECT_EQ(r.escapeIteration, 2);
    EXPECT_NEAR(r.escapeRadius, (1 + std::sqrt(5.0)) / 2, 1e-9);
}

TEST(Orbit, ConnectednessFromCriticalOrbits) {
    auto complexMap = [](const char* formula, Quaternion c) {
        return restrictToComplexPlane(compileFormula(formula, c))->polynomial;
    };
    Connectedness minusOne = connectedness(complexMap("z^2 + c", -1.0), 1000);
    EXPECT_TRUE(minusOne.connected);
    EXPECT_TRUE(minusOne.certain);
    ASSERT_EQ(minusOne.criticalOrbits.size(), 1u);
    EXPECT_EQ(minusOne.criticalOrbits[0].point, Complex(0));
    Connectedness outside = connectedness(complexMap("z^2 + c", 0.3), 1000);
    EXPECT_FALSE(outside.connected);
    EXPECT_TRUE(outside.cantor);
    EXPECT_TRUE(connectedness(complexMap("z^2 + c", kUnitI), 1000).connected);
    // z^3 - 3z + 3: critical points +-1; 1 is a superattracting fixed point, -1 -> 5 escapes.
    Connectedness cubic = connectedness(complexMap("z^3 - 3z + c", 3.0), 1000);
    ASSERT_EQ(cubic.criticalOrbits.size(), 2u);
    EXPECT_FALSE(cubic.connected);
    EXPECT_FALSE(cubic.cantor);
    EXPECT_TRUE(cubic.certain);
    // z^3 + c: the double critical point 0, found exactly.
    auto cubicCritical = criticalPoints(complexMap("z^3 + c", 0.2));
    ASSERT_EQ(cubicCritical.size(), 1u);
    EXPECT_EQ(cubicCritical[0].second, 2);
    // The parabolic c = -3/4 stays undecided: connected, but not certain.
    Connectedness parabolic = connectedness(complexMap("z^2 + c", -0.75), 300);
    EXPECT_TRUE(parabolic.connected);
    EXPECT_FALSE(parabolic.certain);
}

// ---- Other algebras (issue 16) ------------------------------------------------------------

void expectNearComplex(Complex actual, Complex expected, double tolerance) {
    EXPECT_NEAR(actual.real(), expected.real(), tolerance);
    EXPECT_NEAR(actual.imag(), expected.imag(), tolerance);
}

Hypercomplex hypercomplex(const Quaternion& q) {
    return {q.w, q.x, q.y, q.z, 0, 0, 0, 0};
}

template <std::size_t N>
HypercomplexOrbitResult<N> hypercomplexOrbitOf(Algebra algebra, const Hypercomplex& c,
                                               const Hypercomplex& z0) {
    const HypercomplexJuliaSet set(HypercomplexFormula(Formula::parse("z^2 + c"), algebra, c), 100,
                                   0);
    return analyzeHypercomplexOrbit<N>(set.formula(), set.escapeRadius(), z0);
}

TEST(HypercomplexOrbit, OctonionOrbitInTheQuaternionHalfIsTheQuaternionOrbit) {
    // (a, 0)(c, 0) = (ac, 0): the quaternions are a subalgebra, so the orbit, its fate and
    // cycle are the quaternion ones. Off it, D(z^2)(0, d) = (0, d) 2 Re z ((a, 0)(0, d) +
    // (0, d)(a, 0) = (0, d (a + conj a))): the 8x8 Jacobian of f^n is diag(J_H, prod 2 Re z_k).
    const Quaternion z0(0.05, 0.02, 0.03, 0);
    const OrbitResult h = orbitOf(kRabbit, z0);
    const auto o =
        hypercomplexOrbitOf<8>(Algebra::kOctonion, hypercomplex(kRabbit), hypercomplex(z0));
    EXPECT_EQ(o.fate, h.fate);
    EXPECT_EQ(o.fate, OrbitFate::Attracted);
    EXPECT_EQ(o.preperiod, h.preperiod);
    ASSERT_TRUE(o.cycle && h.cycle);
    ASSERT_EQ(o.cycle->period(), 3);
    ASSERT_TRUE(o.cycle->multiplier && h.cycle->multiplier);  // the cycle lies in C_i
    EXPECT_EQ(*o.cycle->multiplier, *h.cycle->multiplier);
    double product = 1;
    for (int k = 0; k < 3; ++k) {
        const Hypercomplex& w = o.cycle->points[size_t(k)];
        expectNear(Quaternion(w[0], w[1], w[2], w[3]), h.cycle->points[size_t(k)], 1e-12);
        for (size_t n = 4; n < 8; ++n)
            EXPECT_EQ(w[n], 0);
        product *= 2 * w[0];
    }
    for (size_t i = 0; i < 8; ++i) {
        for (size_t j = 0; j < 8; ++j) {
            const double expected = i < 4 && j < 4     ? h.cycle->jacobian[i][j]
                                    : i == j && i >= 4 ? product
                                                       : 0.0;
            EXPECT_NEAR(o.cycle->jacobian[i][j], expected, 1e-12) << i << ", " << j;
        }
    }
    // The rabbit's cycle holds the critical point 0: every eigenvalue is 0.
    for (Complex e : o.cycle->eigenvalues)
        EXPECT_NEAR(std::abs(e), 0, 1e-6);
    EXPECT_EQ(o.governingClass.stability, h.cycle->classInH.stability);
}

TEST(HypercomplexOrbit, BicomplexOrbitIsTwoComplexOrbitsInDuplexForm) {
    // The duplex form is an isomorphism onto C x C: z^2 + c acts as w^2 + c_1 and w^2 + c_2.
    // c_1 = the rabbit (a superattracting 3-cycle through 0), c_2 with an attracting fixed
    // point w* = (1 - sqrt(1 - 4 c_2)) / 2 of multiplier mu = 2 w*. The orbit lands near the
    // product cycle, of period 3; in the duplex coordinates D f^3 is multiplication by
    // (0, mu^3), so the real 4x4 Jacobian has the eigenvalues mu^3, conj mu^3, 0, 0.
    const Complex c1(kRabbit.w, kRabbit.x), c2(-0.1, 0.1);
    const Complex fixed = (1.0 - std::sqrt(1.0 - 4.0 * c2)) / 2.0, mu3 = std::pow(2.0 * fixed, 3);
    const Hypercomplex c = fromDuplexForm(c1, c2);
    const auto r = hypercomplexOrbitOf<4>(Algebra::kBicomplex, c, fromDuplexForm(0.01, 0.02));
    EXPECT_EQ(r.fate, OrbitFate::Attracted);
    ASSERT_TRUE(r.cycle);
    ASSERT_EQ(r.cycle->period(), 3);
    for (const Hypercomplex& w : r.cycle->points) {
        const auto [a, b] = duplexForm(w);
        const Complex image = a * a + c1;  // a is on the rabbit's cycle
        EXPECT_TRUE(std::abs(a) < 1e-9 || std::abs(a - c1) < 1e-9 ||
                    std::abs(a - (c1 * c1 + c1)) < 1e-9)
            << a << " -> " << image;
        EXPECT_NEAR(std::abs(b - fixed), 0, 1e-9);
    }
    const auto& e = r.cycle->eigenvalues;
    expectNearComplex(e[0], Complex(mu3.real(), std::abs(mu3.imag())), 1e-9);
    expectNearComplex(e[1], Complex(mu3.real(), -std::abs(mu3.imag())), 1e-9);
    EXPECT_NEAR(std::abs(e[2]), 0, 1e-6);
    EXPECT_NEAR(std::abs(e[3]), 0, 1e-6);
    EXPECT_EQ(r.governingClass.stability, Stability::Attracting);

    // Escape: at the first k with |q_k|^2 = (|a_k|^2 + |b_k|^2) / 2 > 4^2, the bailout.
    const Complex a0(0.3, 0.2), b0(0.9, 0.6);
    const auto escaping = hypercomplexOrbitOf<4>(Algebra::kBicomplex, c, fromDuplexForm(a0, b0));
    Complex a = a0, b = b0;
    int k = 0;
    while ((std::norm(a) + std::norm(b)) / 2 <= 16) {
        a = a * a + c1, b = b * b + c2;
        ++k;
    }
    EXPECT_EQ(escaping.fate, OrbitFate::Escapes);
    EXPECT_EQ(escaping.escapeIteration, k);
    EXPECT_GT(k, 2);
}

TEST(HypercomplexOrbit, CoquaternionOrbitInTheComplexPlaneIsTheComplexOne) {
    // i^2 = -1: span{1, i} is a subalgebra equal to C, and D(z^2)h = zh + hz = 2 Re z h for h
    // in span{j, k} as in H (ij = -ji): the same orbit, cycle and Jacobian as the quaternions'.
    for (const Quaternion& z0 : {Quaternion(0.05, 0.02, 0, 0), Quaternion(0)}) {
        const OrbitResult h = orbitOf(-1.0, z0);
        const auto q =
            hypercomplexOrbitOf<4>(Algebra::kCoquaternion, realElement(-1), hypercomplex(z0));
        EXPECT_EQ(q.fate, h.fate);
        EXPECT_EQ(q.preperiod, h.preperiod);
        ASSERT_TRUE(q.cycle && h.cycle);
        ASSERT_EQ(q.cycle->period(), 2);
        for (size_t k = 0; k < 4; ++k)
            expectNearComplex(q.cycle->eigenvalues[k], h.cycle->eigenvalues[k], 1e-12);
        EXPECT_EQ(q.cycle->classInH.stability, Stability::Superattracting);
    }
}

TEST(HypercomplexOrbit, BicomplexFixedPointInSpanOneJHasTheComplexMultiplier) {
    // j^2 = -1: span{1, j} is a copy of C, so with c = -0.5 + 0.3 j the fixed point
    // w* = (1 - sqrt(1 - 4c)) / 2 (read as x + y j) has the multiplier 2 w*. In duplex form
    // x + y j is (x + y i, x - y i), a fixed point of w^2 + c_1 and of its conjugate map, so
    // the 4x4 Jacobian has 2 w* and its conjugate twice each.
    const Complex c(-0.5, 0.3), fixed = (1.0 - std::sqrt(1.0 - 4.0 * c)) / 2.0;
    const auto r = hypercomplexOrbitOf<4>(Algebra::kBicomplex, {c.real(), 0, c.imag(), 0},
                                          {fixed.real(), 0, fixed.imag(), 0});
    EXPECT_EQ(r.fate, OrbitFate::Periodic);
    ASSERT_TRUE(r.cycle && r.cycle->multiplier);
    EXPECT_EQ(r.cycle->period(), 1);
    EXPECT_EQ(r.cycle->axis, Quaternion(0, 0, 1, 0));
    expectNearComplex(*r.cycle->multiplier, 2.0 * fixed, 1e-12);
    EXPECT_EQ(r.governingClass.stability, Stability::Attracting);  // |2 w*| = 0.83
    const auto& e = r.cycle->eigenvalues;
    const Complex upper(2 * fixed.real(), std::abs(2 * fixed.imag()));
    expectNearComplex(e[0], upper, 1e-12);
    expectNearComplex(e[1], upper, 1e-12);
    expectNearComplex(e[2], std::conj(upper), 1e-12);
    expectNearComplex(e[3], std::conj(upper), 1e-12);
    // An orbit from off the plane converges to the same cycle; its class is the Jacobian's.
    const auto off =
        hypercomplexOrbitOf<4>(Algebra::kBicomplex, {c.real(), 0, c.imag(), 0}, {0.01, 0.02, 0, 0});
    ASSERT_TRUE(off.cycle);
    EXPECT_EQ(off.fate, OrbitFate::Attracted);
    EXPECT_EQ(off.cycle->period(), 1);
    EXPECT_EQ(off.governingClass.stability, off.cycle->classInH.stability);
}

// ---- Orbits that recur before they reach their cycle (issue 41) ----------------------------
// Each of these crashed: the recurrence |z_k - z_{k-n}| <= tol puts z_k within about
// tol / |1 - lambda| of the cycle, and Newton's cycle lay beyond tol of every iterate so far.
// The answers are checked against the orbit itself, iterated far past the analysis.

template <typename Map, typename Point>
Point iterateMany(const Map& f, Point z, int n) {
    for (int k = 0; k < n; ++k)
        z = f(z);
    return z;
}

TEST(OrbitRegression, CoquaternionOrbitSpirallingIntoAFixedPointIsAttracted) {
    // quaternia orbit --set fractal.algebra=coquaternion (the default c, z0 = 0): the fixed
    // point's multipliers -0.513 +- 0.699i turn by 126 degrees, so z_k recurs with period 3.
    const Hypercomplex c{-0.2, 0.6, 0.2, 0.2, 0, 0, 0, 0};
    const auto r = hypercomplexOrbitOf<4>(Algebra::kCoquaternion, c, Hypercomplex{});
    ASSERT_EQ(r.fate, OrbitFate::Attracted) << r.note;
    ASSERT_TRUE(r.cycle);
    EXPECT_EQ(r.cycle->period(), 1);
    EXPECT_EQ(r.governingClass.stability, Stability::Attracting);
    const HypercomplexFormula f(Formula::parse("z^2 + c"), Algebra::kCoquaternion, c);
    const Hypercomplex w = r.cycle->points[0];
    EXPECT_LT(euclideanNorm(f.evaluate(w) - w), 1e-13);
    auto map = [&](const Hypercomplex& z) { return f.evaluate(z); };
    EXPECT_LT(euclideanNorm(iterateMany(map, Hypercomplex{}, 5000) - w), 1e-12);
    // The analysis met the cycle where the orbit does: within tol there, not before.
    const Hypercomplex met = iterateMany(map, Hypercomplex{}, r.preperiod);
    EXPECT_LE(euclideanNorm(met - w), r.tolerance);
    EXPECT_GT(euclideanNorm(map(Hypercomplex{}) - w), r.tolerance);
}

TEST(OrbitRegression, BicomplexSineOrbitCreepingIntoAFixedPointIsAttracted) {
    // quaternia orbit --set fractal.algebra=bicomplex --set fractal.formula="sin(z) + c" ...
    const Hypercomplex c{0.079, 0.147, -0.152, 0.109, 0, 0, 0, 0};
    const Hypercomplex z0{0.931, 0.358, 0.125, 0.567, 0, 0, 0, 0};
    const HypercomplexJuliaSet set(
        HypercomplexFormula(Formula::parse("sin(z) + c"), Algebra::kBicomplex, c), 100, 0);
    const auto r = analyzeHypercomplexOrbit<4>(set.formula(), set.escapeRadius(), z0);
    ASSERT_EQ(r.fate, OrbitFate::Attracted) << r.note;
    ASSERT_TRUE(r.cycle);
    EXPECT_EQ(r.cycle->period(), 1);
    EXPECT_EQ(r.governingClass.stability, Stability::Attracting);
    auto map = [&](const Hypercomplex& z) { return set.formula().evaluate(z); };
    const Hypercomplex w = r.cycle->points[0];
    EXPECT_LT(euclideanNorm(map(w) - w), 1e-13);
    EXPECT_LT(euclideanNorm(iterateMany(map, z0, 20000) - w), 1e-12);
    EXPECT_LE(euclideanNorm(iterateMany(map, z0, r.preperiod) - w), r.tolerance);
}

TEST(OrbitRegression, CriticalOrbitsThatRecurEarlyStillDecideConnectedness) {
    // The critical orbits behind two crashes: z^2 + 0.1 z + c at c = -0.611 - 0.038i + 0.029j
    // - 0.075k (quaternia orbit ...), and z^3 + c at c = 0.139 + 0.542i - 0.304j + 0.195k
    // (quaternia plane ... plane.kind=julia), both through the plane C_u of c, where the
    // critical orbits converge to an attracting cycle: K is connected, and certainly so.
    struct Case {
        const char* formula;
        Quaternion c;
    };
    for (const Case& item : {Case{"z^2 + 0.1*z + c", Quaternion(-0.611, -0.038, 0.029, -0.075)},
                             Case{"z^3 + c", Quaternion(0.139, 0.542, -0.304, 0.195)}}) {
        const auto restriction = restrictToComplexPlane(compileFormula(item.formula, item.c));
        ASSERT_TRUE(restriction) << item.formula;
        const ComplexPolynomial& p = restriction->polynomial;
        const Connectedness k = connectedness(p, 1000);
        EXPECT_TRUE(k.connected) << item.formula;
        EXPECT_TRUE(k.certain) << item.formula;
        for (const CriticalOrbit& critical : k.criticalOrbits) {
            const OrbitResult& r = critical.orbit;
            ASSERT_TRUE(r.fate == OrbitFate::Attracted || r.fate == OrbitFate::Periodic ||
                        r.fate == OrbitFate::Preperiodic)
                << item.formula << ": " << r.note;
            ASSERT_TRUE(r.cycle);
            // The critical orbit, iterated as a complex number far past the analysis, sits on
            // the cycle the analysis found (its points are in C_i: quaternionPolynomial).
            Complex z = critical.point;
            for (int n = 0; n < 20000; ++n)
                z = p.evaluate(z);
            double nearest = INFINITY;
            for (const Quaternion& w : r.cycle->points)
                nearest = std::min(nearest, std::abs(Complex(w.w, w.x) - z));
            EXPECT_LT(nearest, 1e-10) << item.formula;
        }
    }
}

TEST(OrbitRegression, OrbitThatNeverReachesNewtonsCycleIsUndecided) {
    // An orbit that recurs (within tol over 3 iterates) while still far from its fixed point,
    // with too few iterations left to arrive: the analysis says so instead of naming a cycle.
    const Hypercomplex c{-0.2, 0.6, 0.2, 0.2, 0, 0, 0, 0};
    const HypercomplexJuliaSet set(
        HypercomplexFormula(Formula::parse("z^2 + c"), Algebra::kCoquaternion, c), 100, 0);
    const auto full = analyzeHypercomplexOrbit<4>(set.formula(), set.escapeRadius(), {});
    ASSERT_EQ(full.fate, OrbitFate::Attracted);
    OrbitOptions options;
    options.maxIterations = full.preperiod - 1;
    const auto cut = analyzeHypercomplexOrbit<4>(set.formula(), set.escapeRadius(), {}, options);
    EXPECT_EQ(cut.fate, OrbitFate::Undecided);
    EXPECT_FALSE(cut.cycle);
    EXPECT_TRUE(cut.unsure);
    EXPECT_NE(cut.note.find("recurred"), std::string::npos) << cut.note;
}

TEST(HypercomplexOrbit, DimensionMustBeTheAlgebras) {
    const HypercomplexFormula f(Formula::parse("z^2 + c"), Algebra::kOctonion, realElement(-1));
    EXPECT_THROW(analyzeHypercomplexOrbit<4>(f, 2, Hypercomplex{}), std::invalid_argument);
}

}  // namespace
}  // namespace quaternia

namespace quaternia {
namespace {

// One analysis for every algebra (analyzeOrbit of a JuliaSet): the rabbit's interior orbit ends
// on the same superattracting 3-cycle whether the map is the quaternions' polynomial or the same
// formula evaluated through Hamilton's multiplication table, and the octonions and bicomplex
// numbers, which hold the complex plane C_i as a subalgebra, find it there too.
TEST(Orbit, OneAnalysisForEveryAlgebra) {
    const Quaternion c(-0.122561, 0.744862, 0, 0);
    const Hypercomplex z0{0.05, 0.02, 0, 0, 0, 0, 0, 0};
    auto periodOf = [&](const JuliaSet& set) {
        return std::visit(
            [](const auto& r) {
                EXPECT_EQ(r.fate, OrbitFate::Attracted);
                return r.cycle ? r.cycle->period() : 0;
            },
            analyzeOrbit(set, z0));
    };
    const QuaternionJuliaSet quaternion(compileFormula("z^2 + c", c), 100, 0);
    EXPECT_EQ(periodOf(quaternion), 3);
    EXPECT_TRUE(std::holds_alternative<OrbitResult>(analyzeOrbit(quaternion, z0)));
    for (Algebra algebra : {Algebra::kQuaternion, Algebra::kOctonion, Algebra::kBicomplex}) {
        FractalSettings settings;
        settings.formula = "z^2 + c";
        settings.algebra = algebra;
        settings.c = c;
        settings.maxIterations = 100;
        const auto set = hypercomplexJuliaSetOf(settings);
        EXPECT_EQ(periodOf(*set), 3) << algebraName(algebra);
        EXPECT_EQ(analyzeOrbit(*set, z0).index(), algebraDimension(algebra) == 4 ? 1u : 2u);
    }
}

}  // namespace
}  // namespace quaternia
