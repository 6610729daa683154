// Fractals built from scenes (scene_fractal.h) in every algebra: the quaternion fold of
// octonions, the bicomplex duplex form, the Lipschitz paths of coquaternions and biquaternions.
#include "quaternia/scene/scene_fractal.h"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <random>

#include "quaternia/fractal/fractal.h"
#include "quaternia/fractal/hypercomplex_julia.h"
#include "quaternia/scene/parameters.h"
#include "quaternia/util/error.h"

namespace quaternia {
namespace {

using Complex = std::complex<double>;

Scene sceneIn(Algebra algebra, const Hypercomplex& c, int maxIterations = 12, double bailout = 0) {
    Scene scene = defaultScene();
    scene.fractal.algebra = algebra;
    scene.fractal.c = Quaternion(c[0], c[1], c[2], c[3]);
    scene.fractal.cUpper = {c[4], c[5], c[6], c[7]};
    scene.fractal.cComponents = algebraDimension(algebra);
    scene.fractal.maxIterations = maxIterations;
    scene.fractal.bailout = bailout;
    return scene;
}

Point3d randomPoint(std::mt19937& rng, double scale) {
    std::uniform_real_distribution<double> u(-scale, scale);
    return Point3d(u(rng), u(rng), u(rng));
}

// The duplex components of a bicomplex number (hypercomplex.h).
std::array<Complex, 2> duplex(const Hypercomplex& q) {
    return {Complex(q[0] - q[3], q[1] + q[2]), Complex(q[0] + q[3], q[1] - q[2])};
}

TEST(HypercomplexJulia, OctonionsInTheQuaternionSubalgebraDrawTheQuaternionSet) {
    // c and the slice (origin 0, axes e0 e1 e2: the quaternion default slice) in components
    // 0 .. 3: every orbit stays in the quaternions, so membership and estimate are the
    // quaternion ones, escape radius included.
    const Hypercomplex c{-0.2, 0.6, 0.2, 0.2, 0, 0, 0, 0};
    const Fractal quaternion = fractalFromScene(sceneIn(Algebra::kQuaternion, c));
    const Fractal octonion = fractalFromScene(sceneIn(Algebra::kOctonion, c));
    EXPECT_NEAR(octonion.escapeRadius(), quaternion.escapeRadius(), 1e-12);
    EXPECT_EQ(octonion.distanceKind(), DistanceKind::kEstimate);
    std::mt19937 rng(21);
    int inside = 0;
    for (int trial = 0; trial < 3000; ++trial) {
        const Point3d p = randomPoint(rng, 1.5);
        const DistanceEstimate a = quaternion.estimate(p), b = octonion.estimate(p);
        ASSERT_EQ(a.inside, b.inside) << p;
        EXPECT_EQ(quaternion.contains(p), octonion.contains(p));
        EXPECT_EQ(a.escapeIteration, b.escapeIteration);
        EXPECT_NEAR(a.distance, b.distance, 1e-9 * (1 + a.distance)) << p;
        inside += a.inside;
    }
    EXPECT_GT(inside, 100);  // the test sees the set, not only its outside
}

TEST(HypercomplexJulia, OctonionRealFormsRunAsQuaternionsThroughAnIsometry) {
    // z^2 + c with c outside the quaternion half, on a slice whose parts orthogonal to 1 and
    // Im c span a plane: the SIMD engine's Fractal is a quaternion one (the lanes draw it), and
    // it answers as the octonion arithmetic of the scalar engine does.
    Scene scene = sceneIn(Algebra::kOctonion, {-0.2, 0.5, 0.1, 0.2, 0.15, -0.1, 0.2, 0.05});
    scene.slice.axes = {1, 0, 0, 0, 0, 0, 0, 0,  //
                        0, 1, 0, 0, 0, 0, 0, 0,  //
                        0, 0, 0, 0, 0, 0, 1, 0};
    for (const char* formula : {"z^2 + c", "z^3 - 0.5*z + c", "z^2 + (z - 1)*0.1 + i*c"}) {
        scene.fractal.formula = formula;
        scene.render.engine = RenderEngine::Simd;
        const Fractal fast = fractalFromScene(scene);
        scene.render.engine = RenderEngine::Scalar;
        const Fractal reference = fractalFromScene(scene);
        EXPECT_TRUE(fast.setAs<QuaternionJuliaSet>() != nullptr) << formula;
        EXPECT_FALSE(reference.setAs<QuaternionJuliaSet>() != nullptr);
        EXPECT_NEAR(fast.escapeRadius(), reference.escapeRadius(), 1e-9) << formula;
        std::mt19937 rng(28);
        int inside = 0;
        for (int trial = 0; trial < 2000; ++trial) {
            const Point3d p = randomPoint(rng, 1.5);
            const DistanceEstimate a = fast.estimate(p), b = reference.estimate(p);
            ASSERT_EQ(a.inside, b.inside) << formula << " " << p;
            EXPECT_EQ(a.escapeIteration, b.escapeIteration);
            EXPECT_NEAR(a.distance, b.distance, 1e-9 * (1 + b.distance)) << formula << " " << p;
            inside += a.inside;
        }
        EXPECT_GT(inside, 20) << formula;  // the test sees the set
    }
    // Three imaginary directions orthogonal to Im c: no isometry into H, the octonion path.
    scene.fractal.formula = "z^2 + c";
    scene.render.engine = RenderEngine::Simd;
    scene.slice.axes = {0, 0, 1, 0, 0, 0, 0, 0,  //
                        0, 0, 0, 1, 0, 0, 0, 0,  //
                        0, 0, 0, 0, 0, 0, 1, 0};
    EXPECT_FALSE(fractalFromScene(scene).setAs<QuaternionJuliaSet>() != nullptr);
    // Neither for a formula with a quaternion coefficient.
    scene.slice.axes.clear();
    scene.fractal.formula = "i*z^2 + c";
    EXPECT_FALSE(fractalFromScene(scene).setAs<QuaternionJuliaSet>() != nullptr);
}

TEST(HypercomplexJulia, NegatingTheOctonionBHalfIsAnAutomorphism) {
    // (a, b) -> (a, -b) keeps the Cayley-Dickson product and the norm: negating the b-half of
    // c and of the slice leaves every membership and estimate unchanged.
    Scene scene = sceneIn(Algebra::kOctonion, {-0.2, 0.5, 0.1, 0.2, 0.15, -0.1, 0.2, 0.05});
    scene.slice.origin = {0, 0, 0, 0.1, 0.05, 0.1, -0.2, 0.1};
    scene.slice.axes = {1, 0, 0, 0, 0.1, 0,   0, 0,     //
                        0, 1, 0, 0, 0,   0.2, 0, 0,     //
                        0, 0, 0, 0, 0,   0,   1, 0.3};  // an axis outside the quaternion half
    Scene negated = scene;
    for (double& x : negated.fractal.cUpper)
        x = -x;
    for (size_t n = 4; n < 8; ++n)
        negated.slice.origin[n] = -negated.slice.origin[n];
    for (size_t a = 0; a < 3; ++a)
        for (size_t n = 4; n < 8; ++n)
            negated.slice.axes[8 * a + n] = -negated.slice.axes[8 * a + n];
    const Fractal first = fractalFromScene(scene), second = fractalFromScene(negated);
    std::mt19937 rng(22);
    int inside = 0;
    for (int trial = 0; trial < 2000; ++trial) {
        const Point3d p = randomPoint(rng, 1.5);
        const DistanceEstimate a = first.estimate(p), b = second.estimate(p);
        ASSERT_EQ(a.inside, b.inside) << p;
        EXPECT_NEAR(a.distance, b.distance, 1e-9 * (1 + a.distance));
        inside += a.inside;
    }
    EXPECT_GT(inside, 50);
    // And the b-half matters: the same scene with c's b-half dropped is another set.
    Scene dropped = scene;
    dropped.fractal.cUpper = {0, 0, 0, 0};
    const Fractal third = fractalFromScene(dropped);
    int differ = 0;
    for (int trial = 0; trial < 2000; ++trial) {
        const Point3d p = randomPoint(rng, 1.5);
        differ += first.contains(p) != third.contains(p);
    }
    EXPECT_GT(differ, 20);
}

TEST(HypercomplexJulia, BicomplexMembershipIsThatOfTwoComplexOrbits) {
    // z^2 + c in duplex form: a <- a^2 + c_1, b <- b^2 + c_2 with std::complex, escaping where
    // (|a|^2 + |b|^2) / 2 > bailout^2.
    const Hypercomplex c{-0.3, 0.4, 0.25, 0.1, 0, 0, 0, 0};
    const Scene scene = sceneIn(Algebra::kBicomplex, c, 30);
    const auto set = hypercomplexFractalFromScene(scene);
    EXPECT_EQ(set.set().bailout(), 4);  // POV-Ray's default
    const auto cd = duplex(c);
    std::mt19937 rng(23);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    int inside = 0;
    for (int trial = 0; trial < 20000; ++trial) {
        const Hypercomplex q{u(rng), u(rng), u(rng), u(rng), 0, 0, 0, 0};
        auto w = duplex(q);
        bool member = true;
        for (int n = 0; n < 30; ++n) {
            if (0.5 * (std::norm(w[0]) + std::norm(w[1])) > 16) {
                member = false;
                break;
            }
            w = {w[0] * w[0] + cd[0], w[1] * w[1] + cd[1]};
        }
        EXPECT_EQ(set.set().contains(q), member);
        inside += member;
    }
    EXPECT_GT(inside, 100);
}

TEST(HypercomplexJulia, BicomplexDistanceComesFromTheComplexEstimates) {
    // A point whose first duplex component lies in K_1 and whose second escapes is at the
    // second's complex estimate over sqrt(2) (|D(q)| = sqrt(2) |q|).
    const Hypercomplex c{-0.3, 0.4, 0.25, 0.1, 0, 0, 0, 0};
    const auto set = hypercomplexFractalFromScene(sceneIn(Algebra::kBicomplex, c, 30));
    const auto cd = duplex(c);
    const Complex a = 0;  // the fixed region of a <- a^2 + c_1 contains 0 here
    for (const Complex b : {Complex(1.3, 0.2), Complex(-0.9, 1.1), Complex(0.2, -1.4)}) {
        // The complex estimate 0.5 |w| ln|w| / |w'| with the same continuation rule.
        Complex w = b, slope = 1;
        while (std::norm(w) < 1e8) {
            slope *= 2.0 * w;
            w = w * w + cd[1];
        }
        const double expected = 0.5 * std::abs(w) * std::log(std::abs(w)) / std::abs(slope);
        const Hypercomplex q{0.5 * (a.real() + b.real()),
                             0.5 * (a.imag() + b.imag()),
                             0.5 * (a.imag() - b.imag()),
                             0.5 * (b.real() - a.real()),
                             0,
                             0,
                             0,
                             0};
        const DistanceEstimate e = set.set().estimate(q);
        EXPECT_FALSE(e.inside);
        EXPECT_NEAR(e.distance, expected / std::sqrt(2.0), 1e-9 * expected) << b;
    }
}

TEST(HypercomplexJulia, CoquaternionsOnSpanOneIAreTheComplexJuliaSet) {
    // i^2 = -1: on span{1, i} (the slice's plane z = 0) z^2 + c is the complex map.
    const Hypercomplex c{-0.4, 0.55, 0, 0, 0, 0, 0, 0};
    const Fractal fractal = fractalFromScene(sceneIn(Algebra::kCoquaternion, c, 40));
    EXPECT_EQ(fractal.distanceKind(), DistanceKind::kLipschitz);
    std::mt19937 rng(24);
    std::uniform_real_distribution<double> u(-1.6, 1.6);
    int inside = 0;
    for (int trial = 0; trial < 4000; ++trial) {
        const double x = u(rng), y = u(rng);
        Complex z(x, y);
        bool member = true;
        for (int n = 0; n < 40; ++n) {
            if (std::abs(z) > 2) {
                member = false;
                break;
            }
            z = z * z + Complex(c[0], c[1]);
        }
        EXPECT_EQ(fractal.contains(Point3d(x, y, 0)), member) << x << " " << y;
        inside += member;
    }
    EXPECT_GT(inside, 100);
}

TEST(HypercomplexJulia, CoquaternionsOnSpanOneJAreProductsOfIntervals) {
    // j^2 = +1: on span{1, j} (the plane y = 0) the null coordinates u = x + y, v = x - y of
    // x + y j follow two real maps, u <- u^2 + c0 + c2 and v <- v^2 + c0 - c2, whose filled
    // Julia sets are the intervals |u| <= beta = (1 + sqrt(1 - 4 c)) / 2. With these c both
    // intervals lie inside the bailout (|q|^2 = (u^2 + v^2) / 2 <= 4), so K is their product.
    const double c0 = -0.5, c2 = 0.2;
    const Fractal fractal =
        fractalFromScene(sceneIn(Algebra::kCoquaternion, {c0, 0, c2, 0, 0, 0, 0, 0}, 400));
    const double betaU = (1 + std::sqrt(1 - 4 * (c0 + c2))) / 2;
    const double betaV = (1 + std::sqrt(1 - 4 * (c0 - c2))) / 2;
    std::mt19937 rng(25);
    std::uniform_real_distribution<double> w(-1.8, 1.8);
    int inside = 0, tested = 0;
    for (int trial = 0; trial < 4000; ++trial) {
        const double u = w(rng), v = w(rng);
        // Points within 0.02 of an interval's end escape too slowly to decide in 400 steps.
        if (std::abs(std::abs(u) - betaU) < 0.02 || std::abs(std::abs(v) - betaV) < 0.02) continue;
        const bool member = std::abs(u) <= betaU && std::abs(v) <= betaV;
        const double x = 0.5 * (u + v), y = 0.5 * (u - v);
        EXPECT_EQ(fractal.contains(Point3d(x, 0, y)), member) << u << " " << v;
        inside += member;
        ++tested;
    }
    EXPECT_GT(inside, 300);
    EXPECT_GT(tested, 3000);
}

TEST(HypercomplexJulia, BiquaternionsWithoutAnHPartAreTheQuaternionSet) {
    // b = 0 throughout: (a + 0h)(c + 0h) = ac, the quaternion product, at the same bailout.
    const Hypercomplex c{-0.2, 0.6, 0.2, 0.2, 0, 0, 0, 0};
    const Fractal quaternion = fractalFromScene(sceneIn(Algebra::kQuaternion, c, 12, 2));
    const Fractal biquaternion = fractalFromScene(sceneIn(Algebra::kBiquaternion, c, 12, 0));
    EXPECT_EQ(biquaternion.boundingRadius(), 2);  // the default bailout of the biquaternions
    std::mt19937 rng(26);
    int inside = 0;
    for (int trial = 0; trial < 3000; ++trial) {
        const Point3d p = randomPoint(rng, 1.5);
        ASSERT_EQ(quaternion.contains(p), biquaternion.contains(p)) << p;
        inside += quaternion.contains(p);
    }
    EXPECT_GT(inside, 100);
}

TEST(HypercomplexJulia, LipschitzDistanceKeepsTheBallOutsideTheSet) {
    // The proven distance: no point of the ball it names lies in K_N.
    for (Algebra algebra : {Algebra::kCoquaternion, Algebra::kBiquaternion}) {
        Scene scene = sceneIn(algebra, {-0.3, 0.5, 0.2, -0.1, 0.1, 0, 0.1, 0});
        scene.fractal.formula = "z^2 + (0.2+0.1j)*z*i + c";
        const Fractal fractal = fractalFromScene(scene);
        std::mt19937 rng(27);
        std::uniform_real_distribution<double> unit(-1, 1);
        int positive = 0;
        for (int trial = 0; trial < 400; ++trial) {
            const Point3d p = randomPoint(rng, 1.6);
            const DistanceEstimate e = fractal.estimate(p);
            if (e.inside || e.distance <= 0) continue;
            ++positive;
            for (int k = 0; k < 50; ++k) {
                Vector3d d(unit(rng), unit(rng), unit(rng));
                const double length = std::sqrt(dot(d, d));
                if (length > 1 || length == 0) continue;
                const Point3d q = p + d * (0.999 * e.distance);
                EXPECT_FALSE(fractal.contains(q)) << algebraName(algebra) << " " << p;
            }
        }
        EXPECT_GT(positive, 100);
    }
}

TEST(HypercomplexJulia, DegenerateAxesAreRejected) {
    Scene scene = sceneIn(Algebra::kOctonion, {-0.2, 0.6, 0.2, 0.2, 0, 0, 0, 0});
    scene.slice.axes = {1, 0,  0, 0, 0, 0, 0, 0,  //
                        0, 1,  0, 0, 0, 0, 0, 0,  //
                        2, -3, 0, 0, 0, 0, 0, 0};
    try {
        fractalFromScene(scene);
        ADD_FAILURE() << "no error";
    } catch (const UserError& error) {
        EXPECT_EQ(error.key(), "slice.axes");
        EXPECT_NE(std::string(error.what()).find("axis 3"), std::string::npos) << error.what();
    }
}

}  // namespace
}  // namespace quaternia
