#include "quaternia/algebra/hypercomplex.h"

#include <gtest/gtest.h>

#include <complex>
#include <random>

#include "quaternia/algebra/quaternion.h"

namespace quaternia {
namespace {

using Complex = std::complex<double>;

Hypercomplex randomElement(std::mt19937& rng, Algebra algebra) {
    std::uniform_real_distribution<double> u(-1.5, 1.5);
    Hypercomplex a{};
    for (int n = 0; n < algebraDimension(algebra); ++n)
        a[n] = u(rng);
    return a;
}

void expectNear(const Hypercomplex& actual, const Hypercomplex& expected,
                double tolerance = 1e-12) {
    for (int n = 0; n < kMaxAlgebraDimension; ++n)
        EXPECT_NEAR(actual[n], expected[n], tolerance) << "component " << n;
}

bool near(const Hypercomplex& a, const Hypercomplex& b, double tolerance = 1e-9) {
    return euclideanNorm(a - b) <= tolerance;
}

TEST(HypercomplexAlgebra, NamesReadBackAndDimensionsAreFourOrEight) {
    ASSERT_EQ(allAlgebras().size(), 5u);
    for (Algebra a : allAlgebras()) {
        EXPECT_EQ(algebraFromName(algebraName(a)), a);
        EXPECT_EQ(MultiplicationTable::of(a).dimension(), algebraDimension(a));
    }
    EXPECT_EQ(algebraDimension(Algebra::kBicomplex), 4);
    EXPECT_EQ(algebraDimension(Algebra::kOctonion), 8);
    EXPECT_FALSE(algebraFromName("hypercomplex"));
    EXPECT_FALSE(algebraFromName("Quaternion"));
}

TEST(HypercomplexTable, OneIsTheIdentityAndEveryRowASignedPermutation) {
    for (Algebra algebra : allAlgebras()) {
        const MultiplicationTable& t = MultiplicationTable::of(algebra);
        for (int i = 0; i < t.dimension(); ++i) {
            EXPECT_EQ(t.product(0, i).index, i);
            EXPECT_EQ(t.product(i, 0).index, i);
            EXPECT_EQ(t.product(0, i).sign, 1);
            EXPECT_EQ(t.product(i, 0).sign, 1);
            std::vector<bool> seen(t.dimension(), false);
            for (int j = 0; j < t.dimension(); ++j) {
                const BasisProduct e = t.product(i, j);
                ASSERT_TRUE(e.index >= 0 && e.index < t.dimension());
                EXPECT_TRUE(e.sign == 1 || e.sign == -1);
                EXPECT_FALSE(seen[e.index]) << algebraName(algebra) << " row " << i;
                seen[e.index] = true;
            }
        }
    }
}

TEST(HypercomplexQuaternion, TableIsHamiltonsProduct) {
    const MultiplicationTable& t = MultiplicationTable::of(Algebra::kQuaternion);
    std::mt19937 rng(1);
    for (int n = 0; n < 100; ++n) {
        const Hypercomplex a = randomElement(rng, Algebra::kQuaternion);
        const Hypercomplex b = randomElement(rng, Algebra::kQuaternion);
        const Quaternion p =
            Quaternion(a[0], a[1], a[2], a[3]) * Quaternion(b[0], b[1], b[2], b[3]);
        expectNear(t.multiply(a, b), {p.w, p.x, p.y, p.z});
    }
}

// (x, y, z, w) -> ((x - w) + (y + z) i, (x + w) + (y - z) i): POV-Ray's duplex form.
std::pair<Complex, Complex> duplex(const Hypercomplex& q) {
    return {Complex(q[0] - q[3], q[1] + q[2]), Complex(q[0] + q[3], q[1] - q[2])};
}

TEST(HypercomplexBicomplex, DuplexFormIsARingIsomorphismOntoCTimesC) {
    const MultiplicationTable& t = MultiplicationTable::of(Algebra::kBicomplex);
    std::mt19937 rng(2);
    for (int n = 0; n < 100; ++n) {
        const Hypercomplex a = randomElement(rng, Algebra::kBicomplex);
        const Hypercomplex b = randomElement(rng, Algebra::kBicomplex);
        const auto [a1, a2] = duplex(a);
        const auto [b1, b2] = duplex(b);
        const auto [p1, p2] = duplex(t.multiply(a, b));
        EXPECT_NEAR(std::abs(p1 - a1 * b1), 0, 1e-12);
        EXPECT_NEAR(std::abs(p2 - a2 * b2), 0, 1e-12);
        const auto [s1, s2] = duplex(a + b);
        EXPECT_NEAR(std::abs(s1 - (a1 + b1)), 0, 1e-12);
        EXPECT_NEAR(std::abs(s2 - (a2 + b2)), 0, 1e-12);
        // |q|^2 = (|a|^2 + |b|^2) / 2.
        EXPECT_NEAR(euclideanNorm(a) * euclideanNorm(a), (std::norm(a1) + std::norm(a2)) / 2,
                    1e-12);
        expectNear(t.multiply(a, b), t.multiply(b, a));  // commutative
    }
    // k = ij squares to +1 and is a zero divisor's factor: (1 + k)(1 - k) = 0.
    const Hypercomplex one = realElement(1), k = basisElement(3);
    expectNear(t.multiply(k, k), one);
    expectNear(t.multiply(one + k, one - k), {});
}

TEST(HypercomplexCoquaternion, RelationsHoldAndTheIndefiniteNormIsMultiplicative) {
    const MultiplicationTable& t = MultiplicationTable::of(Algebra::kCoquaternion);
    const Hypercomplex one = realElement(1), i = basisElement(1), j = basisElement(2),
                       k = basisElement(3);
    expectNear(t.multiply(i, i), -1.0 * one);
    expectNear(t.multiply(j, j), one);
    expectNear(t.multiply(k, k), one);
    expectNear(t.multiply(i, j), k);
    expectNear(t.multiply(j, i), -1.0 * k);
    expectNear(t.multiply(j, k), -1.0 * i);
    expectNear(t.multiply(k, j), i);
    expectNear(t.multiply(k, i), j);
    expectNear(t.multiply(i, k), -1.0 * j);
    auto quadratic = [](const Hypercomplex& q) {
        return q[0] * q[0] + q[1] * q[1] - q[2] * q[2] - q[3] * q[3];
    };
    std::mt19937 rng(3);
    for (int n = 0; n < 100; ++n) {
        const Hypercomplex a = randomElement(rng, Algebra::kCoquaternion);
        const Hypercomplex b = randomElement(rng, Algebra::kCoquaternion);
        const Hypercomplex c = randomElement(rng, Algebra::kCoquaternion);
        EXPECT_NEAR(quadratic(t.multiply(a, b)), quadratic(a) * quadratic(b), 1e-11);
        expectNear(t.multiply(t.multiply(a, b), c), t.multiply(a, t.multiply(b, c)));
    }
    // A null element: 1 + j has norm 0 and divides zero.
    expectNear(t.multiply(one + j, one - j), {});
}

TEST(HypercomplexBiquaternion, IsTheComplexifiedQuaternions) {
    const MultiplicationTable& t = MultiplicationTable::of(Algebra::kBiquaternion);
    const MultiplicationTable& h = MultiplicationTable::of(Algebra::kQuaternion);
    const Hypercomplex unitH = basisElement(4);
    std::mt19937 rng(4);
    for (int n = 0; n < 100; ++n) {
        const Hypercomplex a = randomElement(rng, Algebra::kBiquaternion);
        const Hypercomplex b = randomElement(rng, Algebra::kBiquaternion);
        const Hypercomplex c = randomElement(rng, Algebra::kBiquaternion);
        expectNear(t.multiply(t.multiply(a, b), c), t.multiply(a, t.multiply(b, c)));
        expectNear(t.multiply(unitH, a), t.multiply(a, unitH));  // h is central
        // The b = 0 half is H itself.
        const Hypercomplex p = randomElement(rng, Algebra::kQuaternion);
        const Hypercomplex q = randomElement(rng, Algebra::kQuaternion);
        expectNear(t.multiply(p, q), h.multiply(p, q));
    }
    expectNear(t.multiply(unitH, unitH), realElement(-1));
    // (1 + h i)(1 - h i) = 1 - (h i)^2 = 1 - (-1)(-1) = 0: a zero divisor.
    const Hypercomplex hi = basisElement(5);
    expectNear(t.multiply(realElement(1) + hi, realElement(1) - hi), {});
}

Hypercomplex octonionConjugate(const Hypercomplex& a) {
    Hypercomplex c = -1.0 * a;
    c[0] = a[0];
    return c;
}

TEST(HypercomplexOctonion, IsAlternativeWithMultiplicativeNormButNotAssociative) {
    const MultiplicationTable& t = MultiplicationTable::of(Algebra::kOctonion);
    std::mt19937 rng(5);
    for (int n = 0; n < 100; ++n) {
        const Hypercomplex a = randomElement(rng, Algebra::kOctonion);
        const Hypercomplex b = randomElement(rng, Algebra::kOctonion);
        const Hypercomplex c = randomElement(rng, Algebra::kOctonion);
        EXPECT_NEAR(euclideanNorm(t.multiply(a, b)), euclideanNorm(a) * euclideanNorm(b), 1e-12);
        // Alternative: (aa)b = a(ab), (ba)a = b(aa).
        expectNear(t.multiply(t.multiply(a, a), b), t.multiply(a, t.multiply(a, b)));
        expectNear(t.multiply(t.multiply(b, a), a), t.multiply(b, t.multiply(a, a)));
        // A Moufang identity: ((ab)c)b = a(b(cb)).
        expectNear(t.multiply(t.multiply(t.multiply(a, b), c), b),
                   t.multiply(a, t.multiply(b, t.multiply(c, b))), 1e-11);
        // conj(ab) = conj(b) conj(a), and a conj(a) = |a|^2.
        expectNear(octonionConjugate(t.multiply(a, b)),
                   t.multiply(octonionConjugate(b), octonionConjugate(a)));
        expectNear(t.multiply(a, octonionConjugate(a)),
                   realElement(euclideanNorm(a) * euclideanNorm(a)));
        // Power-associative: z^5 is the same however bracketed.
        const Hypercomplex a2 = t.multiply(a, a), a3 = t.multiply(a2, a);
        expectNear(t.power(a, 5), t.multiply(a3, a2), 1e-10);
        // (a, b) -> (a, -b) is an automorphism.
        auto flip = [](Hypercomplex x) {
            for (int k = 4; k < 8; ++k)
                x[k] = -x[k];
            return x;
        };
        expectNear(flip(t.multiply(a, b)), t.multiply(flip(a), flip(b)));
    }
    // Three imaginary units that do not lie in one quaternion subalgebra do not associate.
    const Hypercomplex e1 = basisElement(1), e2 = basisElement(2), e4 = basisElement(4);
    EXPECT_FALSE(near(t.multiply(t.multiply(e1, e2), e4), t.multiply(e1, t.multiply(e2, e4))));
    // Every imaginary unit squares to -1, and the first half is H.
    for (int n = 1; n < 8; ++n)
        expectNear(t.multiply(basisElement(n), basisElement(n)), realElement(-1));
    const MultiplicationTable& h = MultiplicationTable::of(Algebra::kQuaternion);
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            expectNear(t.multiply(basisElement(i), basisElement(j)),
                       h.multiply(basisElement(i), basisElement(j)));
}

TEST(HypercomplexPower, ZeroIsOneAndPowersMatchProducts) {
    for (Algebra algebra : allAlgebras()) {
        const MultiplicationTable& t = MultiplicationTable::of(algebra);
        std::mt19937 rng(6);
        const Hypercomplex z = randomElement(rng, algebra);
        expectNear(t.power(z, 0), realElement(1));
        expectNear(t.power(z, 1), z);
        expectNear(t.power(z, 3), t.multiply(t.multiply(z, z), z), 1e-12);
    }
}

}  // namespace
}  // namespace quaternia
