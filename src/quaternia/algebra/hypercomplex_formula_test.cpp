#include "quaternia/algebra/hypercomplex_formula.h"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <random>

namespace quaternia {
namespace {

Hypercomplex randomElement(std::mt19937& rng, Algebra algebra, double scale = 1.5) {
    std::uniform_real_distribution<double> u(-scale, scale);
    Hypercomplex a{};
    for (int n = 0; n < algebraDimension(algebra); ++n)
        a[n] = u(rng);
    return a;
}

HypercomplexFormula compiled(const char* text, Algebra algebra, const Hypercomplex& c = {}) {
    return HypercomplexFormula(Formula::parse(text), algebra, c);
}

TEST(HypercomplexFormula, ProductsFollowTheTableInTheOrderWritten) {
    std::mt19937 rng(11);
    const Hypercomplex i = basisElement(1), j = basisElement(2);
    for (Algebra algebra : allAlgebras()) {
        const MultiplicationTable& table = MultiplicationTable::of(algebra);
        const Hypercomplex c = randomElement(rng, algebra);
        const HypercomplexFormula formula = compiled("i*z*j*z + c", algebra, c);
        for (int trial = 0; trial < 20; ++trial) {
            const Hypercomplex z = randomElement(rng, algebra);
            // Left to right: ((i z) j) z + c.
            const Hypercomplex expected =
                table.multiply(table.multiply(table.multiply(i, z), j), z) + c;
            EXPECT_LT(euclideanNorm(formula.evaluate(z) - expected), 1e-12) << algebraName(algebra);
        }
    }
}

TEST(HypercomplexFormula, ParenthesesMatterForOctonionsOnly) {
    // (z i) j and z (i j) differ for an octonion z with a b-half: the octonions are not
    // associative; the quaternions are.
    const Hypercomplex z{0.3, -0.2, 0.5, 0.1, 0.7, -0.4, 0.2, 0.6};
    const auto left = compiled("(z*i)*j", Algebra::kOctonion).evaluate(z);
    const auto right = compiled("z*(i*j)", Algebra::kOctonion).evaluate(z);
    EXPECT_GT(euclideanNorm(left - right), 0.1);
    const Hypercomplex q{0.3, -0.2, 0.5, 0.1, 0, 0, 0, 0};
    EXPECT_LT(euclideanNorm(compiled("(z*i)*j", Algebra::kQuaternion).evaluate(q) -
                            compiled("z*(i*j)", Algebra::kQuaternion).evaluate(q)),
              1e-15);
}

TEST(HypercomplexFormula, DerivativeMatchesCentralDifferences) {
    std::mt19937 rng(12);
    for (Algebra algebra : allAlgebras()) {
        const Hypercomplex c = randomElement(rng, algebra, 0.5);
        const HypercomplexFormula formula =
            compiled("(1+0.2i)*z*(0.5-j)*z + z^3 - 0.3*z*k + c", algebra, c);
        for (int trial = 0; trial < 10; ++trial) {
            const Hypercomplex z = randomElement(rng, algebra, 0.8);
            const Hypercomplex h = randomElement(rng, algebra, 1.0);
            const double e = 1e-6;
            const Hypercomplex difference =
                (0.5 / e) * (formula.evaluate(z + e * h) - formula.evaluate(z - e * h));
            const auto [value, slope] = formula.evaluateWithDerivative(z, h);
            EXPECT_LT(euclideanNorm(value - formula.evaluate(z)), 1e-14);
            EXPECT_LT(euclideanNorm(slope - difference), 1e-7) << algebraName(algebra);
        }
    }
}

TEST(HypercomplexFormula, ProductBoundHoldsAndIsAttained) {
    std::mt19937 rng(13);
    for (Algebra algebra : allAlgebras()) {
        const MultiplicationTable& table = MultiplicationTable::of(algebra);
        const double kappa = productBound(algebra);
        double largest = 0;
        for (int trial = 0; trial < 4000; ++trial) {
            const Hypercomplex a = randomElement(rng, algebra), b = randomElement(rng, algebra);
            const double ratio =
                euclideanNorm(table.multiply(a, b)) / (euclideanNorm(a) * euclideanNorm(b));
            EXPECT_LE(ratio, kappa * (1 + 1e-12)) << algebraName(algebra);
            largest = std::max(largest, ratio);
        }
        if (kappa == 1) {
            EXPECT_NEAR(largest, 1, 1e-12) << algebraName(algebra);
        }
    }
    // Attained: a bicomplex number with one duplex component zero, (1 - k) / 2, squares to
    // itself with |q| = 1 / sqrt(2); the coquaternion 1 + j, a null element, has (1 + j)^2 =
    // 2 (1 + j); the biquaternion 1 + i h has (1 + i h)^2 = 2 + 2 i h.
    auto ratio = [](Algebra algebra, const Hypercomplex& q) {
        const double n = euclideanNorm(q);
        return euclideanNorm(MultiplicationTable::of(algebra).multiply(q, q)) / (n * n);
    };
    EXPECT_NEAR(ratio(Algebra::kBicomplex, {0.5, 0, 0, -0.5}), std::sqrt(2.0), 1e-12);
    EXPECT_NEAR(ratio(Algebra::kCoquaternion, {1, 0, 1, 0}), std::sqrt(2.0), 1e-12);
    EXPECT_NEAR(ratio(Algebra::kBiquaternion, {1, 0, 0, 0, 0, 1, 0, 0}), std::sqrt(2.0), 1e-12);
}

TEST(HypercomplexFormula, NormBoundBoundsValuesAndDerivatives) {
    std::mt19937 rng(14);
    for (Algebra algebra : allAlgebras()) {
        const Hypercomplex c = randomElement(rng, algebra, 0.6);
        const HypercomplexFormula formula =
            compiled("j*z*(1-i)*z - (z + k)^3 + 0.5*z + c", algebra, c);
        ASSERT_EQ(formula.degree(), 3);
        ASSERT_EQ(formula.normBound().size(), 4u);
        for (int trial = 0; trial < 200; ++trial) {
            const Hypercomplex z = randomElement(rng, algebra, 1.2);
            const Hypercomplex h = randomElement(rng, algebra, 1.0);
            const double r = euclideanNorm(z);
            double bound = 0;
            for (size_t k = formula.normBound().size(); k-- > 0;)
                bound = bound * r + formula.normBound()[k];
            EXPECT_LE(euclideanNorm(formula.evaluate(z)), bound * (1 + 1e-12));
            EXPECT_LE(euclideanNorm(formula.evaluateWithDerivative(z, h).second),
                      formula.derivativeNormBound(r) * euclideanNorm(h) * (1 + 1e-12))
                << algebraName(algebra);
        }
    }
}

TEST(HypercomplexFormula, TopDegreeMinimumIsTheProductOfNormsOfOneTopTerm) {
    // Multiplicative norms: |2 i z j z| = 2 |z|^2 exactly.
    EXPECT_NEAR(compiled("2*i*z*j*z + z + c", Algebra::kOctonion).topDegreeMinimum(), 2, 1e-15);
    EXPECT_NEAR(compiled("z^3 + c", Algebra::kOctonion).topDegreeMinimum(), 1, 1e-15);
    // Top terms that cancel certify nothing; nor does a norm that is not multiplicative.
    EXPECT_EQ(compiled("z^2 - z*z + z + c", Algebra::kOctonion).topDegreeMinimum(), 0);
    EXPECT_EQ(compiled("z^2 + c", Algebra::kCoquaternion).topDegreeMinimum(), 0);
    EXPECT_EQ(compiled("z^2 - z*z + z + c", Algebra::kOctonion).degree(), 2);
}

TEST(HypercomplexFormula, BicomplexFunctionsActOnEachDuplexComponent) {
    // POV-Ray's hypercomplex functions: f(q) is f applied to both complex components of the
    // duplex form, with its derivative by the chain rule.
    std::mt19937 rng(15);
    const Hypercomplex c{0.1, -0.2, 0.3, 0.05, 0, 0, 0, 0};
    const HypercomplexFormula formula = compiled(
        "sin(z) + exp(z)*c + z^2.5 - reciprocal(z + 3) + atanh(0.5*z)", Algebra::kBicomplex, c);
    EXPECT_TRUE(formula.transcendental());
    const auto cd = duplexForm(c);
    for (int trial = 0; trial < 20; ++trial) {
        const Hypercomplex z = randomElement(rng, Algebra::kBicomplex, 0.9);
        const auto w = duplexForm(z);
        std::array<std::complex<double>, 2> expected;
        for (size_t i = 0; i < 2; ++i)
            expected[i] = std::sin(w[i]) + std::exp(w[i]) * cd[i] + std::pow(w[i], 2.5) -
                          1.0 / (w[i] + 3.0) + std::atanh(0.5 * w[i]);
        EXPECT_LT(euclideanNorm(formula.evaluate(z) - fromDuplexForm(expected[0], expected[1])),
                  1e-12);
        const Hypercomplex h = randomElement(rng, Algebra::kBicomplex, 1.0);
        const double e = 1e-6;
        const Hypercomplex difference =
            (0.5 / e) * (formula.evaluate(z + e * h) - formula.evaluate(z - e * h));
        EXPECT_LT(euclideanNorm(formula.evaluateWithDerivative(z, h).second - difference), 1e-6);
    }
}

TEST(HypercomplexFormula, FunctionsAreRefusedOutsideTheBicomplexNumbers) {
    for (Algebra algebra : allAlgebras()) {
        if (algebra == Algebra::kBicomplex) continue;
        for (const char* text : {"sin(z) + c", "z^1.5 + c", "z^-1 + c"}) {
            try {
                compiled(text, algebra);
                ADD_FAILURE() << text << " in " << algebraName(algebra);
            } catch (const FormulaError& error) {
                EXPECT_NE(std::string(error.what()).find("bicomplex"), std::string::npos)
                    << error.what();
            }
        }
    }
    // The quaternion expansion refuses them too, at the column of the function.
    try {
        Formula::parse("z^2 + cos(z)").expand(Quaternion(0.1));
        ADD_FAILURE() << "cos expanded";
    } catch (const FormulaError& error) {
        EXPECT_EQ(error.column(), 7);
        EXPECT_NE(std::string(error.what()).find("cos()"), std::string::npos) << error.what();
    }
}

TEST(HypercomplexFormula, ComplexAxisIsACopyOfCHoldingEveryConstant) {
    using Complex = std::complex<double>;
    const Hypercomplex cJ{0.3, 0, -0.5, 0, 0, 0, 0, 0};  // 0.3 - 0.5 j
    // Bicomplex j^2 = -1: span{1, j} is C, and z^2 + (1 + 2j) z + c acts there as the complex
    // polynomial w^2 + (1 + 2i) w + (0.3 - 0.5 i) in the coordinates x + y j.
    const HypercomplexFormula bicomplex = compiled("z^2 + (1 + 2j) z + c", Algebra::kBicomplex, cJ);
    const auto axis = bicomplex.complexAxis();
    ASSERT_TRUE(axis);
    EXPECT_EQ(*axis, Quaternion(0, 0, 1, 0));
    for (const Complex w : {Complex(0.2, -0.7), Complex(-1.1, 0.4)}) {
        const Hypercomplex value = bicomplex.evaluate({w.real(), 0, w.imag(), 0, 0, 0, 0, 0});
        const Complex expected = w * w + Complex(1, 2) * w + Complex(0.3, -0.5);
        EXPECT_NEAR(value[0], expected.real(), 1e-14);
        EXPECT_NEAR(value[2], expected.imag(), 1e-14);
        EXPECT_EQ(value[1], 0);
        EXPECT_EQ(value[3], 0);
    }
    // Not with k (k^2 = +1), nor with constants in two planes, nor with functions.
    EXPECT_FALSE(compiled("z^2 + 0.5k", Algebra::kBicomplex).complexAxis());
    EXPECT_FALSE(compiled("z^2 + i z + c", Algebra::kBicomplex, cJ).complexAxis());
    EXPECT_FALSE(compiled("sin(z) + 0.5", Algebra::kBicomplex).complexAxis());
    // Coquaternions: i^2 = -1 but j^2 = +1.
    EXPECT_TRUE(compiled("z^2 + 0.5i", Algebra::kCoquaternion).complexAxis());
    EXPECT_FALSE(compiled("z^2 + c", Algebra::kCoquaternion, cJ).complexAxis());
    // Real constants: the axis i, in every algebra.
    for (Algebra algebra : allAlgebras())
        EXPECT_EQ(compiled("z^3 - 2 z + 0.25", algebra).complexAxis(), Quaternion(0, 1, 0, 0));
    // 8 components: the constants must lie in the quaternion half.
    const Hypercomplex cUpper{0.3, 0, 0, 0, 0, 0.1, 0, 0};
    EXPECT_FALSE(compiled("z^2 + c", Algebra::kOctonion, cUpper).complexAxis());
    EXPECT_TRUE(compiled("z^2 + c", Algebra::kBiquaternion, cJ).complexAxis());
}

}  // namespace
}  // namespace quaternia
