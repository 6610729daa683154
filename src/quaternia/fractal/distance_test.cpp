#include "quaternia/fractal/distance.h"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <random>

#include "quaternia/algebra/formula.h"
#include "quaternia/util/error.h"

namespace quaternia {
namespace {

QuaternionJuliaSet quadratic(const Quaternion& c, int maxIterations, double bailout = 0) {
    return QuaternionJuliaSet(compileFormula("z^2 + c", c), maxIterations, bailout);
}

Quaternion randomUnit(std::mt19937& rng) {
    std::normal_distribution<double> gauss;
    return normalize(Quaternion(gauss(rng), gauss(rng), gauss(rng), gauss(rng)));
}

// c = 0: z_n = z^(2^n) and |z'_n| = 2^n |z|^(2^n - 1), so the estimate is 0.5 r ln r at every
// iteration count (docs/facts.md, Distance estimate), below the true distance r - 1 for
// 1 < r < 4.92.
TEST(DistanceEstimate, IsHalfRLogRForZeroC) {
    QuaternionJuliaSet set = quadratic(Quaternion{}, 50);
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> radius(1.001, 4.0);
    for (int k = 0; k < 2000; ++k) {
        double r = radius(rng);
        DistanceEstimate e = set.estimate(randomUnit(rng) * r);
        ASSERT_FALSE(e.inside);
        EXPECT_NEAR(e.distance, 0.5 * r * std::log(r), 1e-9 * r);
        EXPECT_LT(e.distance, r - 1) << "r = " << r;
    }
}

TEST(DistanceEstimate, IsZeroInsideTheSet) {
    QuaternionJuliaSet set = quadratic(Quaternion{}, 50);
    DistanceEstimate e = set.estimate(Quaternion(0.3, 0.2, -0.1, 0.5));
    EXPECT_TRUE(e.inside);
    EXPECT_EQ(e.distance, 0);
    EXPECT_EQ(e.escapeIteration, 50);
}

// High degrees and large bailouts must not overflow into infinities or NaN: the continuation
// radius shrinks with the degree.
TEST(DistanceEstimate, StaysFiniteForHighDegreeAndLargeBailout) {
    for (double bailout : {0.0, 1000.0}) {
        QuaternionJuliaSet set(compileFormula("z^40 + c", Quaternion(0.3, 0.1, 0, 0)), 50, bailout);
        std::mt19937 rng(23);
        std::uniform_real_distribution<double> radius(0.5, bailout == 0 ? 2.0 : 999.0);
        for (int k = 0; k < 1000; ++k) {
            DistanceEstimate e = set.estimate(randomUnit(rng) * radius(rng));
            ASSERT_TRUE(std::isfinite(e.distance)) << "bailout " << bailout;
            ASSERT_GE(e.distance, 0);
        }
    }
}

// A bailout below the certified escape radius (here 1.69 against 1.80) leaves escape uncertain:
// an orbit past the bailout may return. Such points lie outside K_N but may be close to it, and
// the escaping estimate 0.5 |z| ln|z| / |z'| overshot K_N there by up to 1.5 times along a
// camera ray of this set (whole blocks of the lanes' cones then started behind its near
// surface). Along random lines, no point before the first member of K_N (found by steps of
// 2.5e-4) may have an estimate beyond the distance to it.
TEST(DistanceEstimate, UncertainEscapeNeverReachesPastTheFirstMemberAlongALine) {
    const Quaternion c(-0.307692, 1.076923, 0.461538, 0.615385);
    QuaternionJuliaSet set(compileFormula("z (0.5+0.1j) z + c", c), 20, 1.692820323);
    ASSERT_GT(set.escapeRadius(), set.bailout());
    std::mt19937 rng(5);
    std::normal_distribution<double> gauss;
    const double far = 1.2 * set.escapeRadius() / 0.51;  // |p1| = 0.51: K lies within R / |p1|
    int lines = 0, points = 0;
    double worst = 0;
    while (lines < 60) {
        Quaternion from = far * normalize(Quaternion(gauss(rng), gauss(rng), gauss(rng), 0));
        Quaternion to(0.3 * gauss(rng), 0.3 * gauss(rng), 0.3 * gauss(rng), 0);
        const Quaternion direction = normalize(to - from);
        const double step = 2.5e-4;
        const int steps = int(2 * far / step);
        int first = -1;
        for (int i = 0; i < steps && first < 0; ++i) {
            if (set.contains(from + (i * step) * direction)) first = i;
        }
        if (first < 0) continue;
        ++lines;
        for (int i = 0; i < first; i += 20) {  // points of the same grid, every 0.005
            const double t = i * step;
            const DistanceEstimate e = set.estimate(from + t * direction);
            ASSERT_FALSE(e.inside);
            worst = std::max(worst, e.distance / (first * step - t + step));
            ++points;
        }
    }
    EXPECT_GT(points, 1000);
    EXPECT_LE(worst, 1.0) << "an estimate reached past K_N along a line";
}

// For a two-sided polynomial the estimate has no theorem behind it; hold it to geometry: at
// points near the set it must not exceed the distance to the nearest member of a fine grid.
TEST(DistanceEstimate, TwoSidedPolynomialStaysBelowGridDistance) {
    const Quaternion c(-0.3, 0.4, 0.1, 0);
    QuaternionJuliaSet set(compileFormula("(1+0.5i) z (0.8-0.3k) z + c", c), 60, 0);
    const int n = 70;
    const double extent = set.escapeRadius();
    const double spacing = 2 * extent / n;
    std::vector<Quaternion> members;
    for (int a = 0; a <= n; ++a) {
        for (int b = 0; b <= n; ++b) {
            for (int d = 0; d <= n; ++d) {
                Quaternion q(-extent + a * spacing, -extent + b * spacing, -extent + d * spacing,
                             0);
                if (set.contains(q)) members.push_back(q);
            }
        }
    }
    ASSERT_GT(members.size(), 100u);
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> coordinate(-extent, extent);
    int tested = 0;
    while (tested < 300) {
        Quaternion p(coordinate(rng), coordinate(rng), coordinate(rng), 0);
        DistanceEstimate e = set.estimate(p);
        if (e.inside || e.distance > 0.3) continue;
        double nearest = 1e300;
        for (const Quaternion& m : members)
            nearest = std::min(nearest, norm(p - m));
        EXPECT_LE(e.distance, nearest) << "at " << p;
        ++tested;
    }
}

// Complex restriction: for c in span{1, i}, the plane (1, i) is invariant and K meets it in the
// complex filled Julia set, computed here independently with std::complex.
TEST(JuliaSet, MatchesComplexFilledJuliaSetOnTheComplexPlane) {
    const std::complex<double> c(-0.8, 0.156);
    const int maxIterations = 40;
    QuaternionJuliaSet set = quadratic(Quaternion(c.real(), c.imag(), 0, 0), maxIterations);
    const double bailout = set.bailout();
    int mismatches = 0, members = 0;
    for (int row = 0; row < 200; ++row) {
        for (int column = 0; column < 200; ++column) {
            std::complex<double> z(-1.8 + 3.6 * column / 199, -1.2 + 2.4 * row / 199);
            bool complexMember = true;
            std::complex<double> w = z;
            for (int n = 0; n < maxIterations; ++n) {
                if (std::norm(w) > bailout * bailout) {
                    complexMember = false;
                    break;
                }
                w = w * w + c;
            }
            bool member = set.contains(Quaternion(z.real(), z.imag(), 0, 0));
            mismatches += member != complexMember;
            members += member;
        }
    }
    EXPECT_GT(members, 1000);
    EXPECT_EQ(mismatches, 0);
}

// For z^2 + c, (-q)^2 = q^2 exactly, also in floating point: K = -K without exception.
TEST(JuliaSet, IsCentrallySymmetric) {
    QuaternionJuliaSet set = quadratic(Quaternion(-0.2, 0.6, 0.2, 0.2), 30);
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> coordinate(-1.5, 1.5);
    int members = 0;
    for (int k = 0; k < 20000; ++k) {
        Quaternion q(coordinate(rng), coordinate(rng), coordinate(rng), coordinate(rng));
        bool member = set.contains(q);
        members += member;
        ASSERT_EQ(member, set.contains(-q)) << q;
    }
    EXPECT_GT(members, 100);
}

// Membership that a rotation should preserve, compared on random points; rounding may flip a
// point within 1e-9 of the boundary, so each mismatch must be such a point.
template <typename Map>
void expectInvariant(const QuaternionJuliaSet& set, Map map, uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> coordinate(-1.6, 1.6);
    int members = 0;
    for (int k = 0; k < 20000; ++k) {
        Quaternion q(coordinate(rng), coordinate(rng), coordinate(rng), coordinate(rng));
        bool member = set.contains(q);
        members += member;
        if (member != set.contains(map(q))) {
            EXPECT_LT(set.estimate(member ? map(q) : q).distance, 1e-9) << q;
        }
    }
    EXPECT_GT(members, 100);
}

// Real c: (a, v) is in K iff a + |v| i is: a solid of revolution about the real axis.
TEST(JuliaSet, RealConstantGivesSolidOfRevolution) {
    QuaternionJuliaSet set = quadratic(Quaternion(-0.9), 30);
    expectInvariant(
        set, [](const Quaternion& q) { return Quaternion(q.w, imaginaryNorm(q), 0, 0); }, 5);
}

// c in span{1, i}: (a, b, d, e) is in K iff (a, b, sqrt(d^2 + e^2), 0) is.
TEST(JuliaSet, HiddenDimensionRotationInvariance) {
    QuaternionJuliaSet set = quadratic(Quaternion(-0.8, 0.156, 0, 0), 30);
    expectInvariant(
        set, [](const Quaternion& q) { return Quaternion(q.w, q.x, std::hypot(q.y, q.z), 0); }, 9);
}

// Conjugation by a unit u is an automorphism: K of z^2 + u c conj(u) is u K conj(u).
TEST(JuliaSet, ConjugationRotatesTheSet) {
    const Quaternion c(-0.2, 0.6, 0.2, 0.2);
    std::mt19937 rng(13);
    Quaternion u = randomUnit(rng);
    QuaternionJuliaSet original = quadratic(c, 30);
    QuaternionJuliaSet rotated = quadratic(u * c * conj(u), 30);
    std::uniform_real_distribution<double> coordinate(-1.5, 1.5);
    for (int k = 0; k < 5000; ++k) {
        Quaternion q(coordinate(rng), coordinate(rng), coordinate(rng), coordinate(rng));
        bool member = original.contains(q);
        if (member != rotated.contains(u * q * conj(u))) {
            EXPECT_LT(original.estimate(q).distance, 1e-9);
        }
    }
}

// K lies in the ball of radius R_c, attained for real c <= 0 at beta = R_c, and K meets the real
// axis in [-beta, beta] (docs/facts.md, Escape radius and bounding sphere).
TEST(JuliaSet, EscapeRadiusIsTightForNegativeRealC) {
    for (double c : {0.0, -0.5, -1.0, -2.0}) {
        QuaternionJuliaSet set = quadratic(Quaternion(c), 25);
        double beta = (1 + std::sqrt(1 - 4 * c)) / 2;
        EXPECT_NEAR(set.escapeRadius(), beta, 1e-12);
        EXPECT_TRUE(set.contains(Quaternion(0.999 * beta))) << c;
        EXPECT_TRUE(set.contains(Quaternion(-0.999 * beta))) << c;
        EXPECT_FALSE(set.contains(Quaternion(1.001 * beta))) << c;
    }
    std::mt19937 rng(17);
    QuaternionJuliaSet set = quadratic(Quaternion(-0.2, 0.6, 0.2, 0.2), 200);
    for (int k = 0; k < 1000; ++k) {
        EXPECT_FALSE(set.contains(randomUnit(rng) * (set.escapeRadius() * 1.0001)));
    }
}

TEST(JuliaSet, RejectsBailoutBelowOne) {
    EXPECT_THROW(quadratic(Quaternion(-1), 10, 0.5), UserError);
    try {
        quadratic(Quaternion(-1), 10, 0.5);
    } catch (const UserError& e) {
        EXPECT_EQ(e.key(), "fractal.bailout");
    }
}

// The iterates z_0 .. z_{N-1} are tested, as POV-Ray does: with N = 1 only |z_0| counts.
TEST(JuliaSet, TestsIteratesZeroToNMinusOne) {
    QuaternionJuliaSet one = quadratic(Quaternion(0.3), 1, 2.0);
    EXPECT_TRUE(one.contains(Quaternion(1.9)));  // z_1 = 3.91 is never tested
    QuaternionJuliaSet two = quadratic(Quaternion(0.3), 2, 2.0);
    EXPECT_FALSE(two.contains(Quaternion(1.9)));
    EXPECT_EQ(two.estimate(Quaternion(1.9)).escapeIteration, 1);
    EXPECT_TRUE(one.estimate(Quaternion(1.9)).inside);
}

}  // namespace
}  // namespace quaternia
